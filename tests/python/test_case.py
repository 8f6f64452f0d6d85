"""flowmpm.Case and flowmpm.check: keys as --set takes them, a saved case
that keeps its comments and runs as the file with --set options does, and
a bad key and a bad value raising CaseError that names them."""
import os
import tomllib
import unittest

import numpy as np

import flowmpm
from support import ROOT, ScratchTest, uniaxial_case

USL = os.path.join(ROOT, "configs", "uniaxial_stress", "case1_usl.toml")


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


class KeysTest(unittest.TestCase):
    def test_get_and_set_with_the_keys_of_set(self):
        case = flowmpm.Case.load(USL)
        self.assertEqual(case["analysis.dt"], 0.01)
        self.assertEqual(case["bodies.0.max"], [1.0, 1.0, 1.0])
        self.assertEqual(case["bodies[0].name"], "block")           # as the engine's messages name it
        self.assertEqual(case["node_sets[1].velocity.y"], -0.01)
        case.set("node_sets.1.velocity.y", -0.02).set("bodies[0].velocity", (0.5, 0, 0))
        self.assertEqual(case.data["node_sets"][1]["velocity"], {"y": -0.02})
        self.assertEqual(case.data["bodies"][0]["velocity"], [0.5, 0, 0])  # a tuple is a TOML array
        case.set("analysis.damping.type", "local")                  # missing tables are made, as --set makes them
        self.assertEqual(case["analysis.damping"], {"type": "local"})
        self.assertEqual(case.set_options()[-1], 'analysis.damping.type="local"')
        with self.assertRaises(KeyError):
            case["analysis.nothing"]

    def test_keys_that_cannot_be_set_name_themselves(self):
        case = flowmpm.Case.load(USL)
        for key, what in (("bodies.3.name", "index 3 is out of range"),
                          ("bodies.first.name", "'first' must be an index into an array"),
                          ("analysis.dt.a.b", "'a' is not a table"),
                          ("analysis.dt.value", "the key's parent is not a table"),
                          ("bodies.0", "the key's parent is not a table")):
            with self.assertRaises(flowmpm.CaseError, msg=key) as caught:
                case.set(key, 1)
            self.assertEqual(caught.exception.key, key)
            self.assertIn(what, caught.exception.message)
        self.assertEqual(case.changes, [])
        self.assertEqual(case.data, tomllib.loads(read(USL)))   # unchanged by the failed sets


class SaveTest(ScratchTest):
    def test_save_keeps_the_comments_and_changes_only_the_values_set(self):
        case = flowmpm.Case.load(USL)
        case.set("analysis.dt", 0.001).set("materials.elastic.youngs_modulus", 2e3)
        case.set("node_sets.1.velocity.y", -0.02).set("output.fields", ["id", "stress"])
        saved = os.path.join(self.scratch, "changed.toml")
        case.save(saved)
        before, after = read(USL).splitlines(), read(saved).splitlines()
        self.assertEqual(tomllib.loads(read(saved)), case.data)
        changed = [(a, b) for a, b in zip(before, after) if a != b]
        self.assertEqual(len(changed), 3, changed)                    # three lines edited in place ...
        self.assertEqual(after[len(before):], ['fields = ["id", "stress"]'])  # ... and one added
        self.assertEqual([line for line in before if line.lstrip().startswith("#")],
                         [line for line in after if line.lstrip().startswith("#")])
        self.assertTrue(any(line.startswith("dt = 0.001 ") and "#" in line for line in after))

    def test_a_case_made_in_python_saves_as_toml_that_reads_back(self):
        case = flowmpm.Case(uniaxial_case())
        case.set("materials.steel", {"type": "linear_elastic", "density": 7850.0, "youngs_modulus": 2.1e11,
                                     "poisson_ratio": 0.3})
        path = os.path.join(self.scratch, "made.toml")
        case.save(path)
        self.assertEqual(tomllib.loads(read(path)), case.data)
        self.assertIn("[[bodies]]", read(path))

    def test_set_and_save_give_what_the_engine_reads_from_set_options(self):
        # The same changes two ways: the file with --set options (run() of a
        # loaded case), and the file case.save wrote. Bit-identical results.
        case = flowmpm.Case.load(USL)
        case.set("analysis.scheme", "musl").set("bodies[0].velocity", [0.0, 0.001, 0.0])
        case.set("node_sets.1.velocity.y", -0.02).set("output.every", 5)
        with_sets = flowmpm.run(case, output=os.path.join(self.scratch, "with_sets"), threads=1)
        saved = case.save(os.path.join(self.scratch, "saved.toml"))
        self.assertEqual(saved.changes, [])
        from_file = flowmpm.run(saved, output=os.path.join(self.scratch, "from_file"), threads=1)
        self.assertEqual(list(with_sets.steps), [0, 5, 10])
        self.assertEqual(with_sets.summary["scheme"], "MUSL")
        for k in range(len(with_sets.steps)):
            for name in ("position", "velocity", "stress", "strain"):
                np.testing.assert_array_equal(with_sets.field(name, k), from_file.field(name, k))
        # The top moved down at 0.02 m/s (the edited inline table) over 0.1 s.
        self.assertAlmostEqual(with_sets.summary["bodies"][0]["mean_strain"]["yy"], -0.002, delta=1e-12)


