"""ParaView (pvpython) reads a flowmpm results.xdmf right, in both its readers.

    pvpython pv_check.py RESULTS.xdmf PARTICLES DIMENSION

For OpenDataFile (ParaView's default, the Xdmf3 reader) and the legacy
XDMFReader, at every time step: the times are those of results.h5; there is
one vertex cell per particle (cell i on point i), so the particles render;
the points are the positions; and every field equals its results.h5
dataset, every component of stress and strain holding, under the label
ParaView shows for it (XX YY ZZ XY YZ XZ), the results.h5 column of that
component (the datasets' "components" attribute names their order).
results.h5 is read with h5py. Prints each failure; exit status 0 when all
pass, 1 otherwise.
"""
import sys

import h5py
import numpy as np
from paraview import servermanager
from paraview import simple
from vtkmodules.util.numpy_support import vtk_to_numpy

TENSORS = ("stress", "strain")


def steps_of(h5_path):
    with h5py.File(h5_path, "r") as f:
        return [{"time": float(g.attrs["time"]), "name": name,
                 "data": {k: g[k][()] for k in g},
                 "order": {k: g[k].attrs["components"].split() for k in g if k in TENSORS}}
                for name, g in sorted(f["steps"].items())]


def check(reader_kind, xdmf, particles, dimension, steps, failures):
    def fail(message):
        failures.append(f"[{reader_kind}] {message}")
        print("  FAIL", message)

    reader = simple.OpenDataFile(xdmf) if reader_kind == "default" else simple.XDMFReader(FileNames=[xdmf])
    print(f"[{reader_kind}] {reader.GetXMLName()}")
    times = list(reader.TimestepValues or [])
    if not np.allclose(times, [s["time"] for s in steps], rtol=1e-12, atol=0):
        fail(f"time steps {times}, results.h5 has {[s['time'] for s in steps]}")
        return
    for t, step in zip(times, steps):
        reader.UpdatePipeline(t)  # without a time, pvpython's output has no arrays
        data = servermanager.Fetch(reader)
        if data.IsA("vtkMultiBlockDataSet"):
            data = data.GetBlock(0)
        where = f"t = {t:g} s ({step['name']})"
        n = particles
        if data.GetNumberOfPoints() != n or data.GetNumberOfCells() != n:
            fail(f"{where}: {data.GetNumberOfPoints()} points and {data.GetNumberOfCells()} cells, expected {n} of each")
            continue
        cells = data.GetCells()
        if not (np.array_equal(vtk_to_numpy(cells.GetConnectivityArray()), np.arange(n))
                and np.array_equal(vtk_to_numpy(cells.GetOffsetsArray()), np.arange(n + 1))):
            fail(f"{where}: the cells are not one vertex per particle, cell i on point i")
        points = vtk_to_numpy(data.GetPoints().GetData()).reshape(n, 3)
        if not np.array_equal(points, step["data"]["position"]):
            fail(f"{where}: the points are not the positions")
        if dimension < 3 and np.any(points[:, 2] != 0):
            fail(f"{where}: a {dimension}D run with z != 0")
        point_data = data.GetPointData()
        for name, values in step["data"].items():
            if name == "position":
                continue
            array = point_data.GetArray(name)
            if array is None:
                fail(f"{where}: no point array {name}")
                continue
            shown = vtk_to_numpy(array).reshape(values.shape)
            if name not in TENSORS:
                if not np.array_equal(shown, values):
                    fail(f"{where}: {name} differs from results.h5")
                continue
            order = step["order"][name]
            for k in range(6):
                label = reader.PointData[name].GetComponentName(k).lower()
                if not np.array_equal(shown[:, k], values[:, order.index(label)]):
                    fail(f"{where}: {name} shown as {label.upper()} is not results.h5's {label}")
    simple.Delete(reader)


def main(argv):
    if len(argv) != 3:
        print(__doc__)
        return 2
    xdmf, particles, dimension = argv[0], int(argv[1]), int(argv[2])
    steps = steps_of(xdmf[: -len(".xdmf")] + ".h5")
    # A check that cannot fail is no check: the tensors' shear must be nonzero.
    last = steps[-1]["data"]
    for name in TENSORS:
        order = steps[-1]["order"][name]
        needed = ["xy"] if dimension == 2 else ["xy", "yz", "xz"]
        for c in needed:
            if not np.any(last[name][:, order.index(c)]):
                print(f"the {name} {c} column is all zero: its label cannot be checked; use a case with shear")
                return 2
    failures = []
    for kind in ("default", "legacy"):
        check(kind, xdmf, particles, dimension, steps, failures)
    print("PASS" if not failures else f"FAIL: {len(failures)} problem(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
