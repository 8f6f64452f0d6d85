"""A sweep's table: sweep.csv joined with each case's summary.json, row by
row, and its speed against error with the Pareto front. The sweep: the
vibrating bar (configs/verification/bar_vibration_small.toml, with an
analytical reference) over two schemes and two resolutions, 4 cases."""
import os
import unittest

import numpy as np

import flowmpm
from flowmpm.sweep import pareto_front
from flowmpm.tables import columns_of
from support import ROOT, ScratchTest

SWEEP = """base = "{base}"
output = "{output}"

[vary]
"analysis.scheme" = ["usl", "musl"]

[[zip]]
"grid.cell_size" = [0.0625, 0.03125]
"grid.cells" = [[20], [40]]
"grid.origin" = [[-0.125], [-0.0625]]
"analysis.dt" = [1.25e-3, 6.25e-4]
"""


class SweepTest(ScratchTest):
    def test_the_table_joins_each_row_with_its_case(self):
        sweep_file = os.path.join(self.scratch, "bar.toml")
        with open(sweep_file, "w") as f:
            f.write(SWEEP.format(base=os.path.join(ROOT, "configs", "verification", "bar_vibration_small.toml"),
                                 output=os.path.join(self.scratch, "out")))
        s = flowmpm.sweep(sweep_file, threads=2)               # into the sweep file's output
        self.assertEqual(s.directory, os.path.join(self.scratch, "out"))
        self.assertEqual(flowmpm.Sweep(sweep_file).directory, s.directory)
        self.assertEqual(s.keys, ["analysis.scheme", "grid.cell_size", "grid.cells", "grid.origin", "analysis.dt"])
        self.assertIn("displacement", s.errors)
        columns = columns_of(s.table)
        for name in ("case", "status", "wall_seconds", "displacement", "scheme", "dt", "energy_error",
                     "errors.displacement", "bar.stress_xx"):
            self.assertIn(name, columns)
        self.assertEqual(list(s.column("case")), ["000", "001", "002", "003"])
        self.assertEqual(list(s.column("status")), ["completed"] * 4)
        # Row i is case i: its varied values are what its summary.json ran.
        self.assertEqual([v.upper() for v in s.column("analysis.scheme")], list(s.column("scheme")))
        np.testing.assert_array_equal(s.column("analysis.dt").astype(float), s.column("dt"))
        np.testing.assert_array_equal(s.column("steps"), np.round(0.4 / s.column("dt")))   # 320 and 640
        np.testing.assert_allclose(s.column("displacement"), s.column("errors.displacement"), rtol=1e-12)
        # Halving the cells cuts the displacement error by about 4 (bspline2,
        # second order; measured 3.99 for USL and 3.97 for MUSL, 4.6e-3 to 1.2e-3).
        error = s.column("displacement")
        for coarse, fine in ((0, 1), (2, 3)):
            self.assertGreater(error[coarse] / error[fine], 3.0)

    def test_pareto_front(self):
        seconds = [1.0, 2.0, 3.0, 4.0, 0.5]
        error = [5.0, 3.0, 4.0, 1.0, 6.0]
        self.assertEqual(pareto_front(seconds, error), [4, 0, 1, 3])   # 3 s / 4.0 is beaten by 2 s / 3.0

    def test_plot_speed_vs_error(self):
        try:
            import matplotlib
        except ImportError:
            self.skipTest("no matplotlib (Debian's python3-matplotlib; scripts/setup.sh --tests installs it)")
        matplotlib.use("Agg")
        out = os.path.join(self.scratch, "out")
        os.makedirs(os.path.join(out, "cases"))
        with open(os.path.join(out, "sweep.csv"), "w") as f:   # a table with a known front
            f.write("case,analysis.dt,status,particles,steps,wall_seconds,particle_steps_per_second,stress,message\n"
                    "000,0.1,completed,8,10,1.0,80,5.0,\n001,0.05,completed,8,20,2.0,80,3.0,\n"
                    "002,0.02,completed,8,50,3.0,133,4.0,\n003,0.01,failed,8,0,0,0,,blew up\n")
        s = flowmpm.Sweep(out)
        self.assertEqual(s.errors, ["stress"])
        png = os.path.join(self.scratch, "front.png")
        ax = s.plot_speed_vs_error(path=png)
        front = ax.get_lines()[1]
        np.testing.assert_array_equal(front.get_xdata(), [1.0, 2.0])
        np.testing.assert_array_equal(front.get_ydata(), [5.0, 3.0])
        with open(png, "rb") as f:
            self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")


if __name__ == "__main__":
    unittest.main()
