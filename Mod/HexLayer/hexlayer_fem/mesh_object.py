"""The Hex-Layer mesh: a Fem::FemMeshObjectPython whose recompute meshes its Part (FEM's MeshGmsh conventions)."""
import time

import FreeCAD
import Fem

from . import Stateless, meshing


class MeshHexLayer(Stateless):
    """Proxy of the mesh object: properties Part, Layers, Size, Sizing, Aspect, Order, DropJunctions, Force and the read-only Status."""

    Type = "Fem::MeshHexLayer"
    OPTIONS = ("Layers", "Size", "Sizing", "Aspect", "Order", "DropJunctions", "Force")  # the properties the mesher takes besides Part

    def __init__(self, obj):
        obj.Proxy = self
        self.add_properties(obj)

    def add_properties(self, obj):
        """Adds the properties the object does not have yet (also for files saved by older versions)."""
        def add(kind, name, doc, value):
            if not hasattr(obj, name):
                obj.addProperty(kind, name, "Hex-Layer", doc)
                setattr(obj, name, value)
        add("App::PropertyLink", "Part", "Thin solid to mesh (an object with a Shape holding a solid)", None)
        add("App::PropertyInteger", "Layers", "Hex layers through the wall thickness (1-64)", 2)
        add("App::PropertyLength", "Size", "Quad edge length on the mid-surface; 0 = the wall thickness", 0.0)
        add("App::PropertyEnumeration", "Sizing", "Element sizing: uniform, or adaptive to the wall thickness and curvature",
            list(meshing.SIZINGS))
        add("App::PropertyFloat", "Aspect", "In-plane size / layer thickness instead of Size (Size must then be 0); 0 = off", 0.0)
        # Order 2 by default: FreeCAD writes hexa8 as fully integrated C3D8, which is too stiff in bending
        # (meshing.ORDER1_WARNING); FreeCAD's own Gmsh and Netgen meshers default to second order too.
        add("App::PropertyInteger", "Order", "Element order: 2 = hexa20 (wall mid-edge nodes on the CAD walls), "
            "1 = hexa8 (written as C3D8: too stiff in bending, see Status)", 2)
        add("App::PropertyBool", "DropJunctions",
            "Mesh the largest sheet and leave out ribs, bosses and flanges standing on it (else a straight rib on a "
            "flat rectangular plate is meshed with it, the others are refused)", False)
        add("App::PropertyBool", "Force", "Keep a mesh that fails its validation (an inverted hex, a crack, the volume), "
            "with the failures in Status", False)
        add("App::PropertyString", "Status", "Summary of the last meshing, or why it failed", "")
        obj.setEditorMode("Status", 1)  # read-only

    def onDocumentRestored(self, obj):
        self.add_properties(obj)

    def execute(self, obj):
        """Meshes the Part (or takes the answer the task panel's run got for it); on failure the FemMesh is emptied
        (no stale mesh reaches a solver) and the error raised."""
        start = time.perf_counter()
        try:
            answer, self.answer = self.answer, None
            if isinstance(answer, Exception):
                raise answer
            result = answer or meshing.mesh(obj.Part, meshing.options(obj), progress=self.progress, force=obj.Force)
        except Exception as error:
            self.result = None
            obj.FemMesh = Fem.FemMesh()
            obj.Status = "Failed: " + meshing.for_people(str(error))
            raise
        self.result = result  # the stages and quality of the last meshing, for the stage views (not saved)
        obj.FemMesh = meshing.femmesh(result)
        obj.Status = meshing.summary(result.report, time.perf_counter() - start)

    answer = None  # a result or error the task panel's run got for the object as it is, for the next execute
    result = None  # meshing result (mesher.read_result) of the last meshing in this session

    @staticmethod
    def progress(line):
        FreeCAD.Console.PrintLog("Hex-Layer: {}\n".format(line))
