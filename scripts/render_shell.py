"""Renders docs/shell_vs_hex.png for the README: the bundled hat section (Resources/samples/hat_holes.step) meshed by
the workbench as hexa20 in 2 layers (HexLayer.makeMesh) and, beside it, as its mid-surface shell of quad8 faces
(HexLayer.makeShellMesh), in FreeCAD's 3D view.

Run from the source folder, with the workbench installed (scripts/install-workbench.sh):
    QTWEBENGINE_DISABLE_SANDBOX=1 xvfb-run -a -s "-screen 0 1600x1000x24" freecad scripts/render_shell.py
"""
import os
import traceback

import FreeCAD
import FreeCADGui as Gui
import Part
from PySide import QtGui

OUT = os.path.join(os.getcwd(), "docs", "shell_vs_hex.png")
GAP = 80.0  # mm between the hexes and the shell, along x (the hat is 60 wide)


def settle():
    for _ in range(50):
        QtGui.QApplication.processEvents()


def render():
    import HexLayer
    doc = FreeCAD.newDocument("ShellVsHex")
    part = doc.addObject("Part::Feature", "Hat")
    part.Shape = Part.read(os.path.join(os.getcwd(), "Resources", "samples", "hat_holes.step"))
    hexes = HexLayer.makeMesh(doc, part, Layers=2)
    shell = HexLayer.makeShellMesh(doc, part)
    doc.recompute()
    print(hexes.Status, "\n", shell.Status)
    shell.Placement.Base = FreeCAD.Vector(GAP, 0, 0)
    part.ViewObject.Visibility = False
    for mesh in (hexes, shell):
        mesh.ViewObject.DisplayMode = "Faces & Wireframe"
    shell.ViewObject.ShapeColor = (0.35, 0.6, 0.9)
    view = Gui.ActiveDocument.ActiveView
    view.viewIsometric()
    view.fitAll()
    settle()
    FreeCAD.ParamGet("User parameter:BaseApp/Preferences/View").SetString("SavePicture", "GrabFramebuffer")
    view.saveImage(OUT, 1600, 800, "White")
    print("wrote", OUT)


try:
    render()
except BaseException:
    traceback.print_exc()
finally:
    os._exit(0)
