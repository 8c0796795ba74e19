"""Hex-Layer for FreeCAD macros: layered all-hex FEM meshes of thin solids.

    import HexLayer
    mesh = HexLayer.makeMesh(doc, part, Layers=2, Size=2.0)
    doc.recompute()   # meshes; mesh.Status says how it went, mesh.FemMesh holds the hexa20 (Order 2, the default)
                      # or hexa8 (Order 1) volumes

The method's stages as objects to look at (from the mesh's last meshing; meshes if needed):
    views = HexLayer.makeStageViews(mesh)   # {"ChordalSurface": ..., "QuadMesh": ..., "ExplodedLayers": ..., "Quality": ...}
or one of makeChordalSurface(mesh), makeQuadMesh(mesh), makeExplodedLayers(mesh, gap=None), makeQualityView(mesh).

Works in freecadcmd (no GUI) and in the GUI, where the mesh gets its view provider and task panel.
"""
import FreeCAD

from hexlayer_fem import meshing, mesh_object, stage_views

__all__ = ["makeMesh", "makeStageViews", "makeChordalSurface", "makeQuadMesh", "makeExplodedLayers", "makeQualityView",
           "writeCalculixMesh"]

makeStageViews = stage_views.make_stage_views
makeChordalSurface = stage_views.make_chordal_surface
makeQuadMesh = stage_views.make_quad_mesh
makeExplodedLayers = stage_views.make_exploded_layers
makeQualityView = stage_views.make_quality_view


def makeMesh(doc, part=None, name="HexLayerMesh", **properties):
    """Adds a Hex-Layer mesh of `part` to `doc` and returns it, not yet meshed (recompute meshes it).
    `properties` sets any of Layers, Size (mm), Sizing, Aspect, Order, Force."""
    unknown = sorted(set(properties) - set(mesh_object.MeshHexLayer.OPTIONS))
    if unknown:
        raise TypeError("makeMesh: unknown properties {}; use {}".format(
            unknown, ", ".join(mesh_object.MeshHexLayer.OPTIONS)))
    obj = doc.addObject("Fem::FemMeshObjectPython", name)
    mesh_object.MeshHexLayer(obj)
    obj.Part = part
    for key, value in properties.items():
        setattr(obj, key, value)
    if FreeCAD.GuiUp:
        from hexlayer_fem import view_provider
        view_provider.VPMeshHexLayer(obj.ViewObject)
    return obj


def writeCalculixMesh(mesh, path):
    """Writes the mesh's FemMesh to `path` for CalculiX, its hexa8 (Order 1) as C3D8I (incompatible modes, accurate in
    bending) instead of FreeCAD's C3D8: where FreeCAD's FemMesh.writeABAQUS can (FreeCAD 1.x), else RuntimeError."""
    meshing.write_calculix_mesh(mesh.FemMesh, path)
