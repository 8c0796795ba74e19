"""View provider of the Hex-Layer mesh: its icon, and the task panel on double click or Edit."""
import FreeCAD
import FreeCADGui

from . import Stateless, icon


class VPMeshHexLayer(Stateless):
    def __init__(self, vobj):
        vobj.Proxy = self

    def attach(self, vobj):
        self.Object = vobj.Object

    def getIcon(self):
        return icon("HexLayer_Mesh")

    def setEdit(self, vobj, mode=0):
        if mode != 0:
            return None  # other edit modes (transform) as for any object
        from .task_panel import TaskPanel
        self.panel = TaskPanel(vobj.Object)
        FreeCADGui.Control.showDialog(self.panel)
        return True

    def unsetEdit(self, vobj, mode=0):
        if self.panel is not None:
            self.panel.cancel()  # a run still going ends with its panel
            self.panel = None
        FreeCADGui.Control.closeDialog()
        return True

    panel = None  # the open task panel (not saved)

    def doubleClicked(self, vobj):
        guidoc = FreeCADGui.getDocument(vobj.Object.Document)
        if guidoc.getInEdit():
            FreeCAD.Console.PrintError("Hex-Layer: another task panel is open: close it first.\n")
        else:
            guidoc.setEdit(vobj.Object.Name)
        return True


class VPShellHexLayer(Stateless):
    """View provider of the mid-surface shell: FEM's display modes and its icon (no task panel: its properties)."""

    def __init__(self, vobj):
        vobj.Proxy = self

    def attach(self, vobj):
        self.Object = vobj.Object

    def getIcon(self):
        return icon("HexLayer_QuadMesh")
