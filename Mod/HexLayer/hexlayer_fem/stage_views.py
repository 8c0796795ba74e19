"""The method's stages as document objects to look at (paper §5-7, Figure 12): the chordal surface, its quad
mesh, the hex layers pulled apart along the sweep direction, and the hexes coloured by scaled Jacobian.

Each view is made from the result of the mesh object's last meshing (meshing again if it has none,
e.g. after the document was reopened) and put in a group "<mesh> stages"; making a view again replaces it.
The views show the hexes' corners (hexa8), also for an Order 2 mesh. No GUI needed; in the GUI the views get
their colours."""
import numpy as np

import FreeCAD
import Fem
import Mesh

from . import Stateless, meshing

STAGES = ("ChordalSurface", "QuadMesh", "ExplodedLayers", "Quality")
LAYER_COLOURS = ((0.31, 0.60, 0.18), (0.85, 0.55, 0.15), (0.20, 0.45, 0.80), (0.75, 0.25, 0.55))
# Scaled Jacobian -> colour: red at 0 (and dark red below: inverted), yellow at 0.5, green at 1.
QUALITY_STOPS = ((0.0, (0.85, 0.10, 0.10)), (0.5, (0.95, 0.85, 0.20)), (1.0, (0.15, 0.65, 0.25)))
INVERTED_COLOUR = (0.45, 0.0, 0.0)


def is_hexlayer_mesh(obj):
    """True for a Hex-Layer mesh object (HexLayer.makeMesh)."""
    return getattr(getattr(obj, "Proxy", None), "Type", None) == "Fem::MeshHexLayer"


def last_result(mesh_obj):
    """The meshing result (mesher.read_result) of the mesh object's last meshing: recomputes the object if it is out of date,
    meshes its Part again if this session has not meshed it. Raises the mesher's error if meshing fails."""
    if not is_hexlayer_mesh(mesh_obj):
        raise TypeError("'{}' is not a Hex-Layer mesh: make one with HexLayer.makeMesh".format(mesh_obj.Label))
    if {"Touched", "Invalid"} & set(mesh_obj.State):
        mesh_obj.recompute()
    if mesh_obj.Proxy.result is None:
        mesh_obj.Proxy.result = meshing.mesh(mesh_obj.Part, meshing.options(mesh_obj))
    return mesh_obj.Proxy.result


# ---- the stages as meshes ---------------------------------------------------------------------------

def chordal_triangles(facets):
    """The chordal facets (-1 padded quads and triangles) as triangles: a quad 0-1-2-3 gives 0-1-2 and 0-2-3."""
    quads = facets[facets[:, 3] >= 0]
    return np.vstack([facets[:, :3], quads[:, [0, 2, 3]]])


def chordal_mesh(result):
    """The chordal surface (§5) as a Mesh.Mesh."""
    surface = Mesh.Mesh()
    points = [FreeCAD.Vector(*p) for p in result.chordal_vertices.tolist()]
    surface.addFacets((points, [tuple(t) for t in chordal_triangles(result.chordal_facets).tolist()]))
    return surface


def quad_femmesh(result):
    """The quad mesh of the chordal surface as a FemMesh of quadrangle faces, ids 1-based in row order."""
    fem = Fem.FemMesh()
    for i, (x, y, z) in enumerate(result.quad_nodes.tolist(), start=1):
        fem.addNode(x, y, z, i)
    for i, quad in enumerate((result.quads + 1).tolist(), start=1):
        fem.addFace(quad, i)
    return fem


