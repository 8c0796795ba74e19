"""View provider of the Hex-Layer mesh: its icon, and the task panel on double click or Edit."""
import FreeCAD
import FreeCADGui

from . import Stateless, icon


class IconViewProvider(Stateless):
    """A view provider with FEM's display modes and the workbench's icon ICON."""
    ICON = "HexLayer_Mesh"

    def __init__(self, vobj):
        vobj.Proxy = self

    def attach(self, vobj):
        self.Object = vobj.Object

    def getIcon(self):
        return icon(self.ICON)


class VPMeshHexLayer(IconViewProvider):

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



class VPShellHexLayer(IconViewProvider):
    """View provider of the mid-surface shell (no task panel: its properties)."""
    ICON = "HexLayer_QuadMesh"
