"""The mid-surface shell in FreeCAD (issue 20): HexLayer.makeShellMesh makes a FEM mesh of quad8 faces on the chordal
surface of a thin solid and an ElementGeometry2D with the measured median thickness; FreeCAD's own CalculiX objects
solve it.

The 100 x 20 x 2 mm steel cantilever plate: Fixed on the solid's root face (Face1: FemMesh.getNodesByFace finds the
shell's root edge, which lies on its mid-line), 10 N in -z on the tip's mid-line (a line object at x = 100, z = 1: a
force on the solid's end face finds no shell face in it, FreeCAD spreads a force on an edge over the shell's edge
nodes). The tip deflection, the mean u_z of the tip's nodes, is compared with the converged reference of
test_hexlayer_ccx (C3D8I, 1 mm quads in 4 layers, the same FreeCAD constraints on the solid: 1.1681 mm measured there;
the issue's converged value is 1.1695 mm): within 2 %.

The wedge plate (thickness 1 -> 4 mm) gets the median as its ElementGeometry2D thickness and a warning in Status.

Run: freecadcmd -t test_hexlayer_shell -M tests/freecad (see hexlayer_testing for the environment).
"""
import os
import shutil
import tempfile
import unittest

import numpy as np

import FreeCAD
import HexLayer
import Part

import hexlayer_testing as t
from test_hexlayer_ccx import PLATE_FACES, add_analysis, plate_reference, write_and_solve


class ShellPlate(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.mkdtemp(prefix="hexlayer_shell_")
        cls.doc = FreeCAD.newDocument("ShellPlate")
        cls.plate = t.add_plate(cls.doc)
        cls.analysis, cls.solver = add_analysis(cls.doc, cls.plate, PLATE_FACES)
        length, width, thickness = t.PLATE
        V = FreeCAD.Vector
        cls.line = cls.doc.addObject("Part::Feature", "TipMidLine")
        cls.line.Shape = Part.LineSegment(V(length, 0, thickness / 2), V(length, width, thickness / 2)).toShape()
        cls.doc.getObject("Force").References = [(cls.line, "Edge1")]
        cls.shell = HexLayer.makeShellMesh(cls.doc, cls.plate, Order=2)
        cls.analysis.addObject(cls.shell)
        cls.analysis.addObject(cls.shell.ElementGeometry)
        cls.doc.recompute()

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.doc.Name)
        shutil.rmtree(cls.work)

    def test_quad8_faces_on_the_mid_plane_with_the_wall_thickness(self):
        fem = self.shell.FemMesh
        self.assertTrue(self.shell.isValid(), self.shell.Status)
        self.assertEqual(fem.VolumeCount, 0)
        self.assertGreater(fem.FaceCount, 100)
        self.assertEqual(set(fem.getElementType(e) for e in fem.Faces), {"Face"})
        self.assertEqual(set(len(fem.getElementNodes(e)) for e in fem.Faces), {8})
        z = [fem.getNodeById(n).z for n in fem.Nodes]
        self.assertAlmostEqual(min(z), 1.0, delta=1e-9)
        self.assertAlmostEqual(max(z), 1.0, delta=1e-9)
        self.assertAlmostEqual(self.shell.ElementGeometry.Thickness.Value, 2.0, delta=1e-9)
        self.assertAlmostEqual(self.shell.ThicknessMin.Value, 2.0, delta=1e-9)
        self.assertNotIn("Warning", self.shell.Status)

    def test_fixed_face_finds_the_shell_root_edge(self):
        fem = self.shell.FemMesh
        found = fem.getNodesByFace(self.plate.Shape.Face1)
        near = [n for n in fem.Nodes if abs(fem.getNodeById(n).x) < 1e-6]
        self.assertEqual(sorted(found), sorted(near))
        self.assertGreater(len(found), 8)
        group = [g for g in fem.Groups if fem.getGroupName(g) == "Face1"][0]
        self.assertEqual(sorted(fem.getGroupElements(group)), sorted(found), "the Face1 node group")

    def test_tip_deflection_within_2_percent_of_the_converged_reference(self):
        result = write_and_solve(self.analysis, self.solver, os.path.join(self.work, "shell"))[1]
        self.assertIsNotNone(result, "FreeCAD loaded no CalculiX result")
        displacement = dict(zip(result.NodeNumbers, result.DisplacementVectors))
        tip = self.shell.FemMesh.getNodesByEdge(self.line.Shape.Edge1)
        self.assertGreater(len(tip), 8)
        deflection = float(np.mean([displacement[n].z for n in tip]))
        reference = plate_reference()
        print("\nshell (quad8) tip deflection {:.4f} mm, reference {:.4f} mm: ratio {:.4f}; converged -1.1695 mm: "
              "ratio {:.4f}".format(deflection, reference, deflection / reference, deflection / -1.1695))
        self.assertAlmostEqual(deflection / reference, 1.0, delta=0.02)


class ShellWedge(unittest.TestCase):
    def test_varying_thickness_takes_the_median_with_a_warning(self):
        doc = t.new_document(self)
        wedge = doc.addObject("Part::Feature", "Wedge")
        wedge.Shape = Part.read(t.sample("wedge_plate.step"))
        shell = HexLayer.makeShellMesh(doc, wedge)
        doc.recompute()
        self.assertTrue(shell.isValid(), shell.Status)
        self.assertAlmostEqual(shell.ThicknessMin.Value, 1.0, delta=0.01)
        self.assertAlmostEqual(shell.ThicknessMax.Value, 4.0, delta=0.04)
        self.assertEqual(shell.ElementGeometry.Thickness.Value, shell.Thickness.Value)
        self.assertGreater(shell.Thickness.Value, 1.5)
        self.assertLess(shell.Thickness.Value, 3.5)
        self.assertIn("Warning: the thickness varies", shell.Status)

    def test_a_part_that_is_not_a_solid_fails_with_its_reason(self):
        doc = t.new_document(self)
        face = doc.addObject("Part::Plane", "Sheet")
        shell = HexLayer.makeShellMesh(doc, face)
        doc.recompute()
        self.assertFalse(shell.isValid())
        self.assertTrue(shell.Status.startswith("Failed: "), shell.Status)
        self.assertEqual(shell.FemMesh.FaceCount, 0)


if __name__ == "__main__":
    unittest.main()
