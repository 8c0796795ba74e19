"""The Python module pyhexlayer: arrays, report, node sets, errors as exceptions, progress callback.

Run by CTest as: /usr/bin/python3 test_binding.py --hexlayer PATH --source DIR
with PYTHONPATH holding the built module and tests/integration (for harness).
"""
import os
import subprocess
import tempfile
import threading
import unittest

import numpy as np

import harness
import pyhexlayer
from hex_geometry import hex_volumes

PLATE_VOLUME = 60.0 * 40.0 * 2.0  # Resources/samples/plate.step: 60 x 40 x 2 mm


PLATE_AREA = 60.0 * 40.0  # its mid-surface


def facet_area(vertices, facets):
    """Area of -1 padded triangles and quads (each quad as the triangles 0-1-2 and 0-2-3)."""
    def area(a, b, c):
        return 0.5 * np.linalg.norm(np.cross(vertices[b] - vertices[a], vertices[c] - vertices[a]), axis=1).sum()
    quads = facets[facets[:, 3] >= 0]
    return area(facets[:, 0], facets[:, 1], facets[:, 2]) + area(quads[:, 0], quads[:, 2], quads[:, 3])


def sample(name):
    return os.path.join(harness.args.source, "Resources", "samples", name)


def brep_of(step):
    """The part as OpenCASCADE BREP text, written by Gmsh's OpenCASCADE kernel."""
    import gmsh
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "part.brep")
        gmsh.initialize()
        try:
            gmsh.option.setNumber("General.Terminal", 0)
            gmsh.open(step)
            gmsh.write(path)
        finally:
            gmsh.finalize()
        with open(path) as f:
            return f.read()


def cli_error(*arguments):
    """Exit code and error message of the CLI on the same input."""
    with tempfile.TemporaryDirectory() as tmp:
        done = subprocess.run([harness.args.hexlayer, "mesh", *arguments, "-o", os.path.join(tmp, "m.inp"), "--quiet"],
                              capture_output=True, text=True, timeout=600)
    return done.returncode, done.stderr.strip().removeprefix("hexlayer: error: ")


