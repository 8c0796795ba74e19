"""The workbench's commands: "Hex-Layer mesh" (FEM_MeshGmshFromShape's conventions)."""
import FreeCAD
import FreeCADGui

from . import icon, meshing


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


COMMANDS = {"HexLayer_Mesh": MeshCommand()}

for _name, _command in COMMANDS.items():
    FreeCADGui.addCommand(_name, _command)
