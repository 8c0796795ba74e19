"""Open boxes bent round SHARP inside edges (Resources/samples/box_sharp*, made by scripts/make_samples.py): the walls
meet the floor and each other in sharp inside edges and corners, their outside edges rounded by less than the wall
(R1 = 0.5 x the wall, with eighth spheres at the bottom corners; R0.5 = 0.25 x) or sharp, a twin in metres (planes
as B-splines) and one with faces split. Each is one sheet bent with a zero inside radius: the outside rounds join
the walls (bend_rounds.hpp), no wall stands on another (no junction, no refusal).

Checked with 2 layers on the written .inp, not the mesher's report:
- every element an 8-node hex of positive volume, scaled Jacobian (at the corners, computed here) min >= 0.2 (the
  issue's bar) and mean >= MEAN_SJ;
- the mesh volume within 2 % of the CAD volume (the samples README's);
- a closed boundary (every boundary quad edge in exactly two boundary quads) whose Euler characteristic is the CAD
  surface's (Gmsh's triangulation: an open box is a disk's boundary, 2);
and from the report: one sheet (no junction), the part's topology, validation passed.

The quads are one structured grid per face between the bends (patch_grids.hpp: node rows along every crease,
graded towards them), where Gmsh's quads fanned round the bends (mean 0.84-0.87, the R0.5 box's folding at a
vertical round: refused); the wall nodes next to a sharp edge are put on it (sharp_edges.hpp). Measured 2026-12-05
(2 layers): box_sharp_inside 3 120 hexes, min 0.430 avg 0.951, volume -1.43 %; box_sharp 3 590, 0.307 / 0.942,
-0.02 % (its worst hex where a corner edge reaches the rim); box_sharp_inside_metres and _split alike;
box_sharp_inside_r025 5 432, 0.500 / 0.944, -0.60 %.

Run by CTest as: /usr/bin/python3 test_bent_boxes.py --hexlayer PATH --source DIR
"""
import collections
import json
import os
import subprocess
import sys
import tempfile
import unittest

import harness
from cad import surface_euler_characteristic, write_as_bsplines
from inp import hex_arrays, read_inp
from test_junction_samples import readme_table

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from hex_geometry import boundary_euler_characteristic, boundary_quads, hex_scaled_jacobians, hex_volumes  # noqa: E402

PARTS = ["box_sharp_inside", "box_sharp", "box_sharp_inside_metres", "box_sharp_inside_split", "box_sharp_inside_r025",
         "box_sharp_holes", "box_l_shape", "box_close_holes", "box_diagonal_holes"]
MIN_SJ, MEAN_SJ, VOLUME_TOL = 0.2, 0.93, 0.02
EULER_TRIANGLE_SIZE = 5.0  # mm; x 1e-3 for the part in metres


def samples():
    return os.path.join(harness.args.source, "Resources", "samples")


def readme_volumes():
    """{part: CAD volume} from the samples README's table (its last column)."""
    with open(os.path.join(samples(), "README.md"), encoding="utf-8") as fh:
        rows = [line.strip().strip("|").split("|") for line in fh if line.startswith("| `")]
    return {cells[0].strip().strip("`")[:-len(".step")]: float(cells[-1]) for cells in rows}


