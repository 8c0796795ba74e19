"""A FreeCAD part meshed with pyhexlayer, and the result as a FemMesh. No GUI: usable from freecadcmd."""
import re

import Fem
import pyhexlayer

# SMESH orders a hexa8's bottom quad the other way round from CalculiX and HexLayer; FreeCAD's
# writeABAQUS maps it back, so this order gives the C3D8 elements it writes positive volumes.
SMESH_HEXA8 = (0, 3, 2, 1, 4, 7, 6, 5)

# The values the mesh object's Sizing property offers; pyhexlayer.check_options says which are supported today.
SIZINGS = ("uniform", "adaptive")


def options(obj):
    """pyhexlayer's keyword options from the mesh object's properties."""
    return dict(layers=obj.Layers, size=obj.Size.Value, sizing=obj.Sizing, aspect=obj.Aspect, order=obj.Order)


def for_people(message):
    """A message naming CLI options ("--order must be ...") in the property editor's words ("Order must be ...")."""
    return re.sub(r"--(\w)(\w*)", lambda m: m.group(1).upper() + m.group(2), message)


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
    """Why pyhexlayer refuses these options, in the property editor's words, or None."""
    try:
        pyhexlayer.check_options(**opts)
    except pyhexlayer.UsageError as error:
        return for_people(str(error))
    return None


def mesh(part, opts, progress=None):
    """pyhexlayer.MeshResult of the part's shape; the BREP text keeps FreeCAD's face numbering."""
    problem = part_problem(part)
    if problem:
        raise pyhexlayer.InputError(problem)
    return pyhexlayer.mesh_brep(part.Shape.exportBrepToString(), progress=progress, **opts)


def femmesh(result):
    """A FemMesh of hexa8 volumes and the node groups TOP, BOTTOM and RIM (ids 1-based, as FreeCAD's)."""
    fem = Fem.FemMesh()
    for i, (x, y, z) in enumerate(result.nodes.tolist(), start=1):
        fem.addNode(x, y, z, i)
    for i, hexa in enumerate((result.hexes[:, SMESH_HEXA8] + 1).tolist(), start=1):
        fem.addVolume(hexa, i)
    for name, nodes in result.node_sets.items():
        fem.addGroupElements(fem.addGroup(name, "Node"), (nodes + 1).tolist())
    return fem


def summary(report, seconds):
    """One line for people: hexes, scaled Jacobian min/avg, volume error, time."""
    sj, volume = report["scaled_jacobian"], report["volume"]
    text = "{} hexes, {} nodes, {} layers. Scaled Jacobian min {:.3f}, avg {:.3f}. Volume {:+.2f} % vs CAD. {:.1f} s.".format(
        report["hexes"], report["nodes"], report["layers"], sj["min"], sj["avg"], 100 * volume["relative_error"], seconds)
    if report["inverted_hexes"]:
        text += " {} inverted hexes: not fit for a solver.".format(report["inverted_hexes"])
    return text