class CheckTest(ScratchTest):
    def test_a_valid_case_passes(self):
        self.assertIsNone(flowmpm.check(USL))
        self.assertIsNone(flowmpm.check(flowmpm.Case(uniaxial_case())))

    def test_a_bad_key_in_a_file_names_file_line_and_key(self):
        text = read(USL).replace("\nevery = 10", "\nevry = 10")
        path = os.path.join(self.scratch, "typo.toml")
        with open(path, "w") as f:
            f.write(text)
        with self.assertRaises(flowmpm.CaseError) as caught:
            flowmpm.check(path)
        e = caught.exception
        line = 1 + text.splitlines().index("evry = 10")
        self.assertEqual((e.file, e.line, e.key), (path, line, "output.evry"))
        self.assertEqual(e.message, "unknown key (did you mean output.every?)")
        self.assertEqual(str(e), f"{path}:{line}: output.evry: {e.message}")

    def test_a_file_that_is_not_toml_names_its_line(self):
        path = os.path.join(self.scratch, "cut.toml")
        with open(path, "w") as f:
            f.write("[grid]\ncells = [1,\norigin = [0.0]\n")    # the array never closed
        with self.assertRaises(flowmpm.CaseError) as caught:
            flowmpm.Case.load(path)
        self.assertEqual((caught.exception.file, caught.exception.line), (path, 3))
        self.assertTrue(caught.exception.message.startswith("not valid TOML: "))

    def test_a_bad_value_set_in_python_names_the_key(self):
        case = flowmpm.Case.load(USL).set("analysis.dt", 0.05)   # above the stable limit
        with self.assertRaises(flowmpm.CaseError) as caught:
            flowmpm.check(case)
        e = caught.exception
        self.assertEqual((e.file, e.line, e.key), (None, None, "analysis.dt"))
        self.assertIn("expected a time step no larger than the stable limit", e.message)
        self.assertTrue(e.message.endswith("got the number 0.05"))
        self.assertTrue(str(e).startswith("--set analysis.dt=0.05: analysis.dt: expected "))

    def test_a_bad_value_in_run_raises_before_anything_is_written(self):
        output = os.path.join(self.scratch, "never")
        with self.assertRaises(flowmpm.CaseError) as caught:
            flowmpm.run(USL, output=output, set={"analysis.scheme": "usx"})
        self.assertEqual(caught.exception.key, "analysis.scheme")
        self.assertIn('expected one of "usf", "usl", "musl"', caught.exception.message)
        self.assertFalse(os.path.exists(os.path.join(output, "results.h5")))

    def test_a_bad_value_in_a_case_made_in_python_names_the_saved_line(self):
        data = uniaxial_case()
        data["materials"]["elastic"]["poisson_ratio"] = 0.7
        with self.assertRaises(flowmpm.CaseError) as caught:
            flowmpm.check(flowmpm.Case(data))
        e = caught.exception
        self.assertEqual(e.key, "materials.elastic.poisson_ratio")
        saved = flowmpm.Case(data).text().splitlines()
        self.assertEqual(saved[e.line - 1], "poisson_ratio = 0.7")


if __name__ == "__main__":
    unittest.main()
