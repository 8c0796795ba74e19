"""Bad and hard inputs (issue 5): each row of TABLE runs the CLI on one input with a time limit and checks its
exit code and a fragment of its message; none may crash (a signal) or hang (the time limit). The hard CAD
files are made by scripts/make_bad_inputs.py into tests/data/robustness.

Run by CTest as: /usr/bin/python3 test_robustness.py --hexlayer PATH --source DIR
"""
import json
import math
import os
import subprocess
import tempfile
import unittest

import harness
from cad import face_group, junctions_named

SECONDS = 120  # every row is done in a few seconds; a hang is cut off here and fails its row

# (name, input file, extra arguments, exit code, fragment of stderr (or of stdout for exit 0)).
# Inputs: "data/X" is tests/data/robustness/X, "sample/X" is Resources/samples/X, "fuzz/X" is an input the
# fuzzer found (tests/fuzz/findings/X), "tmp/X" a path in
# the run's temporary folder (empty.step is made there empty, folder.step as a folder). Numbers in the fragments
# come from how scripts/make_bad_inputs.py builds the part (plate(): a 60 x 40 x 2 box), not from hexlayer's output.
RIB = ((0, 19, 2), (60, 21, 14))  # t_junction.step: a 60 x 2 x 12 box standing on the plate, its corners
RIB_CENTRE = "({:g}, {:g}, {:g})".format(*((a + b) / 2 for a, b in zip(*RIB)))
TABLE = [
    # files that cannot be read
    ("missing file", "tmp/missing.step", [], 3, "does not exist"),
    ("empty file", "tmp/empty.step", [], 3, "is empty"),
    ("folder as input", "tmp/folder.step", [], 3, "is not a regular file"),
    ("garbage STEP", "data/garbage.step", [], 3, "not a valid STEP file"),
    ("garbage BREP", "data/garbage.brep", [], 3, "not a valid BREP file"),
    ("garbage IGES", "data/garbage.iges", [], 3, "not a valid IGES file"),
    ("truncated STEP", "data/truncated.step", [], 3, "not a valid STEP file"),
    ("truncated BREP", "data/truncated.brep", [], 3, "the BREP reader timed out"),
    ("STEP that crashes OpenCASCADE", "fuzz/step_reader_segv.step", [], 3, "the STEP reader crashed (Segmentation fault)"),
    ("STEP text named .brep", "data/step_text.brep", [], 3, "not a valid BREP file"),
    ("unknown extension", "data/plate.txt", [], 3, "unknown input format '.txt'"),
    # files without one closed solid
    ("lone face", "data/lone_face.step", [], 3, "contains no solid: 1 open shell(s) of 1 face(s)"),
    ("IGES lone face", "data/lone_face.iges", [], 3, "contains no solid: 1 loose face(s)"),
    ("wire only", "data/wire.step", [], 3, "contains no solid: 3 edge(s) (wires or curves), no face"),
    ("open shell (STEP)", "data/open_shell.step", [], 3, "1 open shell(s) of 5 face(s) in all, not closed"),
    ("open shell (BREP)", "data/open_shell.brep", [], 3, "1 open shell(s) of 5 face(s) in all, not closed"),
    # geometry the method does not handle
    # a 30 x 20 x 15 box (which of its sides the mesher takes for the thickness is its own choice), a cube
    ("thick block", "data/thick_block.step", [], 4, f"over part size (diagonal) {math.hypot(30, 20, 15):.6g} = "),
    ("cube", "sample/thick_block.step", [], 4, f"= {1 / math.sqrt(3):.6g} (a thin section has at most 0.25)"),
    # a rib on the plate is meshed with it (issue 18), but its mid-surface shell is not made yet
    ("rib (T-junction)", "data/t_junction.step", [], 0, f"Volume {60 * 40 * 2 + 60 * 2 * 12} vs CAD"),
    ("rib, shell", "data/t_junction.step", ["--shell"], 4,
     "T-junction: 1 sheet(s) (rib, boss or flange) stand on the main sheet"),
    ("rib: where", "data/t_junction.step", ["--shell"], 4, RIB_CENTRE + " ["),  # test_rib_junction_names_its_walls
    ("rib left out", "data/t_junction.step", ["--drop-junctions"], 0, f"Volume {60 * 40 * 2} vs CAD {60 * 40 * 2}"),
    # several solids and small features: a valid mesh
    ("two solids", "data/two_plates.step", [], 0, "2 solids, each meshed on its own"),
    # a hole of radius 0.25 at (30, 20): its two circles shorter than the quad size, its wall narrower; the first
    # at a point of its top circle
    ("hole below the size", "data/small_hole.step", [], 0,
     f"2 CAD edges shorter than the quad size and 1 faces narrower (the first at ({30 - 0.25:g}, 20, 2))"),
    ("fillets below the size", "data/small_fillets.step", [], 0, "features that small may be smoothed over"),
    ("chamfers below the size", "data/small_chamfers.step", [], 0, "features that small may be smoothed over"),
    ("short edge", "data/short_edge.step", [], 0, "features that small may be smoothed over"),
    ("sliver face", "data/sliver_face.step", [], 0, "features that small may be smoothed over"),
    ("BREP file", "data/plate.brep", [], 0, "Wrote"),
    # bad options
    ("zero layers", "data/plate.brep", ["--layers", "0"], 2, "--layers must be between 1 and 64, got 0"),
    ("negative layers", "data/plate.brep", ["--layers=-3"], 2, "--layers must be between 1 and 64, got -3"),
    ("absurd layers", "data/plate.brep", ["--layers", "1000000"], 2, "--layers must be between 1 and 64"),
    ("layers not a number", "data/plate.brep", ["--layers", "abc"], 2, "--layers"),
    ("zero size", "data/plate.brep", ["--size", "0"], 2, "--size must be a positive length"),
    ("negative size", "data/plate.brep", ["--size=-1"], 2, "--size must be a positive length"),
    ("NaN size", "data/plate.brep", ["--size", "nan"], 2, "--size must be a positive length"),
    ("infinite size", "data/plate.brep", ["--size", "inf"], 2, "--size must be a positive length"),
    ("size needing terabytes", "data/plate.brep", ["--size", "1e-4"], 2, "GB of memory (estimated), more than this machine's"),
    ("64 layers of tiny quads", "data/plate.brep", ["--layers", "64", "--size", "0.01"], 2,
     f"quads, {64 * 60 * 40 / 0.01 ** 2:.3g} hexes"),
    ("size larger than the part", "data/plate.brep", ["--size", "1e6"], 0, "Wrote"),
    ("negative aspect", "data/plate.brep", ["--aspect=-1"], 2, "--aspect must be a positive ratio"),
    ("size and aspect", "data/plate.brep", ["--size", "1", "--aspect", "2"], 2, "give --size or --aspect, not both"),
    ("order 3", "data/plate.brep", ["--order", "3"], 2, "--order must be 1 or 2, got 3"),
    ("unknown sizing", "data/plate.brep", ["--sizing", "fractal"], 2, "--sizing must be 'uniform' or 'adaptive'"),
    ("min above max size", "data/plate.brep", ["--sizing", "adaptive", "--min-size", "5", "--max-size", "1"], 2,
     "--min-size <= --max-size"),
    ("unknown output format", "data/plate.brep", ["-o", "tmp/out.stl"], 2, "unknown output format '.stl'"),
    ("output folder missing", "data/plate.brep", ["-o", "tmp/no/such/folder/out.inp"], 3, "cannot open the output file"),
]


