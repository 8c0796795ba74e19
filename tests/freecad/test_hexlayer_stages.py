"""The stage views of a Hex-Layer mesh in FreeCAD without GUI: chordal surface, quad mesh, exploded layers,
quality view (HexLayer.makeStageViews and friends), on the 100 x 20 x 2 mm plate meshed with 2 layers.

Run: freecadcmd -t test_hexlayer_stages -M tests/freecad (see hexlayer_testing for the environment).
"""
import os
import tempfile
import unittest

import numpy as np

import FreeCAD
import HexLayer

import hexlayer_testing as t


class PlateStages(unittest.TestCase):
    def setUp(self):
        self.doc, self.plate, self.mesh = t.mesh_plate(self)
        self.result = self.mesh.Proxy.result

    def test_result_hands_out_the_stages(self):
        r = self.result
        self.assertEqual(r.chordal_facets.shape[1], 4)
        self.assertTrue(((r.chordal_facets >= -1) & (r.chordal_facets < len(r.chordal_vertices))).all())
        self.assertTrue((r.chordal_facets[:, :3] >= 0).all(), "only the 4th id of a triangle is -1")
        self.assertEqual(r.quads.shape[1], 4)
        self.assertEqual(r.quads.min(), 0)
        self.assertEqual(r.quads.max(), len(r.quad_nodes) - 1)
        self.assertEqual(len(r.node_layer), len(r.nodes))
        self.assertEqual(sorted(set(r.node_layer.tolist())), [0, 1, 2])
        self.assertEqual(len(r.hexes), 2 * len(r.quads), "each quad swept into one hex per layer")
        mid = t.PLATE[2] / 2
        self.assertLess(np.abs(r.quad_nodes[:, 2] - mid).max(), 0.05, "quad nodes on the mid-surface")
        self.assertLess(np.abs(r.chordal_vertices[:, 2] - mid).max(), 0.05)

    def test_chordal_surface_has_the_mid_surface_area(self):
        view = HexLayer.makeChordalSurface(self.mesh)
        area = t.PLATE[0] * t.PLATE[1]
        self.assertEqual(view.TypeId, "Mesh::Feature")
        self.assertLess(abs(view.Mesh.Area - area) / area, 0.02, view.Mesh.Area)
        facets = self.result.chordal_facets
        self.assertEqual(view.Mesh.CountFacets, len(facets) + int((facets[:, 3] >= 0).sum()), "quads split in two")

    def test_quad_mesh_holds_the_quads(self):
        view = HexLayer.makeQuadMesh(self.mesh)
        self.assertEqual(view.FemMesh.QuadrangleCount, len(self.result.quads))
        self.assertEqual(view.FemMesh.FaceCount, len(self.result.quads))
        self.assertEqual(view.FemMesh.NodeCount, len(self.result.quad_nodes))

    def test_exploded_layers_move_apart_along_the_sweep(self):
        group = HexLayer.makeExplodedLayers(self.mesh, gap=3.0)
        layers = group.Group
        self.assertEqual([layer.Layer for layer in layers], [0, 1])
        self.assertEqual([layer.FemMesh.VolumeCount for layer in layers], [len(self.result.quads)] * 2)
        self.assertEqual([layer.Offset.Value for layer in layers], [0.0, 3.0])
        for layer in layers:  # the plate's sweep is +z: layer k spans z in [k, k + 1] + k x gap
            z = np.array([n.z for n in layer.FemMesh.Nodes.values()])
            self.assertAlmostEqual(z.min(), layer.Layer * 4.0, delta=1e-6)
            self.assertAlmostEqual(z.max(), layer.Layer * 4.0 + 1.0, delta=1e-6)

    def test_exploded_gap_defaults_to_twice_the_wall_thickness(self):
        layers = HexLayer.makeExplodedLayers(self.mesh).Group
        self.assertAlmostEqual(layers[1].Offset.Value, 2 * t.PLATE[2], delta=1e-6)

    def test_quality_view_holds_the_scaled_jacobian_of_every_hex(self):
        view = HexLayer.makeQualityView(self.mesh)
        self.assertEqual(view.FemMesh.VolumeCount, len(self.result.hexes))
        self.assertEqual(len(view.ScaledJacobian), view.FemMesh.VolumeCount)
        np.testing.assert_allclose(view.ScaledJacobian, self.result.scaled_jacobian)
        self.assertIn("min {:.3f}".format(self.result.scaled_jacobian.min()), view.Label)

    def test_views_are_grouped_and_made_again_replace(self):
        views = HexLayer.makeStageViews(self.mesh)
        self.assertEqual(sorted(views), ["ChordalSurface", "ExplodedLayers", "QuadMesh", "Quality"])
        groups = [o for o in self.doc.Objects if getattr(o, "StagesOf", None) is self.mesh]
        self.assertEqual(len(groups), 1)
        self.assertEqual(sorted(o.Stage for o in groups[0].Group), sorted(views))
        count = len(self.doc.Objects)
        HexLayer.makeStageViews(self.mesh)
        self.assertEqual(len(self.doc.Objects), count, "views made again replace the old ones")

    def test_saved_views_reopen_with_their_values(self):
        HexLayer.makeStageViews(self.mesh)
        path = os.path.join(tempfile.mkdtemp(), "stages.FCStd")
        self.doc.saveAs(path)
        FreeCAD.closeDocument(self.doc.Name)
        doc = FreeCAD.openDocument(path)
        self.addCleanup(t.close_document, doc.Name)
        quality = next(o for o in doc.Objects if getattr(o, "Stage", None) == "Quality")
        self.assertEqual(quality.FemMesh.VolumeCount, len(self.result.hexes))
        np.testing.assert_allclose(quality.ScaledJacobian, self.result.scaled_jacobian)
        layers = next(o for o in doc.Objects if getattr(o, "Stage", None) == "ExplodedLayers").Group
        self.assertEqual([layer.FemMesh.VolumeCount for layer in layers], [len(self.result.quads)] * 2)

    def test_views_mesh_again_when_the_session_has_no_result(self):
        self.mesh.Proxy.result = None  # as after reopening the document
        view = HexLayer.makeQuadMesh(self.mesh)
        self.assertEqual(view.FemMesh.QuadrangleCount, len(self.result.quads), "deterministic: the same quads")

    def test_out_of_date_mesh_is_meshed_first(self):
        self.mesh.Layers = 3
        view = HexLayer.makeExplodedLayers(self.mesh)
        self.assertEqual(len(view.Group), 3)
        self.assertEqual(self.mesh.FemMesh.VolumeCount, 3 * len(self.result.quads))


class Failures(unittest.TestCase):
    def test_thick_block_raises_the_mesher_error_and_makes_no_view(self):
        doc = t.new_document(self)
        block = t.add_sample(doc, "thick_block.step")
        mesh = HexLayer.makeMesh(doc, block)
        count = len(doc.Objects)
        with self.assertRaisesRegex(Exception, "not a thin section"):
            HexLayer.makeChordalSurface(mesh)
        self.assertEqual(len(doc.Objects), count)

    def test_other_objects_are_refused(self):
        doc = t.new_document(self)
        plate = t.add_plate(doc)
        with self.assertRaisesRegex(TypeError, "not a Hex-Layer mesh"):
            HexLayer.makeQualityView(plate)


if __name__ == "__main__":
    unittest.main()
