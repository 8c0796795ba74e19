"""The workbench's commands: "Hex-Layer mesh" (FEM_MeshGmshFromShape's conventions), "Mid-surface shell" and the
stage views."""
import FreeCAD
import FreeCADGui

from . import icon, meshing, stage_views


def active_analysis():
    """The active FEM analysis of the active document, or None."""
    import FemGui
    analysis = FemGui.getActiveAnalysis()
    return analysis if analysis is not None and analysis.Document is FreeCAD.ActiveDocument else None


def selected_part():
    """The first selected object with a solid, else the first selected object, else None."""
    selection = FreeCADGui.Selection.getSelection()
    solids = [o for o in selection if meshing.part_problem(o) is None]
    return (solids or selection or [None])[0]


class MeshCommand:
    """Adds a Hex-Layer mesh of the selected solid (to the active analysis, if any) and opens its task panel."""

    def GetResources(self):
        return {"Pixmap": icon("HexLayer_Mesh"),
                "MenuText": "Hex-Layer mesh",
                "ToolTip": "Layered all-hex (hexa8) FEM mesh of the selected thin solid, added to the active analysis.\n"
                           "Select a solid, or activate an analysis and choose the solid in the task panel."}

    def IsActive(self):
        if FreeCAD.ActiveDocument is None:
            return False
        return meshing.part_problem(selected_part()) is None or active_analysis() is not None

    def Activated(self):
        if FreeCAD.ActiveDocument is None:
            FreeCAD.Console.PrintError("Hex-Layer mesh: open a document with a thin solid first.\n")
            return
        part = selected_part()
        problem = meshing.part_problem(part)
        if problem:  # the task panel says it too, and lists the solids to choose from
            FreeCAD.Console.PrintWarning("Hex-Layer mesh: {}\n".format(problem))
        FreeCAD.ActiveDocument.openTransaction("Hex-Layer mesh")
        FreeCADGui.addModule("HexLayer")
        FreeCADGui.doCommand("hexlayer_mesh = HexLayer.makeMesh(App.ActiveDocument, {})".format(
            "App.ActiveDocument.getObject('{}')".format(part.Name) if part else "None"))
        if active_analysis() is not None:
            FreeCADGui.addModule("FemGui")
            FreeCADGui.doCommand("FemGui.getActiveAnalysis().addObject(hexlayer_mesh)")
        FreeCAD.ActiveDocument.commitTransaction()
        FreeCADGui.Selection.clearSelection()
        FreeCADGui.doCommand("Gui.ActiveDocument.setEdit(hexlayer_mesh.Name)")


class ShellCommand:
    """Adds the mid-surface shell of the selected solid and its ElementGeometry2D (to the active analysis, if any) and
    meshes it."""

    def GetResources(self):
        return {"Pixmap": icon("HexLayer_QuadMesh"),
                "MenuText": "Mid-surface shell",
                "ToolTip": "FEM shell mesh (quad8) of the selected thin solid's mid-surface, with an ElementGeometry2D\n"
                           "holding its measured thickness, added to the active analysis."}

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None and meshing.part_problem(selected_part()) is None

    def Activated(self):
        part = selected_part()
        FreeCAD.ActiveDocument.openTransaction("Mid-surface shell")
        FreeCADGui.addModule("HexLayer")
        FreeCADGui.doCommand("hexlayer_shell = HexLayer.makeShellMesh(App.ActiveDocument, "
                             "App.ActiveDocument.getObject('{}'))".format(part.Name))
        if active_analysis() is not None:
            FreeCADGui.addModule("FemGui")
            FreeCADGui.doCommand("FemGui.getActiveAnalysis().addObject(hexlayer_shell)")
            FreeCADGui.doCommand("FemGui.getActiveAnalysis().addObject(hexlayer_shell.ElementGeometry)")
        FreeCAD.ActiveDocument.commitTransaction()
        # a failed meshing leaves the object empty with the reason in its Status, printed either way
        FreeCADGui.doCommand("App.ActiveDocument.recompute()")
        FreeCADGui.doCommand("App.Console.PrintMessage('Mid-surface shell: ' + hexlayer_shell.Status + '\\n')")


def selected_mesh():
    """The first selected Hex-Layer mesh object, or None."""
    meshes = [o for o in FreeCADGui.Selection.getSelection() if stage_views.is_hexlayer_mesh(o)]
    return (meshes or [None])[0]


class StageViewCommand:
    """Makes one stage view of the selected Hex-Layer mesh and shows it alone (the mesh and its part hidden)."""

    def __init__(self, stage, menu_text, tool_tip):
        self.stage, self.menu_text, self.tool_tip = stage, menu_text, tool_tip

    def GetResources(self):
        return {"Pixmap": icon("HexLayer_" + self.stage), "MenuText": self.menu_text,
                "ToolTip": self.tool_tip + "\nSelect a Hex-Layer mesh first."}

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None and selected_mesh() is not None

    def Activated(self):
        mesh = selected_mesh()
        FreeCADGui.addModule("HexLayer")
        FreeCAD.ActiveDocument.openTransaction(self.menu_text)
        error = None
        try:
            FreeCADGui.doCommand("HexLayer.{}(App.ActiveDocument.getObject('{}'))".format(STAGE_API[self.stage], mesh.Name))
        except Exception as e:
            error = e
        view = stage_views.find_view(mesh, self.stage)
        if view is None:  # the mesher's message; the document stays as it was
            FreeCAD.ActiveDocument.abortTransaction()
            FreeCAD.Console.PrintError("{}: {}\n".format(self.menu_text, meshing.for_people(str(error or mesh.Status))))
            return
        FreeCAD.ActiveDocument.commitTransaction()
        show_alone(view, mesh)


def show_alone(view, mesh):
    """Shows `view` (and its members), hides the mesh, its part and the other stage views; fits the 3D view."""
    group = stage_views.stage_group(mesh)
    for obj in [mesh, mesh.Part] + group.Group:
        if obj is not None and obj is not view:
            obj.ViewObject.Visibility = False
    for obj in [view] + list(getattr(view, "Group", [])):
        obj.ViewObject.Visibility = True
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.SendMsgToActiveView("ViewFit")


STAGE_API = {"ChordalSurface": "makeChordalSurface", "QuadMesh": "makeQuadMesh",
             "ExplodedLayers": "makeExplodedLayers", "Quality": "makeQualityView"}

COMMANDS = {
    "HexLayer_Mesh": MeshCommand(),
    "HexLayer_ShellMesh": ShellCommand(),
    "HexLayer_ChordalSurface": StageViewCommand(
        "ChordalSurface", "Chordal surface", "Show the chordal surface (mid-surface cut through the tets) the quads were made on."),
    "HexLayer_QuadMesh": StageViewCommand(
        "QuadMesh", "Quad mesh", "Show the quad mesh of the chordal surface that the sweep turned into hexes."),
    "HexLayer_ExplodedLayers": StageViewCommand(
        "ExplodedLayers", "Exploded layers", "Show the hex layers pulled apart along the sweep direction."),
    "HexLayer_Quality": StageViewCommand(
        "Quality", "Quality view", "Colour the hexes by scaled Jacobian: green 1, yellow 0.5, red 0, dark red inverted."),
}

for _name, _command in COMMANDS.items():
    FreeCADGui.addCommand(_name, _command)
