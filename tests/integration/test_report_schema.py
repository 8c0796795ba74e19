"""Issue 17: the report has one schema, docs/report.schema.json (JSON Schema 2020-12), which the README points
to. Reports of parts that between them have every key (a plate with holes; a hat section at order 2 with
--aspect; a T-junction meshed with --drop-junctions and meshed with its rib (issue 18); a file of two solids, with --shell;
a boss merged into a box's wall) are validated against it with
python3-jsonschema; every key the schema describes appears in one of them (no stale entries), and a report with
a key the schema does not know fails (the schema is closed: a new key must be documented there).

Run by CTest as: /usr/bin/python3 test_report_schema.py --hexlayer PATH --source DIR
"""
import copy
import json
import os
import subprocess
import tempfile
import unittest

import jsonschema

import harness

RUNS = {
    "plate_holes": ("Resources/samples/plate_holes.step", []),
    "hat_order2": ("Resources/samples/rims/hat_round_ends.step", ["--order", "2", "--aspect", "4"]),
    "t_junction": ("tests/data/robustness/t_junction.step", ["--drop-junctions"]),
    "t_junction_meshed": ("tests/data/robustness/t_junction.step", []),  # the rib meshed with the plate
    "two_plates": ("tests/data/robustness/two_plates.step", ["--shell"]),  # its mid-surface shell too
    # a boss merged 0.5 into a 60 x 40 x 15 box's wall (test_junction_meshing.py's write_boss_in_a_wall): its flat's
    # creases followed by its quads (crease_chains)
    "boss_in_wall": ("tests/data/robustness/boss_in_wall.step", []),
}


def report(tmp, name):
    path, extra = RUNS[name]
    out = os.path.join(tmp, name + ".json")
    done = subprocess.run([harness.args.hexlayer, "mesh", os.path.join(harness.args.source, path), "-o",
                           os.path.join(tmp, name + ".inp"), "--report", out, "--quiet", *extra],
                          capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        raise AssertionError(f"{name}: exit {done.returncode}: {done.stderr[-2000:]}")
    with open(out) as f:
        return json.load(f)


def keys(value, prefix=""):
    """The dotted paths of every object key in a report (arrays of objects: their items' keys)."""
    found = set()
    if isinstance(value, dict):
        for k, v in value.items():
            found.add(prefix + k)
            found |= keys(v, prefix + k + ".")
    elif isinstance(value, list):
        for v in value:
            found |= keys(v, prefix)
    return found


def schema_keys(node, schema, prefix=""):
    """The dotted paths of every property the schema describes."""
    if "$ref" in node:
        node = schema["$defs"][node["$ref"].split("/")[-1]]
    found = set()
    for k, v in node.get("properties", {}).items():
        found.add(prefix + k)
        found |= schema_keys(v, schema, prefix + k + ".")
    if "items" in node and isinstance(node["items"], dict):
        found |= schema_keys(node["items"], schema, prefix)
    for alternative in node.get("oneOf", []):
        found |= schema_keys(alternative, schema, prefix)
    return found


class ReportSchema(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        with open(os.path.join(harness.args.source, "docs", "report.schema.json")) as f:
            cls.schema = json.load(f)
        jsonschema.Draft202012Validator.check_schema(cls.schema)
        cls.validator = jsonschema.Draft202012Validator(cls.schema)
        with tempfile.TemporaryDirectory() as tmp:
            cls.reports = {name: report(tmp, name) for name in RUNS}

    def test_every_report_follows_the_schema(self):
        for name, r in self.reports.items():
            with self.subTest(part=name):
                errors = [f"{list(e.path)}: {e.message[:200]}" for e in self.validator.iter_errors(r)]
                self.assertEqual(errors, [])

    def test_the_reports_have_every_key_the_schema_describes(self):
        # A solid's report is the same whether alone or under "solids": compared without that prefix.
        def plain(paths):
            return {p[len("solids."):] if p.startswith("solids.") else p for p in paths}
        seen = set()
        for r in self.reports.values():
            seen |= plain(keys(r))
        # No part here fails validation (--force would hand on such a mesh): a failure's keys come from the
        # one written in test_a_validation_failure_follows_the_schema.
        seen |= {"validation.failures.check", "validation.failures.count", "validation.failures.at",
                 "validation.failures.message"}
        described = plain(schema_keys(self.schema, self.schema))
        self.assertEqual(sorted(described - seen), [])

    def test_an_unknown_key_fails(self):
        r = copy.deepcopy(self.reports["plate_holes"])
        r["quad_mesh"]["undocumented"] = 1
        self.assertFalse(self.validator.is_valid(r))
        r = copy.deepcopy(self.reports["plate_holes"])
        r["undocumented"] = 1
        self.assertFalse(self.validator.is_valid(r))

    def test_a_validation_failure_follows_the_schema(self):
        r = copy.deepcopy(self.reports["plate_holes"])
        r["validation"] = {"passed": False, "failures": [
            {"check": "inverted", "count": 2, "at": [1.0, 2.0, 0.5], "message": "inverted: 2 inverted hexes"}]}
        self.assertTrue(self.validator.is_valid(r))
        r["validation"]["failures"][0]["where"] = "undocumented"
        self.assertFalse(self.validator.is_valid(r))

    def test_the_parts_measure_what_they_should(self):
        self.assertEqual(self.reports["hat_order2"]["order"], 2)
        self.assertIn("quadratic", self.reports["hat_order2"])
        self.assertGreater(len(self.reports["t_junction"]["junctions"]), 0)
        self.assertEqual(len(self.reports["two_plates"]["solids"]), 2)


if __name__ == "__main__":
    harness.main()
