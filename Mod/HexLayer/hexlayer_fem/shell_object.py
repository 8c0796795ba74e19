"""The mid-surface shell (issue 20): a Fem::FemMeshObjectPython whose recompute meshes its Part's chordal surface as
shell faces (quad8 for Order 2, quad4 for Order 1) and sets the linked ElementGeometry2D's Thickness to the measured
median wall thickness. FreeCAD takes one thickness per shell section: Status warns when the part's varies by more than
5 % (the CLI's `hexlayer mesh --shell` writes every node's thickness instead)."""
import time

import FreeCAD
import Fem

from . import Stateless, meshing


def options(obj):
    """The mesher's options for the shell object: its Order, Size, Sizing and DropJunctions (layers do not matter)."""
    return dict(layers=2, size=obj.Size.Value, sizing=obj.Sizing, aspect=0.0, order=obj.Order,
                drop_junctions=obj.DropJunctions, shell=True)


class ShellMeshHexLayer(Stateless):
    """Proxy of the shell mesh object: Part, Order, Size, Sizing, DropJunctions, ElementGeometry, and the read-only
    Thickness (median), ThicknessMin, ThicknessMax and Status."""

    Type = "Fem::ShellMeshHexLayer"
    OPTIONS = ("Order", "Size", "Sizing", "DropJunctions")

    def __init__(self, obj):
        obj.Proxy = self
        self.add_properties(obj)

    def add_properties(self, obj):
        def add(kind, name, doc, value, read_only=False):
            if not hasattr(obj, name):
                obj.addProperty(kind, name, "Hex-Layer shell", doc)
                setattr(obj, name, value)
            if read_only:
                obj.setEditorMode(name, 1)
        add("App::PropertyLink", "Part", "Thin solid whose mid-surface is meshed", None)
        add("App::PropertyInteger", "Order", "2 = quad8 (S8), mid-side nodes on the chordal surface; 1 = quad4", 2)
        add("App::PropertyLength", "Size", "Quad edge length on the mid-surface; 0 = the wall thickness", 0.0)
        add("App::PropertyEnumeration", "Sizing", "Element sizing: uniform, or adaptive to the wall thickness and curvature",
            list(meshing.SIZINGS))
        add("App::PropertyBool", "DropJunctions",
            "Mesh the largest sheet and leave out ribs, bosses and flanges standing on it (else meshing refuses them)", False)
        add("App::PropertyLink", "ElementGeometry", "The ElementGeometry2D whose Thickness is set to the median", None)
        add("App::PropertyLength", "Thickness", "Median wall thickness over the shell's nodes", 0.0, True)
        add("App::PropertyLength", "ThicknessMin", "Smallest wall thickness at a shell node", 0.0, True)
        add("App::PropertyLength", "ThicknessMax", "Largest wall thickness at a shell node", 0.0, True)
        add("App::PropertyString", "Status", "Summary of the last meshing, or why it failed", "", True)

    def onDocumentRestored(self, obj):
        self.add_properties(obj)

    def execute(self, obj):
        """Meshes the Part's mid-surface; on failure the FemMesh is emptied and the error raised."""
        start = time.perf_counter()
        try:
            result = meshing.mesh(obj.Part, options(obj), progress=self.progress)
        except Exception as error:
            obj.FemMesh = Fem.FemMesh()
            obj.Status = "Failed: " + meshing.for_people(str(error))
            raise
        obj.FemMesh = meshing.shell_femmesh(result)
        thickness = result.report["shell"]["thickness"]
        obj.Thickness, obj.ThicknessMin, obj.ThicknessMax = thickness["median"], thickness["min"], thickness["max"]
        if obj.ElementGeometry is not None:
            obj.ElementGeometry.Thickness = thickness["median"]
            obj.ElementGeometry.purgeTouched()  # set from here: nothing of its own to recompute
        obj.Status = meshing.shell_summary(result.report, time.perf_counter() - start)

    @staticmethod
    def progress(line):
        FreeCAD.Console.PrintLog("Hex-Layer shell: {}\n".format(line))
