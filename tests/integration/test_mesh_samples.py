"""End-to-end: mesh the bundled sample sheets with the CLI and check the mesh a user gets. Quality and volume
are measured on the written .vtu (meshio; scaled Jacobian and hex volumes computed here) against the CAD volume
Gmsh's OpenCASCADE gives, not read from the mesher's report.

Run by CTest as: /usr/bin/python3 test_mesh_samples.py --hexlayer PATH --source DIR
"""
import json
import os
import subprocess
import sys
import tempfile
import unittest

import harness
from cad import cad_volume

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from hex_geometry import hex_scaled_jacobians, hex_volumes  # noqa: E402

FLAT_AND_BENT = ["plate", "plate_holes", "cantilever", "lbracket", "uchannel", "hat_holes"]
# What each part allows, measured on its .vtu (2 to 4 layers): the box-like plate and cantilever are bricks
# (scaled Jacobian 1, volume exact); holes and bends are cut by chords (a bend's arc by its quads' edges: the
# U-channel and hat lose 0.5-0.7 %), their worst hexes where a pocket meets a hole or a bend meets a rim.
# (min scaled Jacobian, average, largest |volume error|); measured at 2-4 layers (2026-12-01): plate with holes
# 0.946 / 0.992 / 0.06 %, L-bracket 0.912 / 0.992 / 0.47 %, U-channel 0.895 / 0.991 / 0.54 %, hat 0.880 / 0.988 /
# 0.71 %.
EXPECTED = {"plate": (0.999, 0.999, 1e-9), "cantilever": (0.999, 0.999, 1e-9), "plate_holes": (0.9, 0.985, 0.002),
            "lbracket": (0.88, 0.985, 0.006), "uchannel": (0.87, 0.985, 0.007), "hat_holes": (0.85, 0.982, 0.009)}


def measured(vtu):
    """Scaled Jacobian of every hex and the mesh volume, from the .vtu alone."""
    import meshio
    m = meshio.read(vtu)
    hexes = m.cells_dict["hexahedron"]
    return hex_scaled_jacobians(m.points, hexes), hex_volumes(m.points, hexes).sum()


def run_hexlayer(*args):
    return subprocess.run([harness.args.hexlayer, *args], capture_output=True, text=True, timeout=600)