def hex_layers(result):
    """Layer of every hex (0 = on the bottom surface): the lowest layer of its corners that are in one (a rim
    cap's nodes inside the part are in none: -1); a cap hex none of whose corners is in a layer, the middle one."""
    layers = result.node_layer[result.hexes[:, :8]]
    top = int(result.node_layer.max())
    lowest = np.where(layers >= 0, layers, top + 1).min(axis=1)
    return np.where(lowest > top, top // 2, lowest)


def column_directions(nodes, corners):
    """Unit sweep direction of each hex: from its bottom quad's centre (corners 0-3) to its top quad's (4-7)."""
    d = nodes[corners[:, 4:]].mean(axis=1) - nodes[corners[:, :4]].mean(axis=1)
    return d / np.linalg.norm(d, axis=1, keepdims=True)


def node_directions(node_count, corners, directions):
    """Per node, the unit mean sweep direction of the hexes it is a corner of (zero for nodes of none)."""
    total = np.zeros((node_count, 3))
    np.add.at(total, corners.ravel(), np.repeat(directions, 8, axis=0))
    length = np.linalg.norm(total, axis=1, keepdims=True)
    return np.divide(total, length, out=np.zeros_like(total), where=length > 0)


def wall_thickness(result):
    """Median thickness of the hex columns: layers x the median hex height along its sweep direction."""
    corners = result.hexes[:, :8]
    heights = np.linalg.norm(result.nodes[corners[:, 4:]].mean(axis=1) - result.nodes[corners[:, :4]].mean(axis=1), axis=1)
    return float(np.median(heights)) * (int(result.node_layer.max()) or 1)


def exploded_layers(result, gap):
    """Per layer k (Figure 12(f)): (k, offset k x gap, nodes, hexes), the layer's hexa8 with their own nodes
    (0-based) moved by the offset along the local sweep direction."""
    layer_of = hex_layers(result)
    corners = result.hexes[:, :8]
    layers = []
    for k in range(int(layer_of.max()) + 1):
        hexes = corners[layer_of == k]
        used, local = np.unique(hexes, return_inverse=True)
        local = local.reshape(hexes.shape)
        directions = node_directions(len(used), local, column_directions(result.nodes, hexes))
        layers.append((k, k * gap, result.nodes[used] + k * gap * directions, local))
    return layers


def quality_colour(value):
    """The colour (r, g, b) of a scaled Jacobian, on QUALITY_STOPS."""
    if value <= 0:
        return INVERTED_COLOUR
    for (lo, c0), (hi, c1) in zip(QUALITY_STOPS, QUALITY_STOPS[1:]):
        if value <= hi:
            w = (value - lo) / (hi - lo)
            return tuple(a + w * (b - a) for a, b in zip(c0, c1))
    return QUALITY_STOPS[-1][1]


# ---- the document objects ---------------------------------------------------------------------------

def stage_group(mesh_obj):
    """The group "<mesh> stages" of the mesh object's views, made if missing."""
    doc = mesh_obj.Document
    for obj in doc.Objects:
        if getattr(obj, "StagesOf", None) is mesh_obj:
            return obj
    group = doc.addObject("App::DocumentObjectGroup", mesh_obj.Name + "Stages")
    group.Label = mesh_obj.Label + " stages"
    group.addProperty("App::PropertyLinkHidden", "StagesOf", "Hex-Layer", "The Hex-Layer mesh these views show")
    group.StagesOf = mesh_obj
    return group


def find_view(mesh_obj, stage):
    """The mesh object's view of `stage`, or None."""
    for group in mesh_obj.Document.Objects:
        if getattr(group, "StagesOf", None) is mesh_obj:
            return next((o for o in group.Group if getattr(o, "Stage", None) == stage), None)
    return None


def remove_view(mesh_obj, stage):
    """Removes the mesh object's view of `stage` (and what it groups), so that a view made again replaces it."""
    view = find_view(mesh_obj, stage)
    if view is not None:
        for child in getattr(view, "Group", []):
            view.Document.removeObject(child.Name)
        view.Document.removeObject(view.Name)


def add_view(mesh_obj, stage, type_id, label):
    """A new object of `type_id` for `stage` in the mesh's stage group, replacing the previous one."""
    remove_view(mesh_obj, stage)
    group = stage_group(mesh_obj)
    obj = mesh_obj.Document.addObject(type_id, mesh_obj.Name + stage)
    obj.Label = "{}: {}".format(mesh_obj.Label, label)
    obj.addProperty("App::PropertyString", "Stage", "Hex-Layer", "Which stage of the Hex-Layer method this shows")
    obj.Stage = stage
    obj.setEditorMode("Stage", 1)
    group.addObject(obj)
    return obj


def show_faces_and_edges(obj, colour):
    """In the GUI: faces in `colour` with their edges in a darker shade, lit from both sides."""
    if not FreeCAD.GuiUp:
        return
    vobj = obj.ViewObject
    vobj.ShapeColor = colour
    if obj.isDerivedFrom("Mesh::Feature"):
        vobj.DisplayMode = "Flat Lines"
        vobj.Lighting = "Two side"
        vobj.LineColor = tuple(0.6 * c for c in colour)
    else:
        vobj.DisplayMode = "Faces & Wireframe"


def make_surface_view(mesh_obj, stage, type_id, label, build, colour):
    """A view of a surface stage: an object of `type_id` whose Mesh or FemMesh is build(result)."""
    result = last_result(mesh_obj)
    obj = add_view(mesh_obj, stage, type_id, label)
    setattr(obj, "Mesh" if type_id.startswith("Mesh") else "FemMesh", build(result))
    show_faces_and_edges(obj, colour)
    return obj


def make_chordal_surface(mesh_obj):
    """The chordal surface (§5) as a Mesh::Feature (its quads split into two triangles)."""
    return make_surface_view(mesh_obj, "ChordalSurface", "Mesh::Feature", "chordal surface", chordal_mesh,
                             (0.95, 0.82, 0.42))


def make_quad_mesh(mesh_obj):
    """The quad mesh of the chordal surface (§6) as a Fem::FemMeshObject of quadrangles."""
    return make_surface_view(mesh_obj, "QuadMesh", "Fem::FemMeshObject", "quad mesh", quad_femmesh, (0.55, 0.77, 0.95))


def make_exploded_layers(mesh_obj, gap=None):
    """The hex layers pulled apart (Figure 12(f)): a group with one Fem::FemMeshObject per layer, layer k moved
    by Offset = k x gap along the local sweep direction; gap defaults to twice the wall thickness."""
    result = last_result(mesh_obj)
    gap = 2 * wall_thickness(result) if gap is None else gap
    group = add_view(mesh_obj, "ExplodedLayers", "App::DocumentObjectGroup", "exploded layers")
    for k, offset, nodes, hexes in exploded_layers(result, gap):
        layer = mesh_obj.Document.addObject("Fem::FemMeshObject", "{}Layer{}".format(mesh_obj.Name, k))
        layer.Label = "{}: layer {}".format(mesh_obj.Label, k + 1)
        layer.addProperty("App::PropertyInteger", "Layer", "Hex-Layer", "Hex layer, 0 = on the bottom side")
        layer.addProperty("App::PropertyLength", "Offset", "Hex-Layer", "How far this layer is moved along the sweep")
        layer.Layer, layer.Offset = k, offset
        layer.FemMesh = meshing.hexa_femmesh(nodes, hexes)
        group.addObject(layer)
        show_faces_and_edges(layer, LAYER_COLOURS[k % len(LAYER_COLOURS)])
    return group


class QualityView(Stateless):
    """View provider of the quality view: colours each hex by its ScaledJacobian (also after reopening)."""

    def __init__(self, vobj):
        vobj.Proxy = self

    def attach(self, vobj):
        self.Object = vobj.Object

    def updateData(self, obj, prop):
        if prop in ("FemMesh", "ScaledJacobian") and len(obj.ScaledJacobian) == obj.FemMesh.VolumeCount:
            self.colours = {i: quality_colour(v) for i, v in enumerate(obj.ScaledJacobian, start=1)}
            obj.ViewObject.ElementColor = self.colours  # FreeCAD 0.20 cannot read it back

    colours = None  # element id -> (r, g, b) as last set


def make_quality_view(mesh_obj):
    """The hexes coloured by Verdict scaled Jacobian: a Fem::FemMeshObjectPython whose ScaledJacobian holds the
    value of each hex (element id i: ScaledJacobian[i - 1]); red 0, yellow 0.5, green 1, dark red inverted."""
    result = last_result(mesh_obj)
    sj = result.scaled_jacobian
    label = "scaled Jacobian min {:.3f} avg {:.3f}".format(sj.min(), sj.mean()) if len(sj) else "scaled Jacobian"
    obj = add_view(mesh_obj, "Quality", "Fem::FemMeshObjectPython", label)
    obj.addProperty("App::PropertyFloatList", "ScaledJacobian", "Hex-Layer", "Verdict scaled Jacobian of each hex")
    obj.setEditorMode("ScaledJacobian", 1)
    if FreeCAD.GuiUp:
        QualityView(obj.ViewObject)
    obj.FemMesh = meshing.hexa_femmesh(result.nodes, result.hexes[:, :8])
    obj.ScaledJacobian = sj.tolist()
    if FreeCAD.GuiUp:
        obj.ViewObject.DisplayMode = "Faces & Wireframe"
    return obj


MAKERS = {"ChordalSurface": make_chordal_surface, "QuadMesh": make_quad_mesh,
          "ExplodedLayers": make_exploded_layers, "Quality": make_quality_view}


def make_stage_views(mesh_obj):
    """All four views; returns {stage: object}."""
    return {stage: make(mesh_obj) for stage, make in MAKERS.items()}
