"""What the Python tests share: the checkout, a scratch folder, and the
uniaxial stress case (README.md) built in Python."""
import os
import tempfile
import unittest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def uniaxial_case(scheme="usf", dt=0.01):
    """CB-Geo's uniaxial stress Case I (configs/uniaxial_stress/case1_*.toml)
    as a dict: one 1 m cell, 8 particles, E = 1000 Pa, nu = 0.2, the top
    pushed down at 0.01 m/s to t = 0.1 s."""
    return {
        "name": "uniaxial_from_python",
        "analysis": {"dimension": 3, "scheme": scheme, "shape_function": "linear", "velocity_update": "flip",
                     "dt": dt, "end_time": 0.1},
        "grid": {"origin": [0.0, 0.0, 0.0], "cell_size": 1.0, "cells": [1, 1, 1]},
        "materials": {"elastic": {"type": "linear_elastic", "density": 1.0, "youngs_modulus": 1000.0,
                                  "poisson_ratio": 0.2}},
        "bodies": [{"name": "block", "material": "elastic", "min": [0.0, 0.0, 0.0], "max": [1.0, 1.0, 1.0],
                    "particles_per_cell": 2}],
        "node_sets": [{"name": "bottom", "plane": "y", "at": 0.0, "velocity": {"y": 0.0}},
                      {"name": "top", "plane": "y", "at": 1.0, "velocity": {"y": -0.01}}],
        "output": {"every": 10},
    }


class ScratchTest(unittest.TestCase):
    """A test with a scratch folder, self.scratch, removed after it."""

    def setUp(self):
        self._scratch = tempfile.TemporaryDirectory(prefix="flowmpm-python-")
        self.scratch = self._scratch.name

    def tearDown(self):
        self._scratch.cleanup()
