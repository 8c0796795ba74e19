"""The node groups per CAD face in the Hex-Layer FemMesh, against FreeCAD's own idea of which nodes lie on
a face, on the sample plate with holes (80 x 50 x 2 mm, four holes of 8 mm); and FreeCAD's Fixed and
Force constraints on its end faces solved by CalculiX through FreeCAD's solver tools.

 - For every face of the part (top, bottom, the four sides, the four hole walls), FemMesh.getNodesByFace
   (nodes within the face's tolerance, ~1e-7 mm) returns exactly the nodes of the group of that name.
 - Fixed on the end face x = 0, 10 N in -z on the end face x = 80, order 2 in 2 layers of 2 mm quads: the
   mean tip deflection is within 1 % of the same part meshed by Gmsh in tet10 at 1 mm and solved by ccx as
   C3D10 (tests/python/ccx_tet10.py: every DOF of the fixed face held, the force a uniform traction; no
   HexLayer in the reference).

Run: freecadcmd -t test_hexlayer_groups -M tests/freecad (see hexlayer_testing for the environment).
"""
import shutil
import tempfile
import unittest

import FreeCAD
import HexLayer

import hexlayer_testing as t
import ccx_tet10
from test_hexlayer_ccx import E, FORCE, NU, Faces, solved_tip_deflection

TET_SIZE = 1.0  # mm, the Gmsh tet10 reference's element size


def plate_holes(doc):
    return t.add_sample(doc, "plate_holes.step")


def plate_holes_faces():
    """Fixed at x = 0, Force on x = 80 along the top face's normal reversed (-z)."""
    import Part
    shape = Part.read(t.sample("plate_holes.step"))
    return Faces(t.face_name(shape, lambda c: abs(c.x) < 1e-9), t.face_name(shape, lambda c: abs(c.x - 80) < 1e-9),
                 t.face_name(shape, lambda c: abs(c.z - 2) < 1e-9), True)


class FaceGroups(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.doc = FreeCAD.newDocument("FaceGroups")
        cls.part = plate_holes(cls.doc)
        cls.mesh = HexLayer.makeMesh(cls.doc, cls.part, Layers=2, Order=2)
        cls.doc.recompute()
        fem = cls.mesh.FemMesh
        cls.groups = {fem.getGroupName(g): sorted(fem.getGroupElements(g)) for g in fem.Groups}

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.doc.Name)

    def test_one_group_per_face_named_like_freecad(self):
        faces = ["Face{}".format(i) for i in range(1, len(self.part.Shape.Faces) + 1)]
        self.assertEqual(len(faces), 10)
        self.assertEqual(sorted(n for n in self.groups if n.startswith("Face")), sorted(faces))

    def test_get_nodes_by_face_finds_the_group_on_every_face(self):
        fem = self.mesh.FemMesh
        kinds = {}
        for i, face in enumerate(self.part.Shape.Faces, start=1):
            name = "Face{}".format(i)
            kinds[name] = face.Surface.__class__.__name__
            with self.subTest(face=name, surface=kinds[name]):
                found = sorted(fem.getNodesByFace(face))
                self.assertGreater(len(found), 8)
                self.assertEqual(found, self.groups[name])
        self.assertEqual(sorted(kinds.values()).count("Cylinder"), 4, "the hole walls are among them")


class FixedAndForceOnEndFaces(unittest.TestCase):
    def test_tip_deflection_within_1_percent_of_a_tet10_solve(self):
        work = tempfile.mkdtemp(prefix="hexlayer_ccx_groups_")
        self.addCleanup(shutil.rmtree, work)
        faces = plate_holes_faces()
        deflection, doc = solved_tip_deflection("PlateHoles", work, plate_holes, faces, Layers=2, Order=2)
        FreeCAD.closeDocument(doc.Name)
        reference = ccx_tet10.solve_tet10(t.sample("plate_holes.step"), TET_SIZE, lambda c: abs(c[0]) < 1e-6,
                                          lambda c: abs(c[0] - 80) < 1e-6, (0.0, 0.0, -FORCE), (E, NU)).mean[2]
        print("\nplate with holes, tip deflection C3D20: 2 layers {:.5f} mm, Gmsh tet10 at {} mm {:.5f} mm: ratio "
              "{:.4f}".format(deflection, TET_SIZE, reference, deflection / reference))
        self.assertLess(reference, 0)
        self.assertAlmostEqual(deflection / reference, 1.0, delta=0.01)


if __name__ == "__main__":
    unittest.main()
