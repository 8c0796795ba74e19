"""End-to-end on real public parts from ../shared/parts/real (licences in its SOURCES.md): the flat
Ender-3 X-motor bracket (a 3 mm plate with holes and slots) meshes into a valid layered hex mesh;
the bent ones (the LCD support L-bracket, the support-frame U-channel with sharp inside bends)
mesh without an inverted hex, so does the AnalysisSitus sheet-metal part (bent flanges with rounded
corners); the L-bracket's four bosses are T-junctions, refused unless --drop-junctions leaves them out.

Run by CTest as: /usr/bin/python3 test_real_parts.py --hexlayer PATH --source DIR
"""
import json
import os
import subprocess
import tempfile
import unittest

import harness



class RealParts(unittest.TestCase):
    def mesh(self, name, layers, *extra):
        part = os.path.join(harness.args.source, "..", "shared", "parts", "real", name)
        if not os.path.exists(part):
            self.fail(f"{part} is missing: the real parts live in shared/parts/real beside the repository")
        with tempfile.TemporaryDirectory() as tmp:
            report = os.path.join(tmp, "r.json")
            done = subprocess.run([harness.args.hexlayer, "mesh", part, "-o", os.path.join(tmp, "m.inp"), "--layers",
                                   str(layers), "--report", report, "--quiet", *extra],
                                  capture_output=True, text=True, timeout=600)
            self.assertEqual(done.returncode, 0, done.stderr[-2000:])
            with open(report) as f:
                r = json.load(f)
            for failure in r["validation"]["failures"]:  # --force writes the mesh and warns of each failure
                self.assertIn("hexlayer: warning: validation failed (written because of --force): " + failure["message"],
                              done.stderr)
            return r

    def assert_sound(self, r, thickness, sj_min, sj_avg, volume_error):
        """The wall found, no inverted hex, the quality bounds, the volume, and the part's closed boundary."""
        self.assertAlmostEqual(r["thickness"], thickness, delta=0.01)
        self.assertEqual(r["inverted_hexes"], 0)
        self.assertGreaterEqual(r["scaled_jacobian"]["min"], sj_min)
        self.assertGreaterEqual(r["scaled_jacobian"]["avg"], sj_avg)
        self.assertLess(abs(r["volume"]["relative_error"]), volume_error)
        self.assertTrue(r["boundary"]["watertight"], r["boundary"])
        self.assertTrue(r["boundary"]["same_topology_as_cad"], r["boundary"])

    def test_flat_motor_bracket(self):
        for layers in (2, 3):
            with self.subTest(layers=layers):
                r = self.mesh("ender3_x_motor_bracket_flatplate.step", layers)
                print(f"layers {layers}: {r['hexes']} hexes, SJ min {r['scaled_jacobian']['min']:.3f} "
                      f"avg {r['scaled_jacobian']['avg']:.3f}, volume error {r['volume']['relative_error']:+.4f}")
                self.assert_sound(r, thickness=3.0, sj_min=0.3, sj_avg=0.9, volume_error=0.03)
                self.assertEqual(r["hexes"] % layers, 0)
                self.assertTrue(r["validation"]["passed"], r["validation"])

    def test_lbracket_bosses_are_refused_as_junctions(self):
        part = os.path.join(harness.args.source, "..", "shared", "parts", "real", "ender3_lcd_support_Lbracket.step")
        with tempfile.TemporaryDirectory() as tmp:
            done = subprocess.run([harness.args.hexlayer, "mesh", part, "-o", os.path.join(tmp, "m.inp"), "--quiet"],
                                  capture_output=True, text=True, timeout=600)
        self.assertEqual(done.returncode, 4, done.stderr)
        self.assertIn("T-junction: 4 sheet(s)", done.stderr)
        self.assertIn("(85.4159, -101.243, 95.95) [Face7 Face8 Face38 Face39]", done.stderr)  # a boss, 7 mm tall
        self.assertIn("--drop-junctions", done.stderr)

    def test_bent_parts(self):
        # Measured 2026-11-24 (2 layers, adaptive sizing, the default): L-bracket without its bosses 6412
        # hexes, min 0.59, avg 0.990, the part's topology, a structured grid (block_grids); U-channel 19970
        # hexes, min 0.138, avg 0.868, meshed by Gmsh: the grid's pockets round its seven slots invert
        # quads, so it is not kept (uniform sizing: 10978 hexes, min 0.20, avg 0.900; adaptive refines the
        # bends, and every size transition costs irregular quads). The U-channel's CAD has two
        # tunnels of about 0.002 mm at the corners where the flanges meet (zero-radius inside bend
        # faces running through the bottom flange): Euler characteristic -14, the mesh's -10.
        # (name, thickness, Euler characteristic, extra options, SJ min and avg floors)
        cases = (("ender3_lcd_support_Lbracket.step", 2.0, -6, ("--drop-junctions",), 0.5, 0.95),
                 ("ender3_support_frame_Uchannel.step", 1.5, -10, (), 0.13, 0.86))
        for name, thickness, euler, extra, worst, mean in cases:
            with self.subTest(part=name):
                r = self.mesh(name, 2, *extra)
                error = r["volume"]["relative_error"]  # against the CAD volume without the junction sheets
                self.assertAlmostEqual(r["volume"]["junctions_left_out"], sum(j["volume"] for j in r["junctions"]))
                print(f"{name}: {r['hexes']} hexes, {r['inverted_hexes']} inverted, SJ min "
                      f"{r['scaled_jacobian']['min']:.3f} avg {r['scaled_jacobian']['avg']:.3f}, volume error "
                      f"{error:+.4f} without {len(r['junctions'])} junction sheets")
                self.assertAlmostEqual(r["thickness"], thickness, delta=0.01)
                self.assertEqual(r["inverted_hexes"], 0)
                self.assertGreaterEqual(r["scaled_jacobian"]["min"], worst)
                self.assertGreaterEqual(r["scaled_jacobian"]["avg"], mean)
                self.assertLess(abs(error), 0.02)
                self.assertTrue(r["boundary"]["watertight"], r["boundary"])
                self.assertEqual(r["boundary"]["euler_characteristic"], euler)
                self.assertEqual(r["quad_mesh"]["unpaired_triangles"], 0)
                self.assertTrue(r["validation"]["passed"], r["validation"])

    def test_sheet_metal_flanges_with_rounded_corners(self):
        # Measured 2026-11-23 (2 layers): 4768 hexes, 0 inverted, SJ min 0.726 avg 0.930, volume -0.21 %.
        # Before the rim slivers at the rounded corners were dropped (tets/isCoplanarTet): 280 inverted.
        r = self.mesh("analysissitus_sheet_metal_54_SHELLONLY.brep", 2)
        print(f"sheet_metal_54: {r['hexes']} hexes, {r['inverted_hexes']} inverted, SJ min "
              f"{r['scaled_jacobian']['min']:.3f} avg {r['scaled_jacobian']['avg']:.3f}, volume error "
              f"{r['volume']['relative_error']:+.4f}")
        self.assert_sound(r, thickness=1.2, sj_min=0.5, sj_avg=0.9, volume_error=0.01)
        self.assertEqual(r["quad_mesh"]["unpaired_triangles"], 0)


if __name__ == "__main__":
    harness.main()
