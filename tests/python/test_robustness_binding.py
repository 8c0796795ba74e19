"""The bad and hard inputs of tests/integration/test_robustness.py through pyhexlayer (issue 5): the same
exit code as an exception's exit_code and the CLI's very message, never a crash of the interpreter; as BREP
strings (FreeCAD's way in) too.

Run by CTest as: /usr/bin/python3 test_robustness_binding.py --hexlayer PATH --source DIR
with PYTHONPATH holding the built module and tests/integration (for harness and the table).
"""
import os
import subprocess
import tempfile
import unittest

import harness
import pyhexlayer
from test_robustness import TABLE, resolve

# CLI options the binding takes as keywords.
KEYWORDS = {"--layers": ("layers", int), "--size": ("size", float), "--aspect": ("aspect", float),
            "--order": ("order", int), "--sizing": ("sizing", str)}
EXCEPTIONS = {2: pyhexlayer.UsageError, 3: pyhexlayer.InputError, 4: pyhexlayer.GeometryError,
              6: pyhexlayer.ValidationError}


def keywords(extra):
    """The row's options as keywords, or None if one has no keyword (output paths, --min-size, bad syntax) or
    means something else to the binding."""
    pairs = []
    for arg in extra:
        if arg.startswith("--") and "=" in arg:
            pairs.extend(arg.split("=", 1))
        else:
            pairs.append(arg)
    out = {}
    for name, value in zip(pairs[::2], pairs[1::2]):
        if name not in KEYWORDS:
            return None
        key, kind = KEYWORDS[name]
        try:
            out[key] = kind(value)
        except ValueError:
            return None
    if out.get("size") == 0:  # size=0 is the binding's (and the panel's) "the wall thickness", not a bad size
        return None
    return out if len(pairs) % 2 == 0 else None


def cli(path, extra, tmp):
    done = subprocess.run([harness.args.hexlayer, "mesh", path, *extra, "-o", os.path.join(tmp, "m.inp"), "--quiet"],
                          capture_output=True, text=True, timeout=120)
    return done.returncode, done.stderr.strip().removeprefix("hexlayer: error: ")


class TableThroughTheBinding(unittest.TestCase):
    def test_same_exit_code_and_message_as_the_cli(self):
        checked = 0
        with tempfile.TemporaryDirectory() as tmp:
            open(os.path.join(tmp, "empty.step"), "w").close()
            os.mkdir(os.path.join(tmp, "folder.step"))
            for name, path, extra, code, fragment in TABLE:
                options = keywords(extra)
                if options is None or code == 0 and extra:
                    continue
                checked += 1
                with self.subTest(name):
                    cli_code, cli_message = cli(resolve(path, tmp), extra, tmp)
                    self.assertEqual(cli_code, code)
                    if code == 0:
                        result = pyhexlayer.mesh_file(resolve(path, tmp), **options)
                        self.assertTrue(result.report["validation"]["passed"])
                        continue
                    with self.assertRaises(EXCEPTIONS[code]) as raised:
                        pyhexlayer.mesh_file(resolve(path, tmp), **options)
                    self.assertEqual(raised.exception.exit_code, code)
                    self.assertEqual(str(raised.exception), cli_message)
                    self.assertIn(fragment, str(raised.exception))
        self.assertGreaterEqual(checked, 25)

    def test_damaged_brep_strings_are_input_errors(self):
        folder = os.path.join(harness.args.source, "tests", "data", "robustness")
        for name, phrase in (("truncated.brep", "the BREP reader timed out"), ("garbage.brep", "not a valid BREP file"),
                             ("open_shell.brep", "contains no solid: 1 open shell(s) of 5 face(s)")):
            with self.subTest(name):
                with open(os.path.join(folder, name), encoding="latin-1") as f:
                    text = f.read()
                with self.assertRaises(pyhexlayer.InputError) as raised:
                    pyhexlayer.mesh_brep(text)
                self.assertIn(phrase, str(raised.exception))
                self.assertIn("the BREP string", str(raised.exception))

    def test_a_mesh_that_fails_validation_is_returned_only_when_forced(self):
        # Quads 8 x the wall across the hat section's bends and holes: the volume is far off the part's.
        part = os.path.join(harness.args.source, "Resources", "samples", "hat_holes.step")
        with self.assertRaises(pyhexlayer.ValidationError) as raised:
            pyhexlayer.mesh_file(part, size=12, sizing="uniform")
        self.assertEqual(raised.exception.exit_code, 6)
        self.assertIn("the mesh failed validation, nothing written", str(raised.exception))
        forced = pyhexlayer.mesh_file(part, size=12, sizing="uniform", force=True)
        failures = forced.report["validation"]["failures"]
        self.assertFalse(forced.report["validation"]["passed"])
        self.assertIn("volume", [f["check"] for f in failures])
        for f in failures:
            self.assertIn(f["message"], str(raised.exception))


if __name__ == "__main__":
    harness.main()
