"""A FreeCAD part meshed by the hexlayer executable (mesher.py), and the result as a FemMesh. No GUI: usable from
freecadcmd."""
import functools
import os
import re
import tempfile

import Fem
import numpy

from . import mesher

# SMESH orders a hexa8's bottom quad the other way round from CalculiX and HexLayer; FreeCAD's
# writeABAQUS maps it back, so this order gives the C3D8 elements it writes positive volumes.
SMESH_HEXA8 = (0, 3, 2, 1, 4, 7, 6, 5)
# SMESH's hexa20 (SMDS_QuadraticVolumeOfNodes): those 8 corners s0-s7, then the mid nodes of its edges
# s0-s1, s1-s2, s2-s3, s3-s0, s4-s5, s5-s6, s6-s7, s7-s4, s0-s4, s1-s5, s2-s6, s3-s7. As columns of
# pyhexlayer's (M, 20) rows (C3D20: mid node 8 + e on edge e of 0-1, 1-2, 2-3, 3-0, 4-5, 5-6, 6-7, 7-4,
# 0-4, 1-5, 2-6, 3-7): s0-s1 is 0-3 (column 11), s1-s2 is 3-2 (10), ... Checked by the tests through
# writeABAQUS: each mid node of the C3D20 it writes lies at the midpoint of its C3D20 edge.
SMESH_HEXA20 = SMESH_HEXA8 + (11, 10, 9, 8, 15, 14, 13, 12, 16, 19, 18, 17)

# One unit hex, for trying what FreeCAD's writer can write.
_UNIT_CUBE = numpy.array([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)], dtype=float)
_UNIT_HEX = numpy.arange(8).reshape(1, 8)

# The values the mesh object's Sizing property offers; mesher.check_options says which are supported today.
SIZINGS = ("adaptive", "uniform")  # the first is the default


def options(obj):
    """The mesher's options (mesher.option_arguments, pyhexlayer's keywords) from the mesh object's properties."""
    return dict(layers=obj.Layers, size=obj.Size.Value, sizing=obj.Sizing, aspect=obj.Aspect, order=obj.Order,
                drop_junctions=obj.DropJunctions)


def for_people(message):
    """A message naming CLI options ("--drop-junctions ...") in the property editor's words ("DropJunctions ...")."""
    return re.sub(r"--([\w-]+)", lambda m: "".join(word.capitalize() for word in m.group(1).split("-")), message)


def part_problem(part):
    """Why `part` cannot be meshed, or None if it has a solid."""
    if part is None:
        return "No part to mesh: choose the solid to mesh as the mesh's Part."
    shape = getattr(part, "Shape", None)
    if shape is None or shape.isNull():
        return "'{}' ({}) has no shape to mesh.".format(part.Label, part.TypeId)
    if not shape.Solids:
        return "'{}' ({}) is a {}, not a solid: Hex-Layer meshes thin solids.".format(
            part.Label, part.TypeId, shape.ShapeType.lower())
    return None


def option_problem(opts):
    """Why the mesher refuses these options (`hexlayer check`), in the property editor's words, or None."""
    try:
        mesher.check_options(**opts)
    except mesher.UsageError as error:
        return for_people(str(error))
    return None


def mesh(part, opts, progress=None, force=False):
    """The meshing result of the part's shape (mesher.read_result: pyhexlayer.MeshResult's arrays), meshed by the
    hexlayer executable out of FreeCAD's process; the BREP text keeps FreeCAD's face numbering. A mesh that fails
    its validation raises mesher.ValidationError, unless force."""
    problem = part_problem(part)
    if problem:
        raise mesher.InputError(problem)
    return mesher.mesh_brep(part.Shape.exportBrepToString(), progress=progress, force=force, **opts)


def femmesh(result):
    """A FemMesh of hexa8 (order 1) or hexa20 (order 2) volumes, the node groups TOP, BOTTOM and RIM, and
    one node group per CAD face named as FreeCAD names the part's faces ("Face1", ...: its nodes are
    the ones FemMesh.getNodesByFace finds on that face). Ids 1-based, as FreeCAD's. FreeCAD 0.20's
    FemMesh groups nodes or whole elements, not faces of volumes: the element faces on each CAD face
    (pyhexlayer's face_elements, the .inp's *SURFACE FaceN_S) have no FemMesh group."""
    fem = hexa_femmesh(result.nodes, result.hexes)
    add_node_groups(fem, list(result.node_sets.items()) + list(result.face_nodes.items()))
    return fem


def add_node_groups(fem, sets):
    """[(name, 0-based node ids)] as node groups of the FemMesh (1-based ids); empty sets left out."""
    for name, nodes in sets:
        if len(nodes):
            fem.addGroupElements(fem.addGroup(name, "Node"), (nodes + 1).tolist())


def node_femmesh(nodes):
    """A FemMesh of the (N, 3) nodes, ids 1..N in row order."""
    fem = Fem.FemMesh()
    for i, (x, y, z) in enumerate(nodes.tolist(), start=1):
        fem.addNode(x, y, z, i)
    return fem


