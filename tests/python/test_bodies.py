"""Rows by particle id and by body after a run whose particles were
re-sorted: three bodies of one material (so the `material` field cannot
tell them apart), one of them cut by an inclusion that wins over it
(`wins_over` removes its particles there), two moving right and one left
across many grid blocks, no gravity and no constraints: every particle
translates with its body's velocity."""
import os
import re
import unittest

import numpy as np

import flowmpm
from support import ScratchTest

V_MATRIX, V_BLOCK, END = 2.0, -1.0, 0.5   # m/s, m/s, s


def three_bodies():
    def body(name, low, high, velocity, **more):
        return dict(name=name, material="rubber", min=low, max=high, particles_per_cell=2,
                    velocity=[velocity, 0.0], **more)
    return flowmpm.Case({
        "name": "three_bodies",
        "analysis": {"dimension": 2, "scheme": "usl", "dt": 1e-3, "end_time": END},
        "grid": {"origin": [0.0, 0.0], "cell_size": 0.1, "cells": [40, 10]},
        "materials": {"rubber": {"type": "linear_elastic", "density": 1000.0, "youngs_modulus": 1e6,
                                 "poisson_ratio": 0.3}},
        "bodies": [body("matrix", [0.2, 0.2], [1.0, 0.8], V_MATRIX),
                   body("inclusion", [0.4, 0.4], [0.6, 0.6], V_MATRIX, wins_over=["matrix"]),
                   body("block", [3.0, 0.2], [3.6, 0.8], V_BLOCK)],
        "output": {"every": 100, "fields": ["id", "position", "displacement", "material"]},
    })


def inside(points, low, high):
    return np.all((points[:, :2] > np.array(low)) & (points[:, :2] < np.array(high)), axis=1)


class BodiesTest(ScratchTest):
    def test_rows_by_id_and_by_body_after_resorting(self):
        output = os.path.join(self.scratch, "bodies")
        r = flowmpm.run(three_bodies(), output=output, threads=2)
        with open(os.path.join(output, "run.log")) as f:
            sorts = int(re.search(r"particles sorted (\d+) times", f.read()).group(1))
        self.assertGreater(sorts, 1)  # the particles were re-sorted as they moved

        # 2 x 2 cells x 2 x 2 per cell = 16 particles in the inclusion; the
        # matrix's 8 x 6 x 4 = 192 less the 16 the inclusion took; 6 x 6 x 4 in the block.
        self.assertEqual(list(r.bodies), ["matrix", "inclusion", "block"])
        self.assertEqual([len(ids) for ids in r.bodies.values()], [176, 16, 144])
        np.testing.assert_array_equal(np.concatenate(list(r.bodies.values())), r.ids)
        with open(os.path.join(output, "run.log")) as f:
            log = f.read()
        for name, ids in r.bodies.items():
            self.assertIn(f"body '{name}': {len(ids)} particles", log)

        x0 = r.field("position", step=0)
        matrix0 = r.field("position", step=0, body="matrix")
        self.assertTrue(inside(matrix0, [0.2, 0.2], [1.0, 0.8]).all())
        self.assertFalse(inside(matrix0, [0.4, 0.4], [0.6, 0.6]).any())   # the inclusion's particles removed
        self.assertTrue(inside(r.field("position", 0, "inclusion"), [0.4, 0.4], [0.6, 0.6]).all())
        self.assertTrue(inside(r.field("position", 0, "block"), [3.0, 0.2], [3.6, 0.8]).all())

        # At every output step each body's rows moved with its velocity (to
        # 5.5e-14 m, measured; 1e-12 allowed): a row that changed particle
        # would be off by the spacing, 0.05 m, one that changed body by 1.5 m.
        for k, t in enumerate(r.times):
            for name, v in (("matrix", V_MATRIX), ("inclusion", V_MATRIX), ("block", V_BLOCK)):
                moved = r.field("displacement", k, name)
                np.testing.assert_allclose(moved[:, 0], v * t, rtol=0, atol=1e-12)
                np.testing.assert_allclose(moved[:, 1], 0.0, rtol=0, atol=1e-12)
                np.testing.assert_array_equal(moved, r.field("position", k, name) - x0[r.bodies[name]])
        # The history of one particle of each body, by id.
        for name, v in (("inclusion", V_MATRIX), ("block", V_BLOCK)):
            first = r.bodies[name][0]
            np.testing.assert_allclose(r.history("position", first)[:, 0], x0[first, 0] + v * r.times,
                                       rtol=0, atol=1e-12)
        both = r.history("displacement", [r.bodies["block"][5], r.bodies["matrix"][3]])
        self.assertEqual(both.shape, (len(r.steps), 2, 3))
        np.testing.assert_allclose(both[-1, :, 0], [V_BLOCK * END, V_MATRIX * END], atol=1e-12)
        np.testing.assert_array_equal(r.field("material"), 0)   # one material: only the bodies tell them apart
        with self.assertRaises(KeyError):
            r.field("position", body="lid")

    def test_a_run_that_fails_raises_simulation_error(self):
        # The block sent left at 20 m/s leaves the 4 m grid within the 0.5 s.
        output = os.path.join(self.scratch, "failed")
        with self.assertRaises(flowmpm.SimulationError) as caught:
            flowmpm.run(three_bodies(), output=output, set={"bodies.2.velocity": [-20.0, 0.0]})
        e = caught.exception
        self.assertEqual((e.status, e.output), (2, output))
        self.assertIn("outside the grid", e.message)
        with open(os.path.join(output, "summary.json")) as f:
            self.assertIn('"status": "failed: ', f.read())


if __name__ == "__main__":
    unittest.main()