class PlateMesh(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.lines = []
        cls.result = pyhexlayer.mesh_file(sample("plate.step"), layers=2, progress=cls.lines.append)

    def test_arrays_match_the_report(self):
        r = self.result
        self.assertGreater(len(r.hexes), 0)
        self.assertEqual(r.hexes.shape, (r.report["hexes"], 8))
        self.assertEqual(r.nodes.shape, (r.report["nodes"], 3))
        self.assertEqual(r.nodes.dtype, np.float64)
        self.assertTrue(np.issubdtype(r.hexes.dtype, np.integer))
        self.assertGreaterEqual(r.hexes.min(), 0)
        self.assertLess(r.hexes.max(), len(r.nodes))
        self.assertEqual(len(np.unique(r.hexes)), len(r.nodes), "every node belongs to a hex")

    def test_quality_and_volume(self):
        r = self.result
        self.assertEqual(r.scaled_jacobian.shape, (len(r.hexes),))
        self.assertGreaterEqual(r.scaled_jacobian.min(), 0.999, "a box's hexes are bricks")
        self.assertAlmostEqual(r.scaled_jacobian.min(), r.report["scaled_jacobian"]["min"], places=12)
        volumes = hex_volumes(r.nodes, r.hexes)
        self.assertGreater(volumes.min(), 0, "node order gives positive volumes")
        self.assertLess(abs(volumes.sum() - PLATE_VOLUME) / PLATE_VOLUME, 1e-9, "planar faces: the volume is exact")

    def test_node_sets_lie_on_the_plate_faces(self):
        sets, z = self.result.node_sets, self.result.nodes[:, 2]
        self.assertEqual(sorted(sets), ["BOTTOM", "RIM", "TOP"])
        top, bottom = z[sets["TOP"]], z[sets["BOTTOM"]]
        self.assertAlmostEqual(np.ptp(top), 0.0, places=6)
        self.assertAlmostEqual(np.ptp(bottom), 0.0, places=6)
        self.assertAlmostEqual(abs(top[0] - bottom[0]), 2.0, places=6)
        self.assertGreater(len(sets["RIM"]), 0)
        self.assertTrue(np.all(np.isin(self.result.hexes[:, 4:], sets["BOTTOM"], invert=True)),
                        "corners 4-7 are above the bottom layer")

    def test_face_groups_are_the_six_plate_faces(self):
        r = self.result
        self.assertEqual(sorted(r.face_nodes), ["Face{}".format(i) for i in range(1, 7)])
        self.assertEqual(sorted(r.face_elements), sorted(r.face_nodes))
        planes = set()
        hex_faces = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
        for name, nodes in r.face_nodes.items():
            xyz = r.nodes[nodes]
            axis = int(np.argmin(np.ptp(xyz, axis=0)))
            self.assertEqual(np.ptp(xyz[:, axis]), 0.0, name + " lies on a plane x, y or z = const")
            planes.add((axis, round(float(xyz[0, axis]), 9)))
            faces = r.face_elements[name]
            self.assertEqual(faces.shape[1], 2)
            self.assertGreater(len(faces), 0)
            corners = {int(r.hexes[h, c]) for h, f in faces for c in hex_faces[f]}
            self.assertTrue(corners <= set(nodes.tolist()), name + ": its element faces' corners are its nodes")
        self.assertEqual(planes, {(0, 0.0), (0, 60.0), (1, 0.0), (1, 40.0), (2, 0.0), (2, 2.0)})
        self.assertEqual(sum(len(f) for f in r.face_elements.values()), r.report["boundary"]["faces"])

    def test_stages_are_handed_out(self):
        r = self.result
        self.assertEqual(r.chordal_facets.shape, (r.report["chordal_surface"]["triangles"] + r.report["chordal_surface"]["quads"], 4))
        self.assertEqual(r.quads.shape, (r.report["quad_mesh"]["quads"], 4))
        self.assertEqual(r.quad_nodes.shape, (r.report["quad_mesh"]["nodes"], 3))
        self.assertEqual(len(r.hexes), 2 * len(r.quads), "one hex per quad and layer")
        self.assertLess(abs(facet_area(r.chordal_vertices, r.chordal_facets) - PLATE_AREA) / PLATE_AREA, 0.02)
        self.assertLess(abs(facet_area(r.quad_nodes, r.quads) - PLATE_AREA) / PLATE_AREA, 0.02)
        self.assertLess(np.abs(r.quad_nodes[:, 2] - 1.0).max(), 0.05, "the quads lie on the mid-surface z = 1")

    def test_node_layer_counts_up_from_the_bottom(self):
        r = self.result
        self.assertEqual(r.node_layer.shape, (len(r.nodes),))
        self.assertEqual(set(r.node_layer[r.node_sets["BOTTOM"]].tolist()), {0})
        self.assertEqual(set(r.node_layer[r.node_sets["TOP"]].tolist()), {2})
        np.testing.assert_array_equal(r.node_layer[r.hexes[:, 4:]], r.node_layer[r.hexes[:, :4]] + 1)
        self.assertAlmostEqual(np.abs(r.nodes[:, 2] - r.node_layer).max(), 0.0, places=6, msg="layer k at z = k mm")

    def test_progress_once_per_stage(self):
        stages = [line.split(":")[0] for line in self.lines]
        self.assertCountEqual(stages, self.result.report["timings_s"])  # the report sorts its keys

    def test_peak_memory_per_stage_is_a_high_water_mark(self):
        stages = [line.split(":")[0] for line in self.lines]  # in the order they ran
        memory = self.result.report["peak_memory_mib"]
        self.assertCountEqual(stages, memory)
        peaks = [memory[s] for s in stages]
        self.assertGreater(peaks[0], 10, "a process with OpenCASCADE loaded holds more than 10 MiB")
        self.assertEqual(peaks, sorted(peaks), "the peak so far never falls")


def two_plates(**options):
    """The 60 x 40 x 2 plate and a 30 x 40 x 2 plate 10 above it, two solids of one BREP file, meshed."""
    import gmsh
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.occ.addBox(0, 0, 0, 60, 40, 2)
        gmsh.model.occ.addBox(0, 0, 10, 30, 40, 2)
        gmsh.model.occ.synchronize()
        with tempfile.TemporaryDirectory() as tmp:
            gmsh.write(os.path.join(tmp, "two.brep"))
            return pyhexlayer.mesh_file(os.path.join(tmp, "two.brep"), layers=2, **options)
    finally:
        gmsh.finalize()


class TwoSolids(unittest.TestCase):
    def test_stages_of_each_solid_follow_each_other(self):
        both = two_plates()
        solids = both.report["solids"]
        self.assertEqual(len(both.quads), sum(s["quad_mesh"]["quads"] for s in solids))
        self.assertEqual(len(both.quad_nodes), sum(s["quad_mesh"]["nodes"] for s in solids))
        self.assertEqual(len(both.chordal_vertices), sum(s["chordal_surface"]["vertices"] for s in solids))
        self.assertEqual(len(np.unique(both.quads)), len(both.quad_nodes), "the second solid's quads use its own nodes")
        self.assertEqual(len(np.unique(both.chordal_facets[both.chordal_facets >= 0])), len(both.chordal_vertices))
        self.assertLess(abs(facet_area(both.quad_nodes, both.quads) - 1.5 * PLATE_AREA) / PLATE_AREA, 0.03)
        self.assertEqual(len(both.node_layer), len(both.nodes))

    def test_shells_of_two_solids_are_one_with_faces_numbered_on(self):
        both = two_plates(shell=True)
        self.assertEqual(len(both.shell_elements), len(both.quads))
        self.assertEqual(len(np.unique(both.shell_elements)), len(both.shell_nodes), "each solid's own nodes")
        self.assertEqual(sorted(both.shell_node_sets), sorted(["RIM"] + ["Face{}".format(k) for k in range(1, 13)]))
        top = both.shell_nodes[both.shell_node_sets["Face12"]]  # the second box's top, z = 12
        self.assertTrue(np.allclose(top[:, 2], 11.0), "the second solid's faces numbered after the first's")
        self.assertAlmostEqual(both.report["shell"]["area"]["shell"], 1.5 * PLATE_AREA, delta=1e-6 * PLATE_AREA)


class ShellPlate(unittest.TestCase):
    """shell=True: the mid-surface shell of the 60 x 40 x 2 plate (issue 20), S8R with order=2."""

    @classmethod
    def setUpClass(cls):
        cls.result = pyhexlayer.mesh_file(sample("plate.step"), order=2, shell=True)

    def test_quad8_elements_on_the_mid_plane_with_the_wall_thickness(self):
        r = self.result
        self.assertEqual(r.shell_elements.shape, (len(r.quads), 8))
        self.assertEqual(r.shell_elements.max() + 1, len(r.shell_nodes))
        self.assertTrue(np.allclose(r.shell_nodes[:, 2], 1.0))
        self.assertTrue(np.allclose(r.shell_thickness, 2.0))
        s = r.report["shell"]
        self.assertEqual((s["element_type"], s["elements"], s["nodes"]), ("S8R", len(r.quads), len(r.shell_nodes)))
        self.assertAlmostEqual(s["area"]["shell"], PLATE_AREA, delta=1e-6 * PLATE_AREA)

    def test_node_sets_per_face_and_rim(self):
        sets = self.result.shell_node_sets
        self.assertEqual(sorted(sets), sorted(["RIM"] + ["Face{}".format(k) for k in range(1, 7)]))
        x = self.result.shell_nodes[:, 0]
        self.assertTrue(np.array_equal(sets["Face1"], np.flatnonzero(np.abs(x) < 1e-9)), "the rim face at x = 0")
        self.assertGreater(len(sets["Face1"]), 4)
        walls = [k for k in range(1, 7) if len(sets["Face{}".format(k)]) == len(self.result.shell_nodes)]
        self.assertEqual(len(walls), 2, "every sweep line ends on the two walls")

    def test_without_shell_there_is_none(self):
        r = pyhexlayer.mesh_file(sample("plate.step"))
        self.assertEqual(r.shell_elements.shape[0], 0)
        self.assertNotIn("shell", r.report)


class QuadraticPlateMesh(unittest.TestCase):
    """order=2: 20-node hexes, the 8 corners then the 12 mid-edge nodes in C3D20 order (types.hpp kHexEdges)."""
    EDGES = np.array([(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4), (0, 4), (1, 5), (2, 6), (3, 7)])

    @classmethod
    def setUpClass(cls):
        cls.result = pyhexlayer.mesh_file(sample("plate.step"), layers=2, order=2)
        cls.corner_pairs = np.sort(cls.result.hexes[:, cls.EDGES], axis=2)  # (M, 12, 2) the corners of each edge
        cls.mids = cls.result.hexes[:, 8:]

    def test_twenty_nodes_a_hex(self):
        r = self.result
        self.assertEqual(r.hexes.shape, (r.report["hexes"], 20))
        self.assertEqual(len(np.unique(r.hexes)), len(r.nodes), "every node belongs to a hex")
        self.assertTrue(np.isin(self.mids, r.hexes[:, :8], invert=True).all(), "mid-edge nodes are not corners")
        self.assertGreater(hex_volumes(r.nodes, r.hexes[:, :8]).min(), 0)

    def test_one_mid_node_an_edge_shared_by_the_hexes_around_it(self):
        edges = np.unique(self.corner_pairs.reshape(-1, 2), axis=0)
        mid_of_edge = np.unique(np.column_stack([self.corner_pairs.reshape(-1, 2), self.mids.reshape(-1)]), axis=0)
        self.assertEqual(len(np.unique(self.mids)), len(edges), "as many mid nodes as distinct edges")
        self.assertEqual(len(mid_of_edge), len(edges), "each edge has one mid node, whichever hex names it")
        self.assertLess(len(np.unique(self.mids)), 12 * len(self.mids) // 2, "shared: an inner edge has 2-4 hexes")

    def test_sweep_edge_nodes_are_midpoints(self):
        x = self.result.nodes
        ends = x[self.corner_pairs[:, 8:]]  # (M, 4, 2, 3): edges 0-4, 1-5, 2-6, 3-7
        np.testing.assert_allclose(x[self.mids[:, 8:]], ends.mean(axis=2), atol=1e-9)

    def test_wall_edge_nodes_are_near_midpoints_on_the_flat_walls(self):
        x = self.result.nodes
        ends = x[self.corner_pairs[:, :8]]
        np.testing.assert_allclose(x[self.mids[:, :8]], ends.mean(axis=2), atol=1e-6)


class BrepString(unittest.TestCase):
    def test_same_mesh_as_the_file(self):
        from_file = pyhexlayer.mesh_file(sample("plate.step"))
        from_text = pyhexlayer.mesh_brep(brep_of(sample("plate.step")))
        self.assertEqual(from_text.report["hexes"], from_file.report["hexes"])
        np.testing.assert_allclose(from_text.nodes, from_file.nodes, atol=1e-9)

    def test_invalid_text_is_an_input_error_naming_the_string(self):
        with self.assertRaises(pyhexlayer.InputError) as caught:
            pyhexlayer.mesh_brep("not a shape")
        self.assertEqual(caught.exception.exit_code, 3)
        self.assertIn("the BREP string", str(caught.exception))
        self.assertNotIn(tempfile.gettempdir(), str(caught.exception))


class Errors(unittest.TestCase):
    def assert_cli_error(self, error_type, code, call, cli_arguments):
        with self.assertRaises(error_type) as caught:
            call()
        self.assertIsInstance(caught.exception, pyhexlayer.HexLayerError)
        self.assertEqual(caught.exception.exit_code, code)
        self.assertEqual(error_type.exit_code, code)
        self.assertEqual(cli_error(*cli_arguments), (code, str(caught.exception)))

    def test_bad_layer_count_is_a_usage_error(self):
        plate = sample("plate.step")
        self.assert_cli_error(pyhexlayer.UsageError, 2, lambda: pyhexlayer.mesh_file(plate, layers=0),
                              [plate, "--layers", "0"])

    def test_missing_file_is_an_input_error(self):
        missing = sample("no_such_part.step")
        self.assert_cli_error(pyhexlayer.InputError, 3, lambda: pyhexlayer.mesh_file(missing), [missing])

    def test_cube_is_a_geometry_error(self):
        cube = sample("thick_block.step")
        self.assert_cli_error(pyhexlayer.GeometryError, 4, lambda: pyhexlayer.mesh_file(cube), [cube])

    def test_bad_order_is_the_clis_usage_error(self):
        plate = sample("plate.step")
        self.assert_cli_error(pyhexlayer.UsageError, 2, lambda: pyhexlayer.mesh_file(plate, order=3),
                              [plate, "--order", "3"])
        self.assertEqual(cli_error(plate, "--order", "3")[1], "--order must be 1 or 2, got 3")

    def test_bad_option_values_are_refused_with_the_clis_message(self):
        for options, phrase in (({"sizing": "graded"}, "--sizing must be 'uniform' or 'adaptive'"),
                                ({"aspect": -1.0}, "--aspect must be a positive ratio"),
                                ({"size": 2.0, "aspect": 5.0}, "give --size or --aspect, not both")):
            with self.subTest(options=options), self.assertRaises(pyhexlayer.UsageError) as caught:
                pyhexlayer.check_options(**options)
            self.assertIn(phrase, str(caught.exception))
        for order in (1, 2):
            for sizing in ("uniform", "adaptive"):
                pyhexlayer.check_options(layers=3, size=1.5, sizing=sizing, aspect=0.0, order=order)
        pyhexlayer.check_options(aspect=5.0)

    def test_options_are_keyword_only(self):
        with self.assertRaises(TypeError):
            pyhexlayer.mesh_file(sample("plate.step"), 2)


class Callback(unittest.TestCase):
    def test_exception_in_the_callback_ends_the_run_and_reaches_the_caller(self):
        def stop(line):
            raise KeyError(line)
        with self.assertRaises(KeyError) as caught:
            pyhexlayer.mesh_file(sample("plate.step"), progress=stop)
        self.assertTrue(caught.exception.args[0].startswith("geometry:"))
        self.assertGreater(len(pyhexlayer.mesh_file(sample("plate.step")).hexes), 0, "the module still works")

    def test_python_runs_while_the_core_meshes(self):
        """The GIL is released during the stages: this thread sees the run between its first and last stage.
        The callback is list.append, C code that never hands the GIL over by itself."""
        lines, seen = [], set()
        worker = threading.Thread(target=pyhexlayer.mesh_file, args=(sample("plate.step"),),
                                  kwargs={"progress": lines.append})
        worker.start()
        while worker.is_alive():
            seen.add(len(lines))
        worker.join()
        self.assertTrue(seen & set(range(1, len(lines))), "stages seen finished: {}".format(sorted(seen)))

    def test_callback_that_is_not_callable_is_a_type_error(self):
        with self.assertRaises(TypeError):
            pyhexlayer.mesh_file(sample("plate.step"), progress=42)


if __name__ == "__main__":
    harness.main()
