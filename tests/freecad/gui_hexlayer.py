"""The Hex-Layer workbench in FreeCAD's GUI: toolbar and menu, the command and its task panel on a sample part,
bad selections, screenshots of the panel and of the meshed part.

Run (CTest does, see tests/CMakeLists.txt):
    QTWEBENGINE_DISABLE_SANDBOX=1 xvfb-run -a -s "-screen 0 1920x1200x24" \
        freecad -P tests/python -P tests/freecad tests/freecad/gui_hexlayer.py
FreeCAD imports this file once its main window is up; it ends FreeCAD with exit code 0 if every test passed.
HEXLAYER_SCREENSHOTS: folder for freecad_panel.png and freecad_mesh.png (the README's are made with docs/).
"""
import os
import sys
import tempfile
import traceback
import unittest

import FreeCAD
import FreeCADGui as Gui
from PySide import QtCore, QtGui

SCREENSHOTS = os.environ.get("HEXLAYER_SCREENSHOTS") or tempfile.mkdtemp(prefix="hexlayer_gui_")


def settle():
    for _ in range(10):
        QtGui.QApplication.processEvents()


def panel():
    """The open Hex-Layer task panel's form, or None."""
    form = Gui.getMainWindow().findChild(QtGui.QWidget, "HexLayerTaskPanel")
    return form if form is not None and form.isVisible() else None


def widget(name, kind=QtGui.QWidget):
    return panel().findChild(kind, name)


def mesh_command():
    from hexlayer_fem import commands
    return commands.COMMANDS["HexLayer_Mesh"]


def distinct_colours(path):
    """How many colours an image has (on a grid of samples): a blank screenshot has one or two."""
    image = QtGui.QImage(path)
    return len({image.pixel(x, y) for x in range(0, image.width(), 7) for y in range(0, image.height(), 7)})


class GuiTest(unittest.TestCase):
    """Each test: a new document, the workbench active, no task panel open at the end."""

    def setUp(self):
        Gui.activateWorkbench("HexLayerWorkbench")
        self.doc = t.new_document(self)
        self.addCleanup(self.close_panel)
        Gui.Selection.clearSelection()

    def close_panel(self):
        if Gui.Control.activeDialog():
            Gui.Control.closeDialog()
        settle()

    def add_analysis(self):
        import FemGui
        import ObjectsFem
        analysis = ObjectsFem.makeAnalysis(self.doc, "Analysis")
        FemGui.setActiveAnalysis(analysis)
        return analysis

    def run_command(self, selected=None):
        """Selects `selected` (if any) and runs "Hex-Layer mesh" as the toolbar button does."""
        if selected is not None:
            Gui.Selection.addSelection(self.doc.Name, selected.Name)
        Gui.runCommand("HexLayer_Mesh")
        settle()
        self.assertIsNotNone(panel(), "the task panel opened")
        return self.doc.ActiveObject

    def press_mesh(self):
        widget("mesh", QtGui.QPushButton).click()
        settle()

    def problem(self):
        label = widget("problem", QtGui.QLabel)
        return label.text() if label.isVisible() else ""


class Workbench(GuiTest):
    def test_toolbar_and_menu_hold_the_command(self):
        window = Gui.getMainWindow()
        toolbars = [b for b in window.findChildren(QtGui.QToolBar) if b.windowTitle() == "Hex-Layer"]
        self.assertEqual(len(toolbars), 1)
        self.assertIn("Hex-Layer mesh", [a.text() for a in toolbars[0].actions()])
        menus = [m for m in window.menuBar().actions() if m.text() == "&Hex-Layer"]
        self.assertEqual([a.text() for a in menus[0].menu().actions()], ["Hex-Layer mesh"])


