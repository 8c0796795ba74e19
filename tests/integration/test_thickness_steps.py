"""Thickness steps (Resources/samples/steps, made by scripts/make_samples.py): a wall going on thinner past a step in
one or both of its faces. A plate 3 thick going on 1.5 thick (steps of 0.75 in both faces, of 0.5 and 1.0, of 1.5 in
one face; the step oblique; the faces split; in metres), a groove across a plate, a round diaphragm 1 thick in a plate
3 thick, a band 1.5 thick round a tube 3 thick. The thin wall's faces meet the thick wall's rim face, which made them a
second sheet standing on a rim (refused, exit 4) unless one of them ran on flush with the thick wall's face
(geometry/sheet_junctions thicknessSteps: now one sheet; the sweep's hexes across the step slope over one row). Steps
in one face: a plate's short thin end, a pocket milled into a plate.

Each part with 2 and 3 layers, checked on the written .inp with tools of their own: every element an 8-node hex of
positive volume; the scaled Jacobian of every hex (min >= 0.5, avg >= 0.99); the mesh volume within 1.5 % of the CAD
volume Gmsh's OpenCASCADE computes (the thin part's volume: a mesh that ran the thick wall on over the step would be
8-33 % high); every boundary node within 1e-6 mm of the CAD face it is grouped on; the part's topology.

Run by CTest as: /usr/bin/python3 test_thickness_steps.py --hexlayer PATH --source DIR
"""
import os

import harness
from cad import opened, surface_euler_characteristic, write_placed
from sample_mesh import MeshTest, boundary_euler_characteristic, check_hexes, check_sample, mesh_step


def write_lipped_box(path, height, outer, scale, turn, size=(80, 60, 25), wall=2, chamfer=False):
    """Writes test_short_lips_round_a_box's part as STEP: an open box `size` (80 x 60 x 25), walls and floor `wall`
    thick, sharp edges, the walls' inner half (outer=False) or outer half (outer=True) cut away over the top `height`
    (the outer half's step chamfered 45 degrees if `chamfer`); scaled by `scale` and turned `turn` degrees about the
    axis (1, 2, 3)."""
    import gmsh
    (x, y, z), t, h = size, wall, wall / 2
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        occ = gmsh.model.occ
        box, _ = occ.cut([(3, occ.addBox(0, 0, 0, x, y, z))], [(3, occ.addBox(t, t, t, x - 2 * t, y - 2 * t, z))])
        if outer and chamfer:  # the ring's inside: the box's outline at the step's foot, the lip's h above it
            def outline(d, at):
                p = [occ.addPoint(px, py, at) for px, py in ((d, d), (x - d, d), (x - d, y - d), (d, y - d))]
                return occ.addCurveLoop([occ.addLine(p[i], p[(i + 1) % 4]) for i in range(4)])
            kept, _ = occ.fuse(occ.addThruSections([outline(0, z - height - h), outline(h, z - height)], makeRuled=True),
                               [(3, occ.addBox(h, h, z - height, x - 2 * h, y - 2 * h, height + 1))])
            ring, _ = occ.cut([(3, occ.addBox(-1, -1, z - height - h, x + 2, y + 2, height + h + 1))], kept)
        elif outer:  # a ring round the box's top outer half
            ring, _ = occ.cut([(3, occ.addBox(-1, -1, z - height, x + 2, y + 2, height + 1))],
                              [(3, occ.addBox(h, h, z - 1 - height, x - 2 * h, y - 2 * h, height + 3))])
        else:
            ring = [(3, occ.addBox(h, h, z - height, x - 2 * h, y - 2 * h, height + 1))]
        occ.cut(box, ring)
        write_placed(gmsh, path, scale, turn)
    finally:
        gmsh.finalize()

# Measured: the least minimum 0.53 (step_one_side: its 1.5 step over one row of 3 mm quads), averages 0.992-0.999;
# volumes -0.45 % (step_both_sides: the step's hexes slope) to +1.24 % (tube_band: its band two quads long).
# Steps in one face (step_one_side_short, pocket_one_side) were written with hexes inverted round a tear of the chordal
# surface beside the step's side (exit 6) until fillTears left the steps' sides out of the rims (pipeline
# thicknessStepSides): measured 0.48 / 0.991 and 0.37 / 0.993 (the short end, 2 and 3 layers), 0.80 / 0.997 (the
# pocket). The sample box_lip meshes too (0.29 / 0.953) but is not here: some of its rim nodes stay 0.07 mm off the
# lip's faces (their projection would spoil a hex).
PARTS = ["step_both_sides", "step_unequal", "step_one_side", "step_split", "step_metres", "step_oblique",
         "groove_both_sides", "diaphragm", "tube_band", "step_one_side_short", "pocket_one_side"]
