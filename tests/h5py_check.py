"""h5py reads a flowmpm results.h5 as the README says (tests/readers_check.sh).

    python3 h5py_check.py RESULTS.xdmf PARTICLES DIMENSION

Asserts the root metadata (the bodies' rows: body_rows from 0 to n, one
range per body); the connectivity /particle_index = 0..n-1; that
/steps links every step file of steps/ and nothing else; at every step,
read through results.h5's links: its step number, the id column 0..n-1
(rows in particle id order), the
displacement equal to the position minus the first step's position, bit for
bit (a row that changed particle between steps would break it), vectors
padded with z = 0 below 3D, and tensors in the order the datasets declare.
Exit status 0 when all pass, 1 otherwise.
"""
import os
import re
import sys

import h5py
import numpy as np


def main(argv):
    xdmf, particles, dimension = argv[0], int(argv[1]), int(argv[2])
    failures = []

    def check(ok, message):
        if not ok:
            failures.append(message)
            print("FAIL", message)

    with h5py.File(xdmf[: -len(".xdmf")] + ".h5", "r") as f:
        a = f.attrs
        check(a["format_version"] == 3, f"format_version {a['format_version']}")
        check(str(a["program"]).startswith("flowmpm "), f"program {a['program']}")
        check(a["dimension"] == dimension, f"dimension {a['dimension']}")
        check(a["tensor_components"] == "xx yy zz xy yz xz", f"tensor_components {a['tensor_components']}")
        for key in ("case", "case_file", "commit", "stress_state", "scheme", "shape_function", "units"):
            check(isinstance(a[key], str), f"attribute {key} is not a string: {a[key]!r}")
        check(len(a["materials"]) >= 1 and all(isinstance(m, str) for m in a["materials"]),
              f"materials {a['materials']!r}")
        rows = a["body_rows"]
        check(len(a["bodies"]) >= 1 and all(isinstance(b, str) for b in a["bodies"]), f"bodies {a['bodies']!r}")
        check(len(rows) == len(a["bodies"]) + 1 and rows[0] == 0 and rows[-1] == particles and
              np.all(np.diff(rows) >= 0), f"body_rows {rows!r}")
        check(np.array_equal(f["particle_index"][()], np.arange(particles)), "particle_index is not 0..n-1")
        names = sorted(f["steps"])
        files = sorted(n[: -len(".h5")] for n in os.listdir(os.path.join(os.path.dirname(xdmf), "steps"))
                       if re.fullmatch(r"\d{8}\.h5", n))
        check(names == files, f"/steps links {names}, steps/ holds {files}")
        steps = [f["steps"][name] for name in names]
        check(len(steps) >= 2, "fewer than 2 steps")
        x0 = steps[0]["position"][()]
        for name, g in zip(names, steps):
            where = "/steps/" + name
            check(g.attrs["step"] == int(name), f"{where}: step attribute {g.attrs['step']}")
            check(np.array_equal(g["id"][()], np.arange(particles)), f"{where}: id is not 0..n-1")
            position, displacement = g["position"][()], g["displacement"][()]
            check(np.array_equal(displacement, position - x0), f"{where}: displacement != position - initial position")
            if dimension < 3:
                check(not np.any(position[:, 2]), f"{where}: z != 0 in {dimension}D")
            for name in ("stress", "strain"):
                check(g[name].shape == (particles, 6), f"{where}/{name} shape {g[name].shape}")
                check(g[name].attrs["components"] == "xx yy zz xy yz xz", f"{where}/{name} components")
            material = g["material"][()]
            check(material.min() >= 0 and material.max() < len(a["materials"]), f"{where}: material index")
        moved = np.abs(steps[-1]["displacement"][()]).max()
        check(moved > 0, "nothing moved: the row check would be empty")
    print("PASS" if not failures else f"FAIL: {len(failures)} problem(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