def resolve(path, tmp):
    kind, name = path.split("/", 1)
    folder = {"data": os.path.join(harness.args.source, "tests", "data", "robustness"),
              "sample": os.path.join(harness.args.source, "Resources", "samples"),
              "fuzz": os.path.join(harness.args.source, "tests", "fuzz", "findings"), "tmp": tmp}[kind]
    return os.path.join(folder, name)


class BadAndHardInputs(unittest.TestCase):
    def run_row(self, path, extra, tmp):
        args = [resolve(a, tmp) if a.startswith("tmp/") else a for a in extra]
        if "-o" not in args:
            args += ["-o", os.path.join(tmp, "out.inp")]
        report = os.path.join(tmp, "report.json")
        return subprocess.run([harness.args.hexlayer, "mesh", resolve(path, tmp), *args, "--report", report],
                              capture_output=True, text=True, timeout=SECONDS)

    def test_table(self):
        self.assertGreaterEqual(len(TABLE), 25)
        with tempfile.TemporaryDirectory() as tmp:
            open(os.path.join(tmp, "empty.step"), "w").close()
            os.mkdir(os.path.join(tmp, "folder.step"))
            for name, path, extra, code, fragment in TABLE:
                with self.subTest(name):
                    done = self.run_row(path, extra, tmp)
                    self.assertEqual(done.returncode, code, f"{name}: {done.stderr[-1500:]}")
                    self.assertIn(fragment, done.stdout if code == 0 else done.stderr)
                    if code == 0:
                        self.check_valid_mesh(os.path.join(tmp, "report.json"))
                    else:
                        self.assertIn("hexlayer: error: ", done.stderr)

    def check_valid_mesh(self, report_path):
        with open(report_path) as f:
            r = json.load(f)
        self.assertTrue(r["validation"]["passed"], r["validation"])
        self.assertEqual(r["inverted_hexes"], 0)
        self.assertLess(abs(r["volume"]["relative_error"]), 0.05)

    def test_a_mesh_failing_validation_is_written_only_when_forced(self):
        # Quads 8 x the wall across the hat section's bends and holes: the holes are lost, the volume is
        # far off the part's.
        with tempfile.TemporaryDirectory() as tmp:
            done = self.run_row("sample/hat_holes.step", ["--size", "12", "--sizing", "uniform"], tmp)
            self.assertEqual(done.returncode, 6, done.stderr[-2000:])
            # Quads this coarse (8 walls) also fold hexes at the rim once its columns are laid on the rim faces
            # (two columns onto one point of the hat's end face): the volume failure is one of several.
            self.assertRegex(done.stderr, r"hexlayer: error: the mesh failed validation, nothing written \(--force writes "
                                          r"it anyway\): (.*; )?volume: the mesh's [\d.]+ differs from the CAD's [\d.]+ by -[\d.]+ %")
            self.assertFalse(os.path.exists(os.path.join(tmp, "out.inp")))
            done = self.run_row("sample/hat_holes.step", ["--size", "12", "--sizing", "uniform", "--force"], tmp)
            self.assertEqual(done.returncode, 0, done.stderr[-2000:])
            self.assertTrue(os.path.exists(os.path.join(tmp, "out.inp")))
            with open(os.path.join(tmp, "report.json")) as f:
                validation = json.load(f)["validation"]
            self.assertFalse(validation["passed"])
            self.assertIn("volume", [f["check"] for f in validation["failures"]])

    def test_rib_junction_names_its_walls(self):
        """The faces the T-junction message names, read from the CAD with Gmsh, are the rib's two walls (inside
        its box, twice 60 x 12 mm^2), and the place it gives is their centre."""
        with tempfile.TemporaryDirectory() as tmp:
            step = resolve("data/t_junction.step", tmp)
            done = self.run_row("data/t_junction.step", ["--shell"], tmp)  # refused (issue 18: no shell yet)
        named = junctions_named(done.stderr)
        self.assertEqual(len(named), 1, done.stderr)
        at, faces = named[0]
        self.assertEqual(len(faces), 2)
        group = face_group(step, faces)
        self.assertAlmostEqual(group["area"], 2 * 60 * 12, places=6)
        self.assertLessEqual(group["diagonal"], math.dist(*RIB) + 1e-6)
        self.assertLess(math.dist(group["centre"], [(a + b) / 2 for a, b in zip(*RIB)]), 1e-6)
        self.assertLess(math.dist(at, group["centre"]), 1e-3)

    def test_memory_estimate_is_in_the_report(self):
        with tempfile.TemporaryDirectory() as tmp:
            done = self.run_row("data/plate.brep", [], tmp)
            self.assertEqual(done.returncode, 0, done.stderr)
            with open(os.path.join(tmp, "report.json")) as f:
                estimate = json.load(f)["memory_estimate"]
            self.assertAlmostEqual(estimate["quads"], 60 * 40 / 2.0 ** 2, delta=1)  # top wall area / size^2
            self.assertAlmostEqual(estimate["hexes"], 2 * estimate["quads"], delta=1)
            self.assertGreater(estimate["machine_bytes"], estimate["bytes"])

    def test_memory_estimate_counts_the_adaptive_quads(self):
        """With adaptive sizing down to a small --min-size the planned size under-counts the quads: the estimate in
        the report is made again from the quads made."""
        with tempfile.TemporaryDirectory() as tmp:
            # the holes' edges refine it: 1144 quads, where the wall's area over the size squared gives 950
            done = self.run_row("sample/plate_holes.step", ["--sizing", "adaptive", "--min-size", "0.3"], tmp)
            self.assertEqual(done.returncode, 0, done.stderr)
            with open(os.path.join(tmp, "report.json")) as f:
                report = json.load(f)
            estimate = report["memory_estimate"]
            self.assertEqual(estimate["quads"], report["quad_mesh"]["quads"])
            self.assertEqual(estimate["hexes"], report["hexes"])


if __name__ == "__main__":
    harness.main()