def shell_femmesh(result):
    """A FemMesh of the mid-surface shell's faces: quad4, or quad8 for Order 2 (SMESH's quad8 lists the corners, then
    the mid-side nodes of edges 0-1, 1-2, 2-3, 3-0, as pyhexlayer's shell_elements do), node groups RIM and Face1..FaceN
    (the shell nodes whose sweep line ends on that wall, or whose column lies on that rim face)."""
    fem = node_femmesh(result.shell_nodes)
    for i, face in enumerate((result.shell_elements + 1).tolist(), start=1):
        fem.addFace(face, i)
    add_node_groups(fem, result.shell_node_sets.items())
    return fem


def hexa_femmesh(nodes, hexes):
    """A FemMesh of the (N, 3) nodes and the (M, 8) or (M, 20) pyhexlayer hexes (0-based), 1-based ids in row order."""
    fem = node_femmesh(nodes)
    smesh_order = SMESH_HEXA20 if hexes.shape[1] == 20 else SMESH_HEXA8
    for i, hexa in enumerate((hexes[:, smesh_order] + 1).tolist(), start=1):
        fem.addVolume(hexa, i)
    return fem


# Order 1 in FreeCAD: its CalculiX writer writes hexa8 as C3D8, fully integrated, which locks in bending (a 2-layer
# cantilever bends 78 % of the converged tip deflection, tests/freecad/test_hexlayer_ccx.py).
ORDER1_WARNING = ("Order 1: FreeCAD's CalculiX writes these hexa8 as C3D8, which are too stiff in bending (2 layers: "
                  "78 % of the converged deflection). Set Order 2 (hexa20) for bending, or use 4 or more layers.")
C3D8I_OFFER = (" This FreeCAD can also write them as C3D8I (incompatible modes, accurate in bending): "
               "HexLayer.writeCalculixMesh(mesh, path).")


@functools.lru_cache(maxsize=None)
def can_write_c3d8i():
    """Whether this FreeCAD's FemMesh.writeABAQUS writes hexa8 as C3D8I (volVariant="incompatible", FreeCAD 1.x):
    tried on one hex, not guessed from the version."""
    fem = hexa_femmesh(_UNIT_CUBE, _UNIT_HEX)
    handle, path = tempfile.mkstemp(suffix=".inp")
    os.close(handle)
    try:
        fem.writeABAQUS(path, 1, False, volVariant="incompatible")
        with open(path) as f:
            return "C3D8I" in f.read().upper()
    except (TypeError, ValueError, RuntimeError):  # 0.20: no keyword arguments; an unknown variant
        return False
    finally:
        os.remove(path)


def write_calculix_mesh(fem, path):
    """Writes the FemMesh for CalculiX as FreeCAD does, but its hexa8 as C3D8I (where can_write_c3d8i)."""
    if not can_write_c3d8i():
        raise RuntimeError("this FreeCAD's FemMesh.writeABAQUS cannot write C3D8I (FreeCAD 1.0 and later can); "
                           "use Order 2 (hexa20) instead")
    fem.writeABAQUS(path, 1, False, volVariant="incompatible")


def order_warning(order):
    """What Status and the task panel say about the element order: nothing for Order 2."""
    if order != 1:
        return ""
    return ORDER1_WARNING + (C3D8I_OFFER if can_write_c3d8i() else "")


def summary(report, seconds):
    """One line for people: hexes, scaled Jacobian min/avg, volume error, time, the failed validation checks, and
    the warning about Order 1."""
    sj, volume = report["scaled_jacobian"], report["volume"]
    text = "{} hexes, {} nodes, {} layers. Scaled Jacobian min {:.3f}, avg {:.3f}. Volume {:+.2f} % vs CAD. {:.1f} s.".format(
        report["hexes"], report["nodes"], report["layers"], sj["min"], sj["avg"], 100 * volume["relative_error"], seconds)
    failures = [f["message"] for f in report["validation"]["failures"]]  # only with Force
    if failures:
        text += " Validation failed, kept as Force is on: {}. Not fit for a solver there.".format("; ".join(failures))
    warning = order_warning(report["order"])
    return text + (" " + warning if warning else "")


# FreeCAD's ElementGeometry2D holds one thickness per shell section: more than this relative spread is worth a warning.
THICKNESS_SPREAD = 0.05


def shell_summary(report, seconds):
    """One line for people about the mid-surface shell: faces, nodes, thickness min/median/max, area against the walls'
    mean, time; a warning when the thickness varies by more than THICKNESS_SPREAD around the median."""
    s = report["shell"]
    t, area = s["thickness"], s["area"]
    kind = "quad8" if s["element_type"] == "S8R" else "quad4"
    text = ("{} {} shell faces, {} nodes. Thickness min {:.4g}, median {:.4g}, max {:.4g} mm (the ElementGeometry2D "
            "takes the median). Area {:.6g} mm2 ({:+.2f} % vs the walls' mean). {:.1f} s.").format(
        s["elements"], kind, s["nodes"], t["min"], t["median"], t["max"], area["shell"],
        100 * area["relative_error"], seconds)
    spread = max(t["max"] - t["median"], t["median"] - t["min"]) / t["median"] if t["median"] > 0 else 0
    if spread > THICKNESS_SPREAD:
        text += (" Warning: the thickness varies by {:.0f} % from the median, and FreeCAD takes one thickness per shell "
                 "section: split the part, or use the CLI's hexlayer mesh --shell, whose .inp has the thickness of "
                 "every node (*NODAL THICKNESS).").format(100 * spread)
    return text
