# Hex-Layer workbench, GUI start-up: one toolbar and one menu with the Hex-Layer commands.
import FreeCADGui

import hexlayer_fem


class HexLayerWorkbench(FreeCADGui.Workbench):
    MenuText = "Hex-Layer"
    ToolTip = "Layered all-hex FEM meshes of thin solids (sheet metal, housings, brackets) for FEM analyses"
    Icon = hexlayer_fem.icon("HexLayerWorkbench")

    def Initialize(self):
        from hexlayer_fem import commands
        self.appendToolbar("Hex-Layer", list(commands.COMMANDS))
        self.appendMenu("&Hex-Layer", list(commands.COMMANDS))

    def GetClassName(self):
        return "Gui::PythonWorkbench"


FreeCADGui.addWorkbench(HexLayerWorkbench())
