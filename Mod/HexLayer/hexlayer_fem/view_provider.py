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
        FreeCADGui.Control.showDialog(TaskPanel(vobj.Object))
        return True

    def unsetEdit(self, vobj, mode=0):
        FreeCADGui.Control.closeDialog()
        return True

    def doubleClicked(self, vobj):
        guidoc = FreeCADGui.getDocument(vobj.Object.Document)
        if guidoc.getInEdit():
            FreeCAD.Console.PrintError("Hex-Layer: another task panel is open: close it first.\n")
        else:
            guidoc.setEdit(vobj.Object.Name)
        return True
