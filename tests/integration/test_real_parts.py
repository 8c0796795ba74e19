"""End-to-end on real public parts from ../shared/parts/real (licences in its SOURCES.md): the flat
Ender-3 X-motor bracket (a 3 mm plate with holes and slots) meshes into a valid layered hex mesh;
the bent ones (the LCD support L-bracket, the support-frame U-channel with sharp inside bends)
mesh without an inverted hex, so does the AnalysisSitus sheet-metal part (bent flanges with rounded
corners); the L-bracket's four bosses are junctions meshed with it by default (issue 18), or left out with
--drop-junctions.
Quality, volume and the boundary's topology are measured on the written .inp; the CAD's volume, topology and
the faces a junction message names are read with Gmsh (cad.py), not taken from hexlayer's report.

Run by CTest as: /usr/bin/python3 test_real_parts.py --hexlayer PATH --source DIR
"""
import json
import math
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

import harness
from cad import cad_volume, face_group, surface_euler_characteristic
from inp import hex_arrays, read_inp

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from hex_geometry import boundary_euler_characteristic, hex_scaled_jacobians, hex_volumes  # noqa: E402

# Gmsh's triangles on the CAD faces for its Euler characteristic: coarse (fast), and a size at which Gmsh
# triangulates both bent parts into a closed surface (at 5 mm it leaves 4 non-manifold edges on the L-bracket).
EULER_TRIANGLE_SIZE = 20.0


def real_part(name):
    return os.path.join(harness.args.source, "..", "shared", "parts", "real", name)


def measured(inp):
    """Scaled Jacobian of every hex, the mesh volume and its boundary's Euler characteristic, from the .inp
    alone."""
    x, hexes, _ = hex_arrays(*read_inp(inp)[:2])
    return hex_scaled_jacobians(x, hexes), hex_volumes(x, hexes).sum(), boundary_euler_characteristic(hexes)


