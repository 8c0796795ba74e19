# Hex-Layer workbench, GUI start-up: one toolbar and one menu with the Hex-Layer commands.
# FreeCAD runs this file with names of its own top level out of the class's sight: import where used.
import FreeCADGui


class HexLayerWorkbench(FreeCADGui.Workbench):
    MenuText = "Hex-Layer"
    ToolTip = "Layered all-hex FEM meshes of thin solids (sheet metal, housings, brackets) for FEM analyses"
    Icon = __import__("hexlayer_fem").icon("HexLayerWorkbench")

    def Initialize(self):
        from hexlayer_fem import commands
        self.appendToolbar("Hex-Layer", list(commands.COMMANDS))
        self.appendMenu("&Hex-Layer", list(commands.COMMANDS))

    def GetClassName(self):
        return "Gui::PythonWorkbench"


FreeCADGui.addWorkbench(HexLayerWorkbench())
