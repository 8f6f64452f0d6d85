"""The round trip: a case built and changed in Python, run, its results
loaded and compared with the uniaxial closed form (CB-Geo's Case I,
docs/validation/uniaxial_stress.md)."""
import os
import unittest

import numpy as np

import flowmpm
from flowmpm.tables import columns_of, read_csv
from support import ScratchTest, uniaxial_case

E, NU, SPEED, HEIGHT = 1000.0, 0.2, 0.01, 1.0  # Pa, -, m/s (the top's), m


class RoundTripTest(ScratchTest):
    def test_uniaxial_stress_against_the_closed_form(self):
        case = flowmpm.Case(uniaxial_case(scheme="usf", dt=0.01))
        case.set("analysis.scheme", "usl").set("analysis.dt", 0.001).set("output.every", 20)
        output = os.path.join(self.scratch, "uniaxial")
        r = flowmpm.run(case, output=output, threads=1)

        self.assertTrue(os.path.exists(os.path.join(output, "case.toml")))  # a case made in Python is saved
        self.assertEqual(r.summary["status"], "completed")
        self.assertEqual(r.summary["scheme"], "USL")
        np.testing.assert_array_equal(r.steps, np.arange(0, 101, 20))
        np.testing.assert_allclose(r.times, r.steps * 0.001, rtol=1e-12)
        self.assertEqual(list(r.ids), list(range(8)))
        self.assertEqual(list(r.bodies), ["block"])
        self.assertEqual(r.tensor_components, ["xx", "yy", "zz", "xy", "yz", "xz"])
        self.assertEqual(r.units, "SI: m, s, kg, Pa, J")
        xx, yy, zz = (r.tensor_components.index(c) for c in ("xx", "yy", "zz"))

        # Closed form, quasi-static uniaxial stress: eps_yy = -v t / H,
        # sigma_yy = E eps_yy, eps_xx = eps_zz = -nu eps_yy, sigma_xx = 0.
        strain = r.history("strain", r.ids)   # steps x particles x 6
        stress = r.history("stress", r.ids)
        eps = -SPEED * r.times / HEIGHT
        # The strain is kinematic: the top node's prescribed motion, exact to round-off.
        np.testing.assert_allclose(strain[:, :, yy], eps[:, None] * np.ones((1, 8)), rtol=0, atol=1e-15)
        # The stresses carry the block's lateral inertia: it starts at rest
        # and its top is pushed at once, so it vibrates sideways (a wave
        # crosses it in H / c_p = 0.03 s) about the quasi-static closed form.
        # Measured at t = 0.1 s (USL, dt = 0.001 s): sigma_yy -0.98663 Pa
        # (1.3 % off), sigma_xx = sigma_zz = 0.0334 Pa, eps_xx = 2.24e-4
        # (12 % above nu |eps_yy|). The bounds: 2 %, 5 % of |sigma_yy|, 15 %.
        # A wrong column would be off by 100 % (yy against xx).
        final = stress[-1]
        np.testing.assert_allclose(final[:, yy], E * eps[-1], rtol=0.02)
        self.assertLess(np.abs(final[:, [xx, zz]]).max(), 0.05 * E * abs(eps[-1]))
        np.testing.assert_allclose(strain[-1][:, [xx, zz]], -NU * eps[-1], rtol=0.15)
        self.assertEqual(np.abs(stress[0]).max(), 0.0)

        # One body: its rows are all rows; timeseries.csv's mean (volume
        # weighted, Voigt order) is the mean of the rows.
        np.testing.assert_array_equal(r.field("stress", body="block"), r.field("stress"))
        volume = r.field("volume")
        mean_yy = (volume * r.field("stress")[:, yy]).sum() / volume.sum()
        ts = r.timeseries
        self.assertAlmostEqual(float(np.asarray(ts["block.stress_yy"])[-1]), mean_yy, delta=1e-12)
        self.assertAlmostEqual(r.summary["bodies"][0]["mean_stress"]["yy"], mean_yy, delta=1e-12)
        np.testing.assert_allclose(np.asarray(ts["time"]), r.times, rtol=1e-12)
        plain = read_csv(os.path.join(output, "timeseries.csv"), use_pandas=False)   # the table without pandas
        self.assertEqual(plain.dtype.names, tuple(columns_of(ts)))
        np.testing.assert_array_equal(plain["block.stress_yy"], np.asarray(ts["block.stress_yy"]))
        self.assertEqual(r.history("position", 7).shape, (len(r.steps), 3))


if __name__ == "__main__":
    unittest.main()