class MeshSamples(unittest.TestCase):
    def mesh(self, part, out, *extra):
        step = os.path.join(harness.args.source, "Resources", "samples", part + ".step")
        report = out + ".json"
        done = run_hexlayer("mesh", step, "-o", out, "--report", report, "--quiet", *extra)
        self.assertEqual(done.returncode, 0, done.stderr[-2000:])
        with open(report) as f:
            return json.load(f)

    def test_quality_volume_and_watertight_boundary(self):
        with tempfile.TemporaryDirectory() as tmp:
            for part in FLAT_AND_BENT:
                for layers in (2, 3, 4):
                    with self.subTest(part=part, layers=layers):
                        vtu = os.path.join(tmp, f"{part}{layers}.vtu")
                        r = self.mesh(part, vtu, "--layers", str(layers))
                        self.assertEqual(r["layers"], layers)
                        self.assertEqual(r["hexes"] % layers, 0)
                        sj, volume = measured(vtu)
                        cad = cad_volume(os.path.join(harness.args.source, "Resources", "samples", part + ".step"))
                        lo_min, lo_avg, volume_error = EXPECTED[part]
                        self.assertGreaterEqual(sj.min(), lo_min)
                        self.assertGreaterEqual(sj.mean(), lo_avg)
                        self.assertLessEqual(abs(volume - cad) / cad, volume_error)
                        self.assertAlmostEqual(sj.min(), r["scaled_jacobian"]["min"], places=6)  # the report agrees
                        self.assertEqual(r["inverted_hexes"], 0)
                        self.assertTrue(r["boundary"]["watertight"])
                        self.assertTrue(r["boundary"]["same_topology_as_cad"], r["boundary"])
                        self.assertEqual(r["boundary"]["open_edges"], 0)
                        self.assertGreater(r["chordal_surface"]["triangles"] + r["chordal_surface"]["quads"], 0)
                        # The rim nodes are moved onto the lateral faces (a few stay, to keep a hex valid).
                        self.assertGreaterEqual(r["sweep"]["rim_nodes_on_lateral_faces"], 0.9 * r["sweep"]["rim_nodes"])
                        # Every boundary node on its CAD face (measured 2026-11-24: at most 4e-13 mm).
                        self.assertLessEqual(r["boundary_deviation"]["max"], 1e-6)
                        self.assertEqual(sum(r["boundary_deviation"]["off_face_tolerance"].values()), 0)
                        self.assertEqual(r["surface_groups"]["meshed_cad_faces"], r["surface_groups"]["cad_faces"])

    def test_vtu_reads_back_through_meshio(self):
        import meshio
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "plate_holes.vtu")
            r = self.mesh("plate_holes", out)
            m = meshio.read(out)
            self.assertEqual(len(m.points), r["nodes"])
            self.assertEqual([c.type for c in m.cells], ["hexahedron"])
            self.assertEqual(len(m.cells[0].data), r["hexes"])

    def test_msh_reads_back_through_gmsh(self):
        import gmsh
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "lbracket.msh")
            r = self.mesh("lbracket", out)
            gmsh.initialize()
            try:
                gmsh.option.setNumber("General.Terminal", 0)
                gmsh.open(out)
                tags, _, _ = gmsh.model.mesh.getNodes()
                self.assertEqual(len(tags), r["nodes"])
                hexes, _ = gmsh.model.mesh.getElementsByType(5)
                self.assertEqual(len(hexes), r["hexes"])
                names = {gmsh.model.getPhysicalName(d, t) for d, t in gmsh.model.getPhysicalGroups()}
                self.assertTrue({"top", "bottom", "rim", "solid"} <= names, names)
            finally:
                gmsh.finalize()

    def test_not_thin_part_is_refused_with_exit_4(self):
        with tempfile.TemporaryDirectory() as tmp:
            step = os.path.join(harness.args.source, "Resources", "samples", "thick_block.step")
            done = run_hexlayer("mesh", step, "-o", os.path.join(tmp, "x.inp"))
            self.assertEqual(done.returncode, 4)
            self.assertIn("not a thin section", done.stderr)

    def test_adaptive_sizing_on_the_hat_section(self):
        # Measured 2026-11-24: adaptive (the default) 8682 hexes, SJ min 0.64, avg 0.922, volume -0.71 %;
        # uniform 8110 hexes.
        with tempfile.TemporaryDirectory() as tmp:
            uniform = self.mesh("hat_holes", os.path.join(tmp, "u.vtu"), "--sizing", "uniform")
            r = self.mesh("hat_holes", os.path.join(tmp, "a.vtu"))
            self.assertEqual(uniform["sizing"], "uniform")
            self.assertEqual(r["sizing"], "adaptive")
            self.assertGreater(r["hexes"], uniform["hexes"], "the bends and the hole rims are refined")
            self.assertGreaterEqual(r["scaled_jacobian"]["avg"], 0.9)
            self.assertGreaterEqual(r["scaled_jacobian"]["min"], 0.5)
            self.assertLess(abs(r["volume"]["relative_error"]), 0.01)
            self.assertTrue(r["boundary"]["same_topology_as_cad"], r["boundary"])

    def test_adaptive_quads_follow_the_wall_thickness(self):
        # The wedge plate thickens from 1 to 4 mm along x. It is one structured patch: across it as many
        # rows as its 1 mm end needs (40 of 1 mm), along it as many columns as the sizing integrates to
        # over its length (39, evenly spaced). Measured 2026-11-24: 3116 hexes, SJ min 0.88 avg 0.989;
        # uniform sizing (2.46 mm, the median wall) about 1000 hexes.
        with tempfile.TemporaryDirectory() as tmp:
            r = self.mesh("wedge_plate", os.path.join(tmp, "w.vtu"))
            u = self.mesh("wedge_plate", os.path.join(tmp, "u.vtu"), "--sizing", "uniform")
            self.assertEqual(r["quad_mesh"]["structured_patches"], 1)
            self.assertGreater(r["hexes"], 1.5 * u["hexes"], "the 1 mm end needs quads of about 1 mm")
            self.assertGreaterEqual(r["scaled_jacobian"]["avg"], 0.95)

    def test_aspect_sets_the_size_from_the_layer_thickness(self):
        # Measured 2026-11-24 (2 layers, structured grids): on the plate and on the curved cylinder shell
        # --aspect 1 and --aspect 5 both hit within 10 % on every hex (the issue asks 80 %). Pockets and
        # O-grids vary the quad size: the plate with holes 85 % and 36 %, the cap 15 % and 0 %.
        with tempfile.TemporaryDirectory() as tmp:
            for part in ("plate", "cylinder_shell"):
                for aspect in (1, 5):
                    with self.subTest(part=part, aspect=aspect):
                        r = self.mesh(part, os.path.join(tmp, f"{part}{aspect}.vtu"), "--aspect", str(aspect))
                        self.assertAlmostEqual(r["size"], aspect * r["thickness"] / 2, places=9)
                        self.assertGreaterEqual(r["aspect_ratio_hit"], 0.8)
                        self.assertGreaterEqual(r["scaled_jacobian"]["min"], 0.3)

    def test_bad_usage_and_missing_file(self):
        with tempfile.TemporaryDirectory() as tmp:
            step = os.path.join(harness.args.source, "Resources", "samples", "plate.step")
            self.assertEqual(run_hexlayer("mesh", step, "-o", os.path.join(tmp, "x.inp"), "--layers", "0").returncode, 2)
            self.assertEqual(run_hexlayer("mesh", step, "-o", os.path.join(tmp, "x.stl")).returncode, 2)
            for bad in (("--sizing", "graded"), ("--size", "2", "--aspect", "3"), ("--aspect", "-1"),
                        ("--min-size", "3", "--max-size", "1")):
                with self.subTest(options=bad):
                    self.assertEqual(run_hexlayer("mesh", step, "-o", os.path.join(tmp, "x.inp"), *bad).returncode, 2)
            missing = run_hexlayer("mesh", os.path.join(tmp, "none.step"), "-o", os.path.join(tmp, "x.inp"))
            self.assertEqual(missing.returncode, 3)
            self.assertIn("does not exist", missing.stderr)


if __name__ == "__main__":
    harness.main()