class BadSelections(GuiTest):
    def test_nothing_selected_and_no_analysis_leaves_the_command_inactive(self):
        t.add_plate(self.doc)
        self.assertFalse(mesh_command().IsActive())

    def test_nothing_selected_in_an_analysis_asks_for_the_part(self):
        plate = t.add_plate(self.doc)
        self.add_analysis()
        self.assertTrue(mesh_command().IsActive())
        self.run_command()
        self.assertIn("No part to mesh", self.problem())
        self.assertFalse(widget("mesh").isEnabled())
        part = widget("part", QtGui.QComboBox)
        self.assertEqual(part.itemData(1), plate.Name, "the panel offers the document's solids")
        part.setCurrentIndex(1)
        self.assertEqual(self.problem(), "")
        self.assertTrue(widget("mesh").isEnabled())

    def test_sketch_is_refused_in_the_panel(self):
        import Part
        import Sketcher  # noqa: F401
        sketch = self.doc.addObject("Sketcher::SketchObject", "Sketch")
        sketch.addGeometry(Part.LineSegment(FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(10, 0, 0)))
        self.doc.recompute()
        Gui.Selection.addSelection(self.doc.Name, sketch.Name)
        self.assertFalse(mesh_command().IsActive(), "a sketch is no solid")
        self.add_analysis()
        self.run_command(sketch)
        self.assertIn("'Sketch'", self.problem())
        self.assertIn("not a solid", self.problem())
        self.assertFalse(widget("mesh").isEnabled())

    def test_both_orders_are_offered_in_the_panel(self):
        self.run_command(t.add_plate(self.doc))
        order = widget("order", QtGui.QSpinBox)
        self.assertEqual((order.minimum(), order.maximum()), (1, 2))
        order.setValue(2)
        self.assertEqual(self.problem(), "")
        self.assertTrue(widget("mesh").isEnabled())

    def test_thick_block_fails_in_the_panel_and_the_document_goes_on(self):
        block = t.add_sample(self.doc, "thick_block.step")
        mesh = self.run_command(block)
        self.press_mesh()
        summary = widget("summary", QtGui.QLabel).text()
        self.assertIn("Failed", summary)
        self.assertIn("not a thin section", summary)
        self.assertFalse(mesh.isValid())
        plate = t.add_plate(self.doc)  # the same panel meshes a thin part next
        self.close_panel()
        Gui.ActiveDocument.setEdit(mesh.Name)
        settle()
        part = widget("part", QtGui.QComboBox)
        part.setCurrentIndex(part.findData(plate.Name))
        self.press_mesh()
        self.assertTrue(mesh.isValid(), mesh.Status)
        self.assertIn("hexes", widget("summary", QtGui.QLabel).text())


class MeshSamplePart(GuiTest):
    """The hat section with holes, meshed through the panel inside an analysis; screenshots for the README."""

    def test_mesh_through_the_panel(self):
        analysis = self.add_analysis()
        part = t.add_sample(self.doc, "hat_holes.step")
        Gui.SendMsgToActiveView("ViewFit")
        self.assertTrue(mesh_command().IsActive())
        mesh = self.run_command(part)
        self.assertIn(mesh, analysis.Group, "the mesh joins the active analysis")
        self.press_mesh()
        stages = widget("progress", QtGui.QPlainTextEdit).toPlainText().splitlines()
        self.assertGreaterEqual(len(stages), 9, "one line per stage")
        summary = widget("summary", QtGui.QLabel).text()
        self.assertIn("{} hexes".format(mesh.FemMesh.VolumeCount), summary)
        self.assertIn("Scaled Jacobian min", summary)
        self.assertGreater(mesh.FemMesh.VolumeCount, 1000)
        self.save_panel(os.path.join(SCREENSHOTS, "freecad_panel.png"))
        self.save_view(mesh, os.path.join(SCREENSHOTS, "freecad_mesh.png"))

    def save_panel(self, path):
        """The task view down to the panel's end (OK/Cancel, title, panel), widened: the summary on few lines."""
        window = Gui.getMainWindow()
        dock = window.findChild(QtGui.QDockWidget, "Combo View")
        window.resizeDocks([dock], [440], QtCore.Qt.Horizontal)
        settle()
        form = task_view = panel()
        while task_view.metaObject().className() != "Gui::TaskView::TaskView":
            task_view = task_view.parentWidget()
        bottom = form.mapTo(task_view, QtCore.QPoint(0, form.height())).y() + 16  # not the empty rest below
        self.assertTrue(task_view.grab(QtCore.QRect(0, 0, task_view.width(), bottom)).save(path))
        self.assertGreater(distinct_colours(path), 10)

    def save_view(self, mesh, path):
        """The 3D view as on screen: isometric, the part filling it, hexes with their edges."""
        Gui.Control.closeDialog()
        mesh.ViewObject.DisplayMode = "Faces & Wireframe"
        view = Gui.ActiveDocument.ActiveView
        view.viewIsometric()
        view.fitAll()
        camera = view.getCameraNode()
        camera.height.setValue(camera.height.getValue() * 0.8)  # fitAll leaves room for the bounding sphere
        settle()
        # The on-screen framebuffer: FreeCAD's default off-screen one draws the edges half hidden on Mesa.
        FreeCAD.ParamGet("User parameter:BaseApp/Preferences/View").SetString("SavePicture", "GrabFramebuffer")
        view.saveImage(path, *view.getSize(), "Current")
        self.assertGreater(distinct_colours(path), 10)


def main():
    Gui.getMainWindow().showMaximized()
    settle()
    result = unittest.TextTestRunner(stream=sys.stderr, verbosity=2).run(
        unittest.defaultTestLoader.loadTestsFromModule(sys.modules[__name__]))
    print("screenshots in", SCREENSHOTS, file=sys.stderr)
    return 0 if result.wasSuccessful() else 1


if __name__ in ("__main__", "gui_hexlayer"):  # FreeCAD imports the file it is given
    code = 1
    try:
        import hexlayer_testing as t  # here, so that a missing path ends FreeCAD too
        code = main()
    except BaseException:
        traceback.print_exc()
    finally:
        sys.stderr.flush()
        sys.stdout.flush()
        os._exit(code)
