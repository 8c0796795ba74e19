"""Shared by the FreeCAD tests: parts, and the hexes as CalculiX reads them.

CTest runs each test module as `freecadcmd -t MODULE -M tests/freecad` with tests/python on PYTHONPATH and
the workbench installed by scripts/install-workbench.sh into a private FreeCAD user folder."""
import os
import tempfile

import numpy as np

import FreeCAD
from hex_geometry import hex_volumes

PLATE = (100.0, 20.0, 2.0)  # length x, width y, thickness z (mm)


def sample(name):
    """A part of Resources/samples (CTest passes the source folder as HEXLAYER_SOURCE)."""
    return os.path.join(os.environ["HEXLAYER_SOURCE"], "Resources", "samples", name)


def new_document(test):
    """A new document, closed when `test` ends (unless the test closed it)."""
    doc = FreeCAD.newDocument(type(test).__name__)
    test.addCleanup(close_document, doc.Name)
    return doc


def close_document(name):
    if name in FreeCAD.listDocuments():
        FreeCAD.closeDocument(name)


def assert_fails(test, mesh, *phrases):
    """Recomputing leaves `mesh` failed, with each phrase in its Status and no mesh for a solver."""
    mesh.Document.recompute()
    test.assertFalse(mesh.isValid())
    test.assertEqual(mesh.FemMesh.VolumeCount, 0, "no stale mesh for a solver")
    test.assertTrue(mesh.Status.startswith("Failed: "), mesh.Status)
    for phrase in phrases:
        test.assertIn(phrase, mesh.Status)


def add_plate(doc, name="Plate"):
    """The 100 x 20 x 2 mm plate as a Part box: Face1 at x = 0, Face2 at x = 100, Face6 on top (z = 2)."""
    box = doc.addObject("Part::Box", name)
    box.Length, box.Width, box.Height = PLATE
    doc.recompute()
    return box


def mesh_plate(test, layers=2, order=1):
    """The plate in a new document, meshed by HexLayer.makeMesh with `layers` layers, hexa8 unless order 2 (the
    default of the mesh object is 2; these tests look at the corners): (document, plate, mesh)."""
    import HexLayer
    doc = new_document(test)
    plate = add_plate(doc)
    mesh = HexLayer.makeMesh(doc, plate, Layers=layers, Order=order)
    doc.recompute()
    test.assertTrue(mesh.isValid(), mesh.Status)
    return doc, plate, mesh


LBRACKET = dict(thickness=2.0, inner_radius=3.0, legs=(40.0, 30.0), width=20.0)  # mm


def lbracket_shape(thickness, inner_radius, legs, width):
    """An L profile in the xz plane extruded along y: leg 1 along x (outer wall z = 0, end face x = legs[0]),
    leg 2 along z (outer wall x = 0, end face z = legs[1]), joined by a bend of inner radius inner_radius."""
    import Part
    V = FreeCAD.Vector
    outer = inner_radius + thickness
    c, s45 = V(outer, 0, outer), 0.5 ** 0.5

    def arc(radius):
        return Part.Arc(V(outer, 0, outer - radius), c + V(-radius * s45, 0, -radius * s45), V(outer - radius, 0, outer))
    x_end, z_end = legs
    edges = [Part.LineSegment(V(outer, 0, 0), V(x_end, 0, 0)), Part.LineSegment(V(x_end, 0, 0), V(x_end, 0, thickness)),
             Part.LineSegment(V(x_end, 0, thickness), V(outer, 0, thickness)), arc(inner_radius),
             Part.LineSegment(V(thickness, 0, outer), V(thickness, 0, z_end)),
             Part.LineSegment(V(thickness, 0, z_end), V(0, 0, z_end)), Part.LineSegment(V(0, 0, z_end), V(0, 0, outer))]
    outer_arc = arc(outer)
    edges.append(Part.Arc(outer_arc.EndPoint, outer_arc.value((outer_arc.FirstParameter + outer_arc.LastParameter) / 2),
                          outer_arc.StartPoint))
    face = Part.Face(Part.Wire([e.toShape() for e in edges]))
    return face.extrude(V(0, width, 0))


def add_lbracket(doc, name="LBracket"):
    """The L-bracket of LBRACKET as a Part feature."""
    part = doc.addObject("Part::Feature", name)
    part.Shape = lbracket_shape(**LBRACKET)
    doc.recompute()
    return part


def face_name(shape, where):
    """The name ("FaceN") of the one planar face of `shape` whose centre satisfies where(center)."""
    names = ["Face{}".format(i) for i, f in enumerate(shape.Faces, start=1)
             if f.Surface.__class__.__name__ == "Plane" and where(f.CenterOfMass)]
    if len(names) != 1:
        raise ValueError("expected one face, found {}".format(names))
    return names[0]


def add_sample(doc, file_name):
    """A sample STEP part as a Part feature."""
    import Part
    part = doc.addObject("Part::Feature", os.path.splitext(file_name)[0])
    part.Shape = Part.read(sample(file_name))
    doc.recompute()
    return part


def element_node_count(keyword_line):
    """Nodes per element of an *ELEMENT line's TYPE (C3D8 -> 8, C3D20 -> 20)."""
    element_type = keyword_line.upper().split("TYPE=")[1].split(",")[0].strip()
    return int("".join(c for c in element_type[3:] if c.isdigit()))


def read_inp(path):
    """Nodes (N, 3) and the node ids of each element (0-based rows of nodes) of an Abaqus/CalculiX .inp;
    an element's ids may go on over several lines."""
    nodes, elements, section, pending = {}, [], None, []
    with open(path) as f:
        for line in f:
            if line.startswith("**") or not line.strip():
                continue
            if line.startswith("*"):
                keyword = line.split(",")[0].strip().upper()
                section = keyword if keyword in ("*NODE", "*ELEMENT") else None
                count = element_node_count(line) if section == "*ELEMENT" else 0
                continue
            values = [v for v in line.split(",") if v.strip()]
            if section == "*NODE":
                nodes[int(values[0])] = [float(v) for v in values[1:4]]
            elif section == "*ELEMENT":
                pending += [int(v) for v in values]
                if len(pending) == count + 1:
                    elements.append(pending[1:])
                    pending = []
    ids = sorted(nodes)
    row = {node: i for i, node in enumerate(ids)}
    return np.array([nodes[i] for i in ids]), np.array([[row[n] for n in e] for e in elements])


def written_elements(femmesh):
    """Nodes and elements of a FemMesh as FreeCAD writes it for CalculiX (writeABAQUS: C3D8 or C3D20)."""
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "mesh.inp")
        femmesh.writeABAQUS(path, 1, False)
        return read_inp(path)


def written_hex_volumes(femmesh):
    """Hex volumes (of the corners) of a FemMesh as FreeCAD writes it for CalculiX."""
    nodes, elements = written_elements(femmesh)
    return hex_volumes(nodes, elements[:, :8])
