"""Hex-Layer for FreeCAD macros: layered all-hex FEM meshes of thin solids.

    import HexLayer
    mesh = HexLayer.makeMesh(doc, part, Layers=2, Size=2.0)
    doc.recompute()   # meshes; mesh.Status says how it went, mesh.FemMesh holds the hexa20 (Order 2, the default)
                      # or hexa8 (Order 1) volumes

The method's stages as objects to look at (from the mesh's last meshing; meshes if needed):
    views = HexLayer.makeStageViews(mesh)   # {"ChordalSurface": ..., "QuadMesh": ..., "ExplodedLayers": ..., "Quality": ...}
or one of makeChordalSurface(mesh), makeQuadMesh(mesh), makeExplodedLayers(mesh, gap=None), makeQualityView(mesh).

The mid-surface shell of a thin solid, as FEM shell faces with its thickness:
    shell = HexLayer.makeShellMesh(doc, part, Order=2)
    doc.recompute()   # shell.FemMesh: quad8 faces; shell.ElementGeometry (an ElementGeometry2D): the median thickness

Works in freecadcmd (no GUI) and in the GUI, where the mesh gets its view provider and task panel.
"""
import FreeCAD

from hexlayer_fem import meshing, mesh_object, shell_object, stage_views

__all__ = ["makeMesh", "makeStageViews", "makeChordalSurface", "makeQuadMesh", "makeExplodedLayers", "makeQualityView",
           "writeCalculixMesh", "makeShellMesh"]

makeStageViews = stage_views.make_stage_views
makeChordalSurface = stage_views.make_chordal_surface
makeQuadMesh = stage_views.make_quad_mesh
makeExplodedLayers = stage_views.make_exploded_layers
makeQualityView = stage_views.make_quality_view


def _make_mesh_object(doc, part, name, proxy_class, properties, maker):
    """A Fem::FemMeshObjectPython with proxy_class's proxy on `part`, `properties` (of proxy_class.OPTIONS) set."""
    unknown = sorted(set(properties) - set(proxy_class.OPTIONS))
    if unknown:
        raise TypeError("{}: unknown properties {}; use {}".format(maker, unknown, ", ".join(proxy_class.OPTIONS)))
    obj = doc.addObject("Fem::FemMeshObjectPython", name)
    proxy_class(obj)
    obj.Part = part
    for key, value in properties.items():
        setattr(obj, key, value)
    return obj


def makeMesh(doc, part=None, name="HexLayerMesh", **properties):
    """Adds a Hex-Layer mesh of `part` to `doc` and returns it, not yet meshed (recompute meshes it).
    `properties` sets any of Layers, Size (mm), Sizing, Aspect, Order, Force."""
    obj = _make_mesh_object(doc, part, name, mesh_object.MeshHexLayer, properties, "makeMesh")
    if FreeCAD.GuiUp:
        from hexlayer_fem import view_provider
        view_provider.VPMeshHexLayer(obj.ViewObject)
    return obj


def makeShellMesh(doc, part=None, name="HexLayerShell", **properties):
    """Adds the mid-surface shell of `part` to `doc` (a FEM mesh of quad8 faces, quad4 with Order=1) and an
    ElementGeometry2D it sets to the measured median thickness (mesh.ElementGeometry); returns the mesh, not yet meshed
    (recompute meshes it). `properties` sets any of Order, Size (mm), Sizing, DropJunctions."""
    import ObjectsFem
    obj = _make_mesh_object(doc, part, name, shell_object.ShellMeshHexLayer, properties, "makeShellMesh")
    if FreeCAD.GuiUp:
        from hexlayer_fem import view_provider
        view_provider.VPShellHexLayer(obj.ViewObject)
    obj.ElementGeometry = ObjectsFem.makeElementGeometry2D(doc, 1.0, name + "Thickness")
    return obj


def writeCalculixMesh(mesh, path):
    """Writes the mesh's FemMesh to `path` for CalculiX, its hexa8 (Order 1) as C3D8I (incompatible modes, accurate in
    bending) instead of FreeCAD's C3D8: where FreeCAD's FemMesh.writeABAQUS can (FreeCAD 1.x), else RuntimeError."""
    meshing.write_calculix_mesh(mesh.FemMesh, path)