class BentBoxes(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.volumes = readme_volumes()

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def mesh(self, part, layers, *extra):
        return self.mesh_file(os.path.join(samples(), part + ".step"), layers, *extra)

    def mesh_file(self, step, layers, *extra):
        out = os.path.join(self.tmp.name, f"{os.path.splitext(os.path.basename(step))[0]}_{layers}")
        done = subprocess.run([harness.args.hexlayer, "mesh", step, "-o",
                               out + ".inp", "--report", out + ".json", "--layers", str(layers), "--quiet", *extra],
                              capture_output=True, text=True, timeout=600)
        self.assertEqual(done.returncode, 0, done.stderr[-2000:])
        with open(out + ".json", encoding="utf-8") as fh:
            return out + ".inp", json.load(fh)

    def check_closed(self, hexes):
        """Every edge of the boundary quads in exactly two of them."""
        quads = boundary_quads(hexes)
        uses = collections.Counter(tuple(sorted((q[k], q[(k + 1) % 4]))) for q in quads for k in range(4))
        self.assertEqual(set(uses.values()), {2}, "the boundary is not closed")

    def check_box(self, part, layers, volume, junctions, mean_sj=MEAN_SJ, min_sj=MIN_SJ, step=None, scale=None):
        """The written mesh and its report as the module's note says; `junctions` the kinds of the report's. The part
        is the sample's, or `step` (written at `scale`: its Euler characteristic measured at that scale)."""
        path, report = self.mesh_file(step, layers) if step else self.mesh(part, layers)
        nodes, elements, _ = read_inp(path)
        self.assertTrue(all(len(n) == 8 for _, n in elements), "8-node hexes only")
        x, hexes, _ = hex_arrays(nodes, elements)
        self.assertEqual(len(hexes) % layers, 0)
        self.assertGreater(hex_volumes(x, hexes).min(), 0, "a hex of zero or negative volume")
        sj = hex_scaled_jacobians(x, hexes)
        self.assertGreaterEqual(sj.min(), min_sj)
        self.assertGreaterEqual(sj.mean(), mean_sj)
        volume_error = hex_volumes(x, hexes).sum() / volume - 1
        self.assertLess(abs(volume_error), VOLUME_TOL)
        self.check_closed(hexes)
        if scale is None:
            scale = 1e-3 if part.endswith("_metres") else 1.0
        cad_euler = surface_euler_characteristic(step or os.path.join(samples(), part + ".step"),
                                                 EULER_TRIANGLE_SIZE * scale)
        self.assertEqual(boundary_euler_characteristic(hexes), cad_euler)
        self.assertEqual([j["kind"] for j in report["junctions"]], junctions)
        self.assertTrue(report["boundary"]["watertight"], report["boundary"])
        self.assertTrue(report["boundary"]["same_topology_as_cad"], report["boundary"])
        self.assertEqual(report["inverted_hexes"], 0)
        self.assertTrue(report["validation"]["passed"], report["validation"])
        print(f"{os.path.basename(step) if step else part} ({layers} layers): {len(hexes)} hexes, scaled Jacobian "
              f"min {sj.min():.3f} avg {sj.mean():.3f}, volume {100 * volume_error:+.3f} %, Euler characteristic "
              f"{cad_euler}, quads {report['quad_mesh'].get('layout', '?')}")
        return report

    def test_bent_boxes_mesh_as_one_sheet(self):
        for part in PARTS:
            with self.subTest(part=part):
                self.check_box(part, 2, self.volumes[part], [])

    def test_chamfered_outsides_are_bends(self):
        """box_chamfered (box_sharp's outside edges chamfered 1.5 x 1.5) and tray_chamfered (a molded cover's edge:
        floor 2, walls 3, corners R6, outside edge chamfered 3 x 3, inside 1 x 1): a chamfer meeting two walls in convex
        sharp edges, its rays landing on the bend's inside, is the outside of a bend (bend_rounds.hpp), so each part is
        one sheet. Refused before (exit 4: the walls stood on the floor as T junctions). Measured 2026-12-05 (the
        chamfers' edges captured, sweep/sharp_edges.hpp): box_chamfered 2 layers 4 528 hexes, min 0.354 avg 0.956,
        volume -0.45 % (patch grid); tray_chamfered 2 layers 2 868, min 0.509 avg 0.931, volume -0.18 % (patch grid
        grown from the faces' flat middles: grown in index order, a face seeded in a rounded corner cut a wall across
        and Gmsh's quads gave avg 0.864), held to the issue's avg 0.9."""
        for layers in (2, 3):
            with self.subTest(part="box_chamfered", layers=layers):
                report = self.check_box("box_chamfered", layers, self.volumes["box_chamfered"], [])
                self.assertEqual(report["quad_mesh"]["layout"], "patch-grid")
        with self.subTest(part="tray_chamfered"):
            report = self.check_box("tray_chamfered", 2, self.volumes["tray_chamfered"], [], mean_sj=0.9)
            self.assertEqual(report["quad_mesh"]["layout"], "patch-grid")

    def check_bspline_twins(self, part, volume, junctions, min_sj):
        """The part with every face a B-spline (as another CAD system may write it), as drawn and in metres, checked
        as the sample is (check_box) with scaled Jacobian min >= min_sj, and its quads the patch grid."""
        for name, scale in (("drawn", 1.0), ("metres", 1e-3)):
            with self.subTest(part=part, twin=name):
                step = os.path.join(self.tmp.name, f"{os.path.basename(part)}_{name}.step")
                write_as_bsplines(os.path.join(samples(), part + ".step"), step, scale)
                report = self.check_box(part, 2, volume * scale ** 3, junctions, min_sj=min_sj, step=step, scale=scale)
                self.assertEqual(report["quad_mesh"]["layout"], "patch-grid")

    def test_chamfered_tray_twins(self):
        """tray_chamfered as B-splines, as drawn and in metres: its bubbles lie elsewhere, and a chamfer's patch of the
        chordal surface ends in two short curves meeting at an angle at each end (six corners, no four-sided face:
        Gmsh's quads, avg 0.893 and 0.899). Such a face keeps the four corners that leave the gentlest turns inside its
        sides (quadmesh/patch_grids PatchSides::KinksInSides, the last layout before Gmsh's): the patch grid, measured
        2 616 hexes 0.506 / 0.943 and 2 748, 0.509 / 0.942."""
        self.check_bspline_twins("tray_chamfered", self.volumes["tray_chamfered"], [], 0.45)

    def test_a_lower_end_walls_twins(self):
        """junctions/box_end_wall_low as B-splines, as drawn and in metres: a ray from near the low end wall's outer
        face's corner that crossed into the long wall beside it made that wall a face across the end wall, so the
        strip above the end wall on that side was not found flush with the long wall's end, the face not split there,
        and the end wall no T: one sheet, min 0.276 avg 0.928. A face across a wall face now takes kAcrossShare of its
        crossing rays' area (geometry/mixed_faces): one T, measured 4 848 hexes 0.507 / 0.943 and 4 854, the same."""
        self.check_bspline_twins("junctions/box_end_wall_low", readme_table()["box_end_wall_low"][1], ["T"], 0.45)

    def test_a_tear_near_a_low_walls_rim_is_filled(self):
        """box_rounded_low (80 x 50 x 8, wall 2, corners R6, floor edges sharp): the tets across the floor's sharp
        inside edge dropped as outside leave a tear in a wall only three walls high, some of whose vertices lie within
        a wall of the rim. It was taken for the part's rim and the spike drops opened it into a notch (Gmsh's quads,
        2026-12-05: 3 224 hexes, min 0.300 avg 0.905, volume -1.98 %, a hole the part does not have); a loop at most
        half of whose vertices are near a lateral face is a tear and is filled. Measured 2026-12-05: 3 944 hexes, min
        0.501 avg 0.943, volume -0.14 % (patch grid)."""
        report = self.check_box("box_rounded_low", 2, self.volumes["box_rounded_low"], [])
        self.assertGreaterEqual(report["chordal_surface"]["rim"]["tears_filled"], 1)
        self.assertEqual(report["quad_mesh"]["layout"], "patch-grid")

    def test_a_lower_end_wall_butts_on_the_long_walls(self):
        """junctions/box_end_wall_low: box_sharp_inside_r025 with its end wall cut down to 10 of 20 between the long
        walls, which run on up flush with its outside. As one sheet mitred at every sharp inside edge the hexes folded
        where the end wall's top meets the long walls (no sweep column serves the mitre below and the long wall above);
        the end wall is now a wall standing on the long walls and the floor (butt_joints.hpp: one T, its foot a U along
        their rim). Measured 2026-12-04 (patch grid): 2 layers 5 168 hexes, min 0.513 avg 0.941, volume -0.54 %
        (Gmsh's quads before: 3 820, 0.481 / 0.881)."""
        volume = readme_table()["box_end_wall_low"][1]
        for layers in (2, 3):
            with self.subTest(layers=layers):
                report = self.check_box("junctions/box_end_wall_low", layers, volume, ["T"])
                self.assertGreaterEqual(report["junctions"][0]["scaled_jacobian"]["avg"], 0.8)

    def test_faces_with_holes_get_pockets_in_the_patch_grid(self):
        """box_sharp_holes (box_sharp_inside_r025 with a round hole and a window in its long walls and a hole in its
        floor): each face with a hole is one grid with a pocket of four blocks round it on the face's map onto the
        square, its sides' nodes those of the faces beside it. Gmsh's quads before (the patch grid needed four-sided
        faces without holes). Measured 2026-12-04: 2 layers 4 148 hexes, min 0.582 avg 0.938, volume -0.91 %."""
        _, report = self.mesh("box_sharp_holes", 2)
        self.assertEqual(report["quad_mesh"]["layout"], "patch-grid")

    def test_holes_whose_pockets_meet_share_the_faces_grid(self):
        """box_close_holes (two D6 holes 8 apart in the floor) and box_diagonal_holes (the same on a diagonal, 2.5
        apart): pockets a quad beyond each hole would meet, so the floor is the shared grid's with its sides' nodes
        given (its lines moved onto the holes' sides and the pockets' boxes). Gmsh's quads before (box_close_holes:
        3 776 hexes, min 0.214, avg 0.896, volume -2.11 %). Measured 2026-12-05: box_close_holes 3 548 hexes, min
        0.280 avg 0.948, -1.01 %; box_diagonal_holes 3 568, min 0.302, avg 0.947, -0.88 %."""
        for part in ("box_close_holes", "box_diagonal_holes"):
            with self.subTest(part=part):
                _, report = self.mesh(part, 2)
                self.assertEqual(report["quad_mesh"]["layout"], "patch-grid")

    def test_an_l_shaped_floor_is_cut_at_its_reflex_corner(self):
        """box_l_shape (an open box on an L-shaped floor, every edge sharp): the floor's six corners, one reflex, are
        two four-sided faces once cut from the reflex corner straight on to the wall across. Measured 2026-12-04: 2
        layers 5 020 hexes, min 0.208 avg 0.949, volume -0.95 % (Gmsh's quads before: 5 210, 0.382 / 0.882,
        -2.27 %, over the 2 % bar)."""
        _, report = self.mesh("box_l_shape", 2)
        self.assertEqual(report["quad_mesh"]["layout"], "patch-grid")

    def test_a_foot_with_flanges_standing_on_it(self):
        """box_foot (a U-channel's foot: flanges standing on a foot that runs on past them, holes in the foot and the
        web, the foot's far corners rounded R3): two T junctions; the main sheet (foot and web bent sharp, holes in
        both) meshed with its footprints. Measured 2026-12-07: 2 layers 1 818 hexes, min 0.380 avg 0.967, volume
        +0.02 % (2026-12-04: 1 822, 0.590 / 0.964, before the shared grid's pockets' sides moved onto their mean
        together: its worst hex now at the web's bend by a flange; before the patch grid took faces with holes: 1 972,
        0.449 / 0.967)."""
        report = self.check_box("box_foot", 2, self.volumes["box_foot"], ["T", "T"])
        for junction in report["junctions"]:
            self.assertGreaterEqual(junction["scaled_jacobian"]["avg"], 0.8)

    def test_quarter_wall_rounds_fill_the_tears_of_the_sharp_inside_corners(self):
        """R0.5 outside rounds (0.25 x the wall): tets spanning a sharp inside corner dropped as outside left a tear in
        its chordal surface, which the quads carried into the mesh as a hole (Euler characteristic 0 against 2) until
        tears were filled (chordal_rim.hpp); the rest is checked with the other boxes."""
        _, report = self.mesh("box_sharp_inside_r025", 2)
        self.assertGreaterEqual(report["chordal_surface"]["rim"]["tears_filled"], 1)
        self.assertEqual(report["quad_mesh"]["layout"], "patch-grid")


if __name__ == "__main__":
    harness.main()
