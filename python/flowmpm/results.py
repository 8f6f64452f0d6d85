"""A run's results (docs/guide/output.md) as numpy arrays, by particle id.

results.h5 links each step file of steps/; h5py follows the links when a
path names them (which `visititems` does not). Rows are particle ids at
every step; each body's rows are the range results.h5's `body_rows` gives.
"""
import json
import os

import h5py
import numpy as np

from .errors import FlowmpmError
from .tables import read_csv


def _text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


class Results:
    """The results in an output directory (or of its results.h5).

    Attributes: `directory`; `steps` (the output steps' numbers) and
    `times` (s), one per output step, in order; `ids` (0..n-1, the rows);
    `bodies` ({name: ids}); `fields` (the datasets of each step);
    `dimension`, `stress_state`, `units` ("SI: m, s, kg, Pa, J"),
    `tensor_components` (the columns of stress and strain, e.g. ["xx",
    "yy", "zz", "xy", "yz", "xz"]; tensor, not engineering, shear),
    `vector_components`, `materials` (names by the `material` field's
    index) and `attrs` (every attribute of results.h5's root)."""

    def __init__(self, path):
        path = os.fspath(path)
        self.directory = os.path.dirname(path) if path.endswith(".h5") else path
        file = path if path.endswith(".h5") else os.path.join(path, "results.h5")
        if not os.path.exists(file):
            raise FileNotFoundError(f"{file}: no results (flowmpm run writes results.h5 in its output directory)")
        self._file = h5py.File(file, "r")
        a = self._file.attrs
        self.attrs = {k: (_text(v) if isinstance(v, (str, bytes)) else v) for k, v in a.items()}
        self.dimension = int(a["dimension"])
        self.stress_state = _text(a["stress_state"])
        self.units = _text(a["units"])
        self.tensor_components = _text(a["tensor_components"]).split()
        self.vector_components = _text(a["vector_components"])
        self.materials = [_text(m) for m in a["materials"]]
        self._labels = sorted(self._file["steps"])
        if not self._labels:
            raise FlowmpmError(f"{file}: no output steps yet")
        self.steps = np.array([int(label) for label in self._labels])
        self.times = np.array([self._file["steps"][label].attrs["time"] for label in self._labels])
        self.ids = np.arange(len(self._file["particle_index"]))
        first = self._file["steps"][self._labels[0]]
        self.fields = [name for name in first if isinstance(first[name], h5py.Dataset)]
        self.bodies = {}
        if "body_rows" in a:
            rows = a["body_rows"]
            for b, name in enumerate(a["bodies"]):
                self.bodies[_text(name)] = np.arange(rows[b], rows[b + 1])
        self._in_id_order = set()
        self._timeseries = self._summary = None

    def close(self):
        self._file.close()

    def __enter__(self):
        return self

    def __exit__(self, *exception):
        self.close()

    def _step(self, step):
        """The group of the output step at index `step` (of `steps`; -1 the
        last), its rows checked to be in id order."""
        try:
            label = self._labels[step]
        except (IndexError, TypeError):
            raise IndexError(f"step index {step!r}: there are {len(self._labels)} output steps "
                             f"(steps {self.steps[0]} to {self.steps[-1]}); -1 is the last") from None
        group = self._file["steps"][label]
        if label not in self._in_id_order and "id" in group:
            ids = group["id"][()]
            if not np.array_equal(ids, np.arange(len(ids))):
                raise FlowmpmError(f"{self.directory}/steps/{label}.h5: its rows are not in particle id order")
            self._in_id_order.add(label)
        return group

    def _dataset(self, group, name):
        if name not in group:
            raise KeyError(f"no field {name!r}; the results hold {', '.join(self.fields)} "
                           "(output.fields chooses them)")
        return group[name]

    def _rows(self, body):
        if body is None:
            return slice(None)
        if not self.bodies:
            raise FlowmpmError(f"{self.directory}/results.h5 does not say which rows are which body "
                               "(written by a flowmpm older than its body_rows attribute)")
        if body not in self.bodies:
            raise KeyError(f"no body {body!r}; the bodies are {', '.join(self.bodies)}")
        ids = self.bodies[body]
        return slice(ids[0], ids[-1] + 1) if len(ids) else slice(0, 0)

    def field(self, name, step=-1, body=None):
        """A field at one output step (`step` an index into `steps`, -1 the
        last) as a numpy array, one row per particle in id order: vectors
        n x 3 (m, m/s; z = 0 below 3D), tensors n x 6 in the order of
        `tensor_components` (Pa for stress), scalars n. With `body`, only
        that body's rows (the ids `bodies[body]`)."""
        return self._dataset(self._step(step), name)[self._rows(body)]

    def history(self, name, ids):
        """A field over every output step for one particle id (steps x
        components) or a list of ids (steps x ids x components), in the
        order of `times`."""
        chosen = np.atleast_1d(np.asarray(ids, dtype=int))
        if chosen.size == 0 or chosen.min() < 0 or chosen.max() >= len(self.ids):
            raise IndexError(f"particle ids {ids!r}: the ids are 0 to {len(self.ids) - 1}")
        low, high = chosen.min(), chosen.max() + 1
        values = np.stack([self._dataset(self._step(k), name)[low:high][chosen - low]
                           for k in range(len(self._labels))])
        return values[:, 0] if np.ndim(ids) == 0 else values

    @property
    def timeseries(self):
        """timeseries.csv: one row per output step (time in s, energies in
        J, per body the mean stress and strain, reactions in N), a pandas
        DataFrame, or a numpy structured array without pandas."""
        if self._timeseries is None:
            self._timeseries = read_csv(os.path.join(self.directory, "timeseries.csv"))
        return self._timeseries

    @property
    def summary(self):
        """summary.json as a dict: status, timings, final mean stresses,
        error norms."""
        if self._summary is None:
            with open(os.path.join(self.directory, "summary.json"), encoding="utf-8") as f:
                self._summary = json.load(f)
        return self._summary

    def __repr__(self):
        return (f"<flowmpm.Results {self.directory}: {len(self.ids)} particles, {len(self.steps)} output steps "
                f"to t = {self.times[-1]:g} s, bodies {list(self.bodies)}>")
