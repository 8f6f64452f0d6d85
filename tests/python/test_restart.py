"""A history that stays continuous through a restart: a run stopped with
SIGINT part way (as Ctrl-C stops it: a checkpoint, exit status 130),
continued with flowmpm.run(..., restart=DIR), reads as one history, step
for step and bit for bit the history of the same case run without
stopping (docs/guide/checkpoint_restart.md's guarantee, seen from Python)."""
import os
import signal
import subprocess
import time
import unittest

import numpy as np

import flowmpm
from support import ScratchTest, uniaxial_case

STEPS, EVERY = 100000, 5000


def lines(path):
    try:
        with open(path) as f:
            return sum(1 for _ in f)
    except FileNotFoundError:
        return 0


class RestartTest(ScratchTest):
    def test_history_through_a_restart(self):
        case = flowmpm.Case(uniaxial_case(scheme="usl", dt=0.1 / STEPS)).set("output.every", EVERY)
        path = os.path.join(self.scratch, "long.toml")
        case.save(path)
        stopped = os.path.join(self.scratch, "stopped")

        # Stopped once two output steps are in timeseries.csv (steps 0 and 5000 of 100000).
        process = subprocess.Popen([flowmpm.program(), "run", path, "--output", stopped, "--threads", "1",
                                    "--quiet"], stderr=subprocess.PIPE, text=True)
        rows = os.path.join(stopped, "timeseries.csv")
        while process.poll() is None:
            if lines(rows) >= 3:
                process.send_signal(signal.SIGINT)
                break
            time.sleep(0.005)
        _, log = process.communicate()
        self.assertEqual(process.returncode, 130, log)
        with flowmpm.Results(stopped) as r:
            at = int(r.summary["status"].removeprefix("interrupted at step "))
            self.assertTrue(EVERY <= at < STEPS, r.summary["status"])
            # Its output steps: every 5000th up to the stop, and the step it stopped at.
            self.assertEqual(r.steps[-1], at)
            before_steps, before = r.steps, r.history("stress", r.ids)

        continued = flowmpm.run(path, restart=stopped, threads=1)
        once = flowmpm.run(path, output=os.path.join(self.scratch, "once"), threads=1)
        self.assertEqual(continued.summary["status"], "completed")
        np.testing.assert_array_equal(continued.steps, np.arange(0, STEPS + 1, EVERY))
        np.testing.assert_array_equal(continued.steps, once.steps)
        np.testing.assert_array_equal(continued.times, once.times)
        self.assertTrue(np.all(np.diff(continued.times) > 0))
        for name in ("stress", "position", "velocity"):
            np.testing.assert_array_equal(continued.history(name, continued.ids), once.history(name, once.ids))
        ts = continued.timeseries
        np.testing.assert_array_equal(np.asarray(ts["step"]), continued.steps)  # one row per output step
        # Its first steps are the stopped run's, kept as they were; the step
        # the stopped run ended at (not an output step) is gone.
        kept = len(before_steps) - 1
        np.testing.assert_array_equal(continued.steps[:kept], before_steps[:-1])
        np.testing.assert_array_equal(continued.history("stress", continued.ids)[:kept], before[:-1])
        self.assertNotIn(at, continued.steps)


if __name__ == "__main__":
    unittest.main()
