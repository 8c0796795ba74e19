"""End-to-end on real public parts from ../shared/parts/real (licences in its SOURCES.md): the flat
Ender-3 X-motor bracket (a 3 mm plate with holes and slots) meshes into a valid layered hex mesh;
the bent ones (the LCD support L-bracket, the support-frame U-channel with sharp inside bends)
mesh, with a small share of inverted hexes at their inside corners that is not solved yet.

Run by CTest as: /usr/bin/python3 test_real_parts.py --hexlayer PATH --source DIR
"""
import json
import os
import subprocess
import tempfile
import unittest

import harness



class RealParts(unittest.TestCase):
    def mesh(self, name, layers, force=False):
        part = os.path.join(harness.args.source, "..", "shared", "parts", "real", name)
        if not os.path.exists(part):
            self.fail(f"{part} is missing: the real parts live in shared/parts/real beside the repository")
        with tempfile.TemporaryDirectory() as tmp:
            report = os.path.join(tmp, "r.json")
            done = subprocess.run([harness.args.hexlayer, "mesh", part, "-o", os.path.join(tmp, "m.inp"), "--layers",
                                   str(layers), "--report", report, "--quiet", *(["--force"] if force else [])],
                                  capture_output=True, text=True, timeout=600)
            self.assertEqual(done.returncode, 0, done.stderr[-2000:])
            with open(report) as f:
                r = json.load(f)
            for failure in r["validation"]["failures"]:  # --force writes the mesh and warns of each failure
                self.assertIn("hexlayer: warning: validation failed (written because of --force): " + failure["message"],
                              done.stderr)
            return r

    def test_flat_motor_bracket(self):
        for layers in (2, 3):
            with self.subTest(layers=layers):
                r = self.mesh("ender3_x_motor_bracket_flatplate.step", layers)
                print(f"layers {layers}: {r['hexes']} hexes, SJ min {r['scaled_jacobian']['min']:.3f} "
                      f"avg {r['scaled_jacobian']['avg']:.3f}, volume error {r['volume']['relative_error']:+.4f}")
                self.assertAlmostEqual(r["thickness"], 3.0, delta=0.01)
                self.assertEqual(r["inverted_hexes"], 0)
                self.assertGreaterEqual(r["scaled_jacobian"]["avg"], 0.9)
                self.assertGreaterEqual(r["scaled_jacobian"]["min"], 0.3)
                self.assertLess(abs(r["volume"]["relative_error"]), 0.03)
                self.assertTrue(r["boundary"]["watertight"])
                self.assertTrue(r["boundary"]["same_topology_as_cad"], r["boundary"])
                self.assertEqual(r["hexes"] % layers, 0)
                self.assertTrue(r["validation"]["passed"], r["validation"])

    def test_bent_parts(self):
        # Measured 2026-11-23: L-bracket 9444 hexes, 22 inverted, avg 0.898; U-channel 12582 hexes,
        # 5 inverted, avg 0.870. The bounds below catch a step back, not the goal (no inverted hex).
        # Not asserted, as not solved: both meshes have cracks where the part has none (boundary
        # Euler characteristic -30 vs the part's -6, and -45 vs -14): at sharp bends, two top and two
        # bottom bubbles on the parallel bend edges are coplanar, their flat tet is dropped and its
        # collinear chordal quad leaves a slit. A few pinch points (the rim touching itself at one
        # vertex) give up to 4 non-manifold boundary edges.
        # Their inverted hexes fail the validation: without --force nothing is written (exit 6, see
        # test_bent_part_without_force_is_refused); with it the mesh is written and the failure reported.
        for name, thickness in (("ender3_lcd_support_Lbracket.step", 2.0), ("ender3_support_frame_Uchannel.step", 1.5)):
            with self.subTest(part=name):
                r = self.mesh(name, 2, force=True)
                self.assertFalse(r["validation"]["passed"])
                inverted = [f for f in r["validation"]["failures"] if f["check"] == "inverted"]
                self.assertEqual(len(inverted), 1, r["validation"])
                self.assertEqual(inverted[0]["count"], r["inverted_hexes"])
                self.assertEqual(inverted[0]["at"], r["worst_hex_at"])
                print(f"{name}: {r['hexes']} hexes, {r['inverted_hexes']} inverted, SJ avg "
                      f"{r['scaled_jacobian']['avg']:.3f}, volume error {r['volume']['relative_error']:+.4f}")
                self.assertAlmostEqual(r["thickness"], thickness, delta=0.01)
                self.assertLess(r["inverted_hexes"], 0.01 * r["hexes"])
                self.assertGreaterEqual(r["scaled_jacobian"]["avg"], 0.85)
                self.assertLess(abs(r["volume"]["relative_error"]), 0.03)
                self.assertEqual(r["boundary"]["open_edges"], 0)
                self.assertLessEqual(r["boundary"]["non_manifold_edges"], 4)

    def test_bent_part_without_force_is_refused(self):
        part = os.path.join(harness.args.source, "..", "shared", "parts", "real", "ender3_lcd_support_Lbracket.step")
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "m.inp")
            done = subprocess.run([harness.args.hexlayer, "mesh", part, "-o", out, "--quiet"],
                                  capture_output=True, text=True, timeout=600)
            self.assertEqual(done.returncode, 6, done.stderr[-2000:])
            self.assertRegex(done.stderr, r"hexlayer: error: the mesh failed validation, nothing written \(--force writes "
                                          r"it anyway\): inverted: \d+ inverted hexes \(scaled Jacobian <= 0\), the worst "
                                          r"at \(-?[\d.]+, -?[\d.]+, -?[\d.]+\)")
            self.assertFalse(os.path.exists(out))


if __name__ == "__main__":
    harness.main()