QUALITY = {"step_one_side_short": (0.35, 0.99)}
LAYERS = (2, 3)


class ThicknessSteps(MeshTest):
    def check(self, part, layers):
        check_sample(self, "steps", part, layers, QUALITY.get(part, (0.5, 0.99)), 0.015, 2.0)

    def test_every_step(self):
        self.check_each(PARTS, LAYERS)

    def test_short_lips_round_a_box(self):
        """An open box 80 x 60 x 25, walls and floor 2, its walls 1 thick over the top 2 or 4 (a lid's lip, 1 or 2 walls
        high): the inner half of the wall kept (4 high; and turned 30 degrees about a skew axis), the outer half kept (2
        and 4 high; 2 high in metres). Each had a facet or two of its chordal surface missing a wall or two over
        the step, near the lip's rim face, which fillTears took for the part's own hole (the quads ran round it: exit
        6, 14 to 155 hexes inverted); now a loop with material all round it is a tear. The outer half kept 5 and 8 high
        (8 also in metres and turned): loops of missing facets over the step several walls long (5 high: the mesh
        written with a hole, its average 0.88) and a tear's fan repeating an edge of the surface (8 high: `one edge is
        incident to 4 triangles`, exit 4); now a loop up to 3 tear lengths round material is a tear, and its fan
        starts where it repeats no edge. The outer half 3, 6 and 10 high (3 in metres, 5 turned), and a box
        100 x 70 x 30, wall 2.5, its outer half 6 high, and the outer half 5 high with its step chamfered 45 degrees
        (in mm and metres): hexes inverted at the box's inside corners under the lip's top
        (exit 6), Gmsh's patches refused (exit 4) or its tries running for minutes; the wall's inner face, shared by the
        wall and the lip, had bubbles for the wall's thickness, twice as far apart as the lip's, and the tets spanning
        the inside corners between them were dropped as outside. Now a wall face thinner over a part is split where
        the thickness steps (mixed_faces.hpp findThinParts), each piece with bubbles for its own thickness. The outer
        half 2 high turned: `could not quad-mesh the chordal surface` (Gmsh: an edge in four triangles) where a quad's
        diagonal was an edge of a fold beside it; a quad is now split on its other diagonal there (chordalTriangles).
        2 layers: every hex positive, scaled Jacobian min >= 0.2 and avg >= 0.9, volume within 2 %, the part's
        topology."""
        BOX = ((80, 60, 25), 2)  # size and wall
        for name, height, outer, scale, turn, box in (
                ("lip_inner_4", 4, False, 1.0, 0, BOX), ("lip_outer_2", 2, True, 1.0, 0, BOX),
                ("lip_outer_4", 4, True, 1.0, 0, BOX), ("lip_outer_2_metres", 2, True, 1e-3, 0, BOX),
                ("lip_inner_4_turned", 4, False, 1.0, 30, BOX), ("lip_outer_5", 5, True, 1.0, 0, BOX),
                ("lip_outer_8", 8, True, 1.0, 0, BOX), ("lip_outer_8_metres", 8, True, 1e-3, 0, BOX),
                ("lip_outer_8_turned", 8, True, 1.0, 30, BOX), ("lip_outer_3", 3, True, 1.0, 0, BOX),
                ("lip_outer_3_metres", 3, True, 1e-3, 0, BOX), ("lip_outer_6", 6, True, 1.0, 0, BOX),
                ("lip_outer_10", 10, True, 1.0, 0, BOX), ("lip_outer_5_turned", 5, True, 1.0, 30, BOX),
                ("lip_outer_2_turned", 2, True, 1.0, 30, BOX),
                ("lip_outer_6_wall_2.5", 6, True, 1.0, 0, ((100, 70, 30), 2.5)),
                ("lip_outer_5_chamfered", 5, True, 1.0, 0, BOX + (True,)),
                ("lip_outer_5_chamfered_metres", 5, True, 1e-3, 0, BOX + (True,))):
            self.check_lipped_box(name, height, outer, scale, turn, box, (0.2, 0.9), 0.02)

    def test_a_small_lipped_box_is_a_patch_grid(self):
        """A box 50 x 50 x 15, walls and floor 1.5, the outer half of its walls kept over the top 3: the patch grid of
        its chordal surface had its floor's corners a quad off the box's (the wall's face, grown from a seed, reaching
        a quad into the floor at a corner where its normal cone ran out), its quads folded along the floor's bend and
        the grid was refused: Gmsh's quads, avg 0.903, volume -1.67 % (and the same at 1e-3 and 1e3). The faces' rims
        are now fitted to their normals where the grid as grown is refused (chordal_patches.hpp PatchRims): 0.47 /
        0.959, -0.53 %. Twins: turned 30 degrees, the step chamfered, a 50 x 40 box. 2 layers: scaled Jacobian min
        >= 0.4 and avg >= 0.95, volume within 1 %, the part's topology."""
        SMALL = ((50, 50, 15), 1.5)
        for name, scale, turn, box in (("small_lip", 1.0, 0, SMALL), ("small_lip_metres", 1e-3, 0, SMALL),
                                       ("small_lip_x1000", 1e3, 0, SMALL), ("small_lip_turned", 1.0, 30, SMALL),
                                       ("small_lip_chamfered", 1.0, 0, SMALL + (True,)),
                                       ("small_lip_50x40", 1.0, 0, ((50, 40, 15), 1.5))):
            self.check_lipped_box(name, 3, True, scale, turn, box, (0.4, 0.95), 0.01)

    def test_short_walls_under_a_lip(self):
        """A box 40 x 45 x 12, walls and floor 2.5, the outer half of its walls cut away over the top 3.9: the walls'
        outer faces under the ledge, 8.1 high (the wall 2.2 thicknesses above the floor), cross the wall on 0.47 of
        their area and were taken for rims; the walls' inner faces and the lip became a sheet standing on the floor:
        exit 4 (`no piece holds the sheet ... after the cut`). A flat face facing a wall face across the wall's
        thickness is now a wall (wall_sides.cpp shortWallFaces). Twins: in metres (B-spline faces), turned 30
        degrees, 60 long, the lip 3 high, a box 40 x 45 x 8 with walls 2 and a lip 2.6 high. 2 layers: every hex
        positive, scaled Jacobian min >= 0.4 and avg >= 0.88 (the default quad size, a wall, is coarse for a box five
        walls high: 0.892-0.914), volume within 2 %, the part's topology."""
        SHORT = ((40, 45, 12), 2.5)
        for name, height, scale, turn, box in (
                ("short_walls", 3.9, 1.0, 0, SHORT), ("short_walls_metres", 3.9, 1e-3, 0, SHORT),
                ("short_walls_turned", 3.9, 1.0, 30, SHORT), ("short_walls_60", 3.9, 1.0, 0, ((60, 45, 12), 2.5)),
                ("short_walls_lip_3", 3.0, 1.0, 0, SHORT), ("short_walls_8_high", 2.6, 1.0, 0, ((40, 45, 8), 2.0))):
            self.check_lipped_box(name, height, True, scale, turn, box, (0.4, 0.88), 0.02)

    def check_lipped_box(self, name, height, outer, scale, turn, box, quality, allowed):
        """write_lipped_box's part meshed with 2 layers: every hex positive, the scaled Jacobian's min and avg at least
        `quality`, the volume within `allowed`, the part's topology."""
        with self.subTest(part=name):
            step = os.path.join(self.tmp.name, name + ".step")
            write_lipped_box(step, height, outer, scale, turn, *box)
            x, hexes = mesh_step(step, 2, os.path.join(self.tmp.name, name + ".inp"))[:2]
            with opened(step) as gmsh:
                check_hexes(self, gmsh, x, hexes, quality, allowed, f"{name}, 2 layers")
            self.assertEqual(boundary_euler_characteristic(hexes), surface_euler_characteristic(step, 2 * scale),
                             "the part's topology")


if __name__ == "__main__":
    harness.main()