class RealParts(unittest.TestCase):
    def mesh(self, name, layers, *extra, part=None):
        """Meshes the real part `name` (or the file `part`): (its report, its measures from the written .inp (see
        measured))."""
        part = part or real_part(name)
        if not os.path.exists(part):
            self.fail(f"{part} is missing: the real parts live in shared/parts/real beside the repository")
        with tempfile.TemporaryDirectory() as tmp:
            report = os.path.join(tmp, "r.json")
            done = subprocess.run([harness.args.hexlayer, "mesh", part, "-o", os.path.join(tmp, "m.inp"), "--layers",
                                   str(layers), "--report", report, "--quiet", *extra],
                                  capture_output=True, text=True, timeout=600)
            self.assertEqual(done.returncode, 0, done.stderr[-2000:])
            self.stderr = done.stderr
            with open(report) as f:
                r = json.load(f)
            for failure in r["validation"]["failures"]:  # --force writes the mesh and warns of each failure
                self.assertIn("hexlayer: warning: validation failed (written because of --force): " + failure["message"],
                              done.stderr)
            return r, measured(os.path.join(tmp, "m.inp"))

    def assert_sound(self, name, r, measures, thickness, sj_min, sj_avg, volume_error):
        """The wall found, no inverted hex, the quality bounds and the volume (measured on the .inp, against
        Gmsh's CAD volume), and a closed boundary with the part's topology (Euler characteristic as Gmsh's)."""
        sj, volume, euler = measures
        cad = cad_volume(real_part(name))
        self.assertAlmostEqual(r["thickness"], thickness, delta=0.01)
        self.assertGreater(sj.min(), 0, "no inverted hex")
        self.assertGreaterEqual(sj.min(), sj_min)
        self.assertGreaterEqual(sj.mean(), sj_avg)
        self.assertLess(abs(volume - cad) / cad, volume_error)
        self.assertTrue(r["boundary"]["watertight"], r["boundary"])
        self.assertEqual(euler, surface_euler_characteristic(real_part(name), EULER_TRIANGLE_SIZE))
        self.assertTrue(r["boundary"]["same_topology_as_cad"], r["boundary"])

    def test_flat_motor_bracket(self):
        for layers in (2, 3):
            with self.subTest(layers=layers):
                name = "ender3_x_motor_bracket_flatplate.step"
                r, measures = self.mesh(name, layers)
                print(f"layers {layers}: {r['hexes']} hexes, SJ min {r['scaled_jacobian']['min']:.3f} "
                      f"avg {r['scaled_jacobian']['avg']:.3f}, volume error {r['volume']['relative_error']:+.4f}")
                self.assert_sound(name, r, measures, thickness=3.0, sj_min=0.3, sj_avg=0.9, volume_error=0.03)
                self.assertEqual(r["hexes"] % layers, 0)
                self.assertTrue(r["validation"]["passed"], r["validation"])

    def test_lbracket_bosses_are_meshed_as_junctions(self):
        """Issue 18: the LCD support's four bosses (hollow standoffs on the bent plate's flat leg) are meshed with it
        by default, all hex: each a ring junction whose faces are a boss's, the part's topology and volume.
        Measured 2026-12-02 (session 29, the gap's poor quads split anew): 8 274 hexes, scaled Jacobian min 0.630 avg
        0.977, volume -0.22 %, the rings' hexes avg 0.94 (before: 7 968, 0.433 / 0.976)."""
        part = real_part("ender3_lcd_support_Lbracket.step")
        with tempfile.TemporaryDirectory() as tmp:
            report_path = os.path.join(tmp, "r.json")
            done = subprocess.run([harness.args.hexlayer, "mesh", part, "-o", os.path.join(tmp, "m.inp"), "--quiet",
                                   "--report", report_path], capture_output=True, text=True, timeout=600)
            self.assertEqual(done.returncode, 0, done.stderr)
            with open(report_path, encoding="utf-8") as fh:
                report = json.load(fh)
        self.assertEqual(report["inverted_hexes"], 0)
        self.assertGreaterEqual(report["scaled_jacobian"]["min"], 0.2)
        self.assertGreaterEqual(report["scaled_jacobian"]["avg"], 0.9)
        self.assertLess(abs(report["volume"]["relative_error"]), 0.02)
        self.assertTrue(report["boundary"]["same_topology_as_cad"])
        self.assertEqual(len(report["junctions"]), 4)
        for junction in report["junctions"]:
            with self.subTest(faces=junction["faces"]):
                self.assertTrue(junction["meshed"])
                self.assertEqual(junction["kind"], "ring")
                self.assertGreaterEqual(junction["scaled_jacobian"]["min"], 0.2)
                self.assertGreaterEqual(junction["scaled_jacobian"]["avg"], 0.8)
                self.assert_names_a_boss(part, junction["at"], [int(f[4:]) for f in junction["faces"]])

    def assert_names_a_boss(self, part, at, faces):
        """The faces a junction message names, read from the CAD with Gmsh, are a boss's (a small part of the
        part's surface, in a small box: the bosses are tubes 6 mm tall, 9 mm across, 0.7 % of the surface) and
        `at` is their area-weighted centre (printed to 6 digits; hexlayer averages samples of the faces)."""
        group = face_group(part, faces)
        self.assertLess(group["area"], 0.01 * group["part_area"])
        self.assertLess(group["diagonal"], 0.1 * group["part_diagonal"])
        self.assertLess(math.dist(at, group["centre"]), 0.01, f"{at} is not the centre {group['centre']} of {faces}")

    def test_another_unit_meshes_as_millimetres(self):
        """The real U-channel's STEP file with its length unit changed from millimetres to micrometres: OpenCASCADE
        reads a part 1000 times smaller, its planes and cylinders kept (what a part drawn in metres but read as
        millimetres is, the other way round). normalizingUnit scales it by 1000 back to the millimetre part's size
        (it scaled such parts to a diagonal of 100: the U-channel at 0.64 x, another packing; in metres with
        FreeCAD's Shape.scale that was refused with 3 inverted hexes). Measured: 11 088 hexes, SJ min 0.313, avg
        0.902, as in millimetres (11 088, 0.313, 0.902); lengths in the report in the file's unit."""
        name = "ender3_support_frame_Uchannel.step"
        with open(real_part(name), "rb") as f:
            text = f.read()
        self.assertIn(b"SI_UNIT ( .MILLI., .METRE. )", text)
        with tempfile.TemporaryDirectory() as tmp:
            micro = os.path.join(tmp, "uchannel_micrometres.step")
            with open(micro, "wb") as f:
                f.write(text.replace(b"SI_UNIT ( .MILLI., .METRE. )", b"SI_UNIT ( .MICRO., .METRE. )"))
            r, (sj, volume, euler) = self.mesh(name, 2, part=micro)
            mm, (sj_mm, _, euler_mm) = self.mesh(name, 2)
            cad = cad_volume(micro)
            self.assertAlmostEqual(cad / cad_volume(real_part(name)), 1e-9, delta=1e-12, msg="read 1000 x smaller")
            print(f"{name} in micrometres: {len(sj)} hexes, SJ min {sj.min():.3f} avg {sj.mean():.3f} "
                  f"(millimetres: {len(sj_mm)}, {sj_mm.min():.3f} / {sj_mm.mean():.3f})")
            self.assertAlmostEqual(r["thickness"], 1.5e-3, delta=1e-5)
            self.assertLess(abs(len(sj) - len(sj_mm)), 0.02 * len(sj_mm), "the millimetre part's quads")
            self.assertGreater(sj.min(), 0, "no inverted hex")
            self.assertGreaterEqual(sj.min(), 0.13)  # test_bent_parts' floors for the millimetre part
            self.assertGreaterEqual(sj.mean(), 0.86)
            self.assertLess(abs(volume - cad) / cad, 0.02)
            self.assertTrue(r["boundary"]["watertight"], r["boundary"])
            self.assertEqual(euler, euler_mm, "the millimetre mesh's topology (its two CAD tunnels closed)")
            self.assertTrue(r["validation"]["passed"], r["validation"])

    def test_bent_parts(self):
        # Measured 2026-11-24 (2 layers, adaptive sizing, the default): L-bracket without its bosses 6412
        # hexes, min 0.59, avg 0.990, the part's topology, a structured grid (block_grids); U-channel 19970
        # hexes, min 0.138, avg 0.868, meshed by Gmsh: the grid's pockets round its seven slots invert
        # quads, so it is not kept (uniform sizing: 10978 hexes, min 0.20, avg 0.900; adaptive refines the
        # bends, and every size transition costs irregular quads).
        # Quality, volume and the boundary's Euler characteristic are measured on the written .inp, the CAD's
        # volume and Euler characteristic by Gmsh (for the L-bracket, less the bosses' volume hexlayer estimates).
        # The U-channel's CAD has two tunnels of about 0.002 mm at the corners where the flanges meet (zero-radius
        # inside bend faces running through the bottom flange): its surface's Euler characteristic is -14, and
        # the mesh closes both tunnels (each adds 2): -10. The mesh has the CAD's topology on the L-bracket (-6).
        # The U-channel's quads are the best of all 36 Gmsh tries (the two faired levels fail on every split:
        # "wrong topology of boundary mesh"): 170 s on a busy 2-core machine (2026-12-02), beyond the quad stage's
        # default budget as first set (10 s + 1 s per 1000 quads; refused in 18 s with it; now 300 s + 1 s per 100
        # quads), so it is given 600 s here. Since 2026-12-03 a try whose patches failed (Gmsh's classification and
        # reparametrization at its angles) is not run again with only the recombination changed: on each faired level
        # 6 of the 12 tries are not run (same_patches_not_run, 15 in all), the same quads in 38 s instead of 55 s.
        # Since 2026-12-03 (session 35) a faired level stops after two angles have failed to make their patches
        # (given_up_on_faired_surfaces: 20, same_patches_not_run: 3): the same quads, 21 -> 18 s on a quiet machine.
        # Since session 36 a chordal surface with sliver facets (edges under 1 % of the median: its zero-radius bends
        # put bubbles in pairs; 573 here) is not faired, since fairing folds the facets round them: no try on the
        # faired levels, the same quads from the unfaired surface's two tries, 10 -> 5 s.
        # Since session 43 its quads are the patch grid (patch_grids.hpp: the web with its four holes and the foot
        # with two and a bend relief are faces with pockets round the holes, the flanges' bends end flat on the foot's
        # sides, the foot's rounded corners cut): 11 998 hexes, min 0.241 avg 0.942, volume -1.46 %, quads in 1.2 s
        # (Gmsh's: 11 088, 0.313 / 0.902, -0.59 %, 5-7 s); no Gmsh try runs.
        # (name, thickness, tunnels the mesh closes, extra options, SJ min and avg floors, tries not run at least)
        cases = (("ender3_lcd_support_Lbracket.step", 2.0, 0, ("--drop-junctions",), 0.5, 0.95, 0),
                 ("ender3_support_frame_Uchannel.step", 1.5, 2, ("--quad-budget", "600"), 0.13, 0.86, 0))
        for name, thickness, tunnels_closed, extra, worst, mean, not_run in cases:
            with self.subTest(part=name):
                r, (sj, volume, euler) = self.mesh(name, 2, *extra)
                self.assertAlmostEqual(r["volume"]["junctions_left_out"], sum(j["volume"] for j in r["junctions"]))
                cad = cad_volume(real_part(name)) - r["volume"]["junctions_left_out"]
                error = (volume - cad) / cad
                print(f"{name}: {len(sj)} hexes, SJ min {sj.min():.3f} avg {sj.mean():.3f}, volume error "
                      f"{error:+.4f} without {len(r['junctions'])} junction sheets, boundary Euler characteristic "
                      f"{euler}")
                self.assertAlmostEqual(r["thickness"], thickness, delta=0.01)
                self.assertGreater(sj.min(), 0, "no inverted hex")
                self.assertGreaterEqual(sj.min(), worst)
                self.assertGreaterEqual(sj.mean(), mean)
                self.assertLess(abs(error), 0.02)
                self.assertTrue(r["boundary"]["watertight"], r["boundary"])
                cad_euler = surface_euler_characteristic(real_part(name), EULER_TRIANGLE_SIZE)
                self.assertEqual(euler, cad_euler + 2 * tunnels_closed)
                self.assertEqual(r["boundary"]["euler_characteristic"], euler, "the report agrees")
                # the bend reliefs: one closed by the quads (a rim loop narrower than a quad), one already by the
                # chordal surface; the CLI says how many the mesh fills
                self.assertEqual(r["quad_mesh"]["pinholes_closed"], min(tunnels_closed, 1))
                if tunnels_closed:
                    self.assertIn(f"the mesh fills {tunnels_closed} hole(s) of the part", self.stderr)
                self.assertEqual(r["quad_mesh"]["unpaired_triangles"], 0)
                tries = r["quad_mesh"]["gmsh_tries"]
                self.assertGreaterEqual(tries["same_patches_not_run"] + tries["given_up_on_faired_surfaces"], not_run)
                if name.startswith("ender3_support_frame_Uchannel"):  # measured: 2 run (was 21, then 6)
                    self.assertLessEqual(tries["run"], 4, "a good try ends the tries: the quads may close a pinhole")
                    self.assertGreater(r["chordal_surface"]["sliver_edges"], 100, "the zero-radius bends' slivers")
                    self.assertEqual(r["chordal_surface"]["fairing_iterations"], 0, "not faired round slivers")
                    self.assertEqual(r["quad_mesh"]["layout"], "patch-grid")
                else:
                    self.assertEqual(r["chordal_surface"]["sliver_edges"], 0)
                self.assertTrue(r["validation"]["passed"], r["validation"])

    def test_power_holder_box_is_one_bent_sheet_and_a_butt_joint(self):
        """The Ender-3 power-holder box (open box 115 x 54 x 70, 2 mm walls meeting the floor and each other in sharp
        inside edges and 0.5 mm outside rounds: cylinders, tori, spheres at the corners) is one bent sheet (its rounds
        are bends, bend_rounds.hpp), not four walls standing on each other (it was refused as T-junctions, exit 4).
        Its lower end wall (x = -57.5...-55.5, 29 high) ends part way up the side walls, which run on to 70 flush with
        its outer face: since butt joints (butt_joints.hpp) it stands on the side walls and the floor, its foot a U
        along their rim: one T junction, meshed. The front wall has a window in a pad 2 mm proud (4 mm thick) whose
        edge, two R1 rounds, passes 0.7 mm from the window's corner; the rounds' middles face along the wall and are
        rim faces (mixed_faces), a wall node on one may go back onto the wall (smoothing.hpp): one hex there stayed flat
        (2026-12-04). Gmsh gave a node of a rounded top corner twice (a slit in the quads: the boundary's Euler
        characteristic -12 against -10); one node at one place since: 18 144 hexes, SJ min 0.296, average 0.903, valid.
        Its side walls' top corners are rounded R10 (45 degrees over six quads) and the pad's slots lie close to the
        window: the patch grid cuts such corners and gives the window and the slots a shared grid (2026-12-05),
        Gmsh's quads before (22 s). Measured: 15 970 hexes, SJ min 0.424, average 0.959, volume -0.62 %, 6.5 s,
        junction hexes 284 (min 0.56, average 0.95); valid, the part's topology."""
        r, (sj, volume, euler) = self.mesh("ender3_power_holder_box.step", 2)
        self.assertEqual(r["quad_mesh"]["layout"], "patch-grid")
        print(f"power-holder box: {r['hexes']} hexes, SJ min {sj.min():.3f} avg {sj.mean():.3f}, worst at "
              f"{r['worst_hex_at']}, quads {r['quad_mesh']['layout']}, junctions {r['junctions']}")
        self.assertTrue(r["validation"]["passed"], r["validation"])
        self.assertGreater(len(sj), 10000)
        self.assertGreaterEqual(sj.min(), 0.2)
        self.assertGreaterEqual(sj.mean(), 0.9)
        cad = cad_volume(real_part("ender3_power_holder_box.step"))
        self.assertLess(abs(volume / cad - 1), 0.015)
        self.assertEqual(euler, surface_euler_characteristic(real_part("ender3_power_holder_box.step"),
                                                             EULER_TRIANGLE_SIZE))
        self.assertEqual([(j["kind"], j["meshed"]) for j in r["junctions"]], [("T", True)])
        self.assertIn("Face26", r["junctions"][0]["faces"])  # the end wall's inside
        self.assertGreaterEqual(r["junctions"][0]["scaled_jacobian"]["avg"], 0.8)
        self.assertGreaterEqual(r["junctions"][0]["scaled_jacobian"]["min"], 0.3)

    def test_sheet_metal_flanges_with_rounded_corners(self):
        # Measured 2026-11-23 (2 layers): 4768 hexes, 0 inverted, SJ min 0.726 avg 0.930, volume -0.21 %.
        # Before the rim slivers at the rounded corners were dropped (tets/isCoplanarTet): 280 inverted.
        name = "analysissitus_sheet_metal_54_SHELLONLY.brep"
        r, measures = self.mesh(name, 2)
        print(f"sheet_metal_54: {r['hexes']} hexes, {r['inverted_hexes']} inverted, SJ min "
              f"{r['scaled_jacobian']['min']:.3f} avg {r['scaled_jacobian']['avg']:.3f}, volume error "
              f"{r['volume']['relative_error']:+.4f}")
        self.assert_sound(name, r, measures, thickness=1.2, sj_min=0.5, sj_avg=0.9, volume_error=0.01)
        self.assertEqual(r["quad_mesh"]["unpaired_triangles"], 0)


if __name__ == "__main__":
    harness.main()
