"""Task panel of the Hex-Layer mesh: the part and options, a Mesh button that runs the mesher as a child process
(QProcess: FreeCAD stays responsive), a progress bar and the stages' lines, Cancel, summary or error."""
import FreeCADGui
from PySide import QtCore, QtGui  # FreeCAD 0.20's PySide shim: the widgets are in QtGui

from . import icon, mesher, meshing

# The progress bar's steps per stage: a running stage that says how far it is (quad_mesh: its tries) moves it
# within its step.
BAR_STEPS = 100
ERROR_STYLE = "color: #c00000;"
# QProcess's crash status: PySide2 (FreeCAD 0.20) has it on the class, PySide6 (1.1) on its ExitStatus enum too.
CRASH_EXIT = getattr(QtCore.QProcess, "CrashExit", None) or QtCore.QProcess.ExitStatus.CrashExit
WARNING_STYLE = "color: #a05a00;"


def meshable_parts(doc, current):
    """The document's objects with a solid, and the current Part (whatever it is) first."""
    parts = [o for o in doc.Objects if o is not current and meshing.part_problem(o) is None]
    return ([current] if current is not None else []) + parts


class TaskPanel:
    def __init__(self, obj):
        self.obj = obj
        self.form = QtGui.QWidget()
        self.form.setObjectName("HexLayerTaskPanel")  # the widgets' object names are for tests and macros
        self.form.setWindowTitle("Hex-Layer mesh")
        self.form.setWindowIcon(QtGui.QIcon(icon("HexLayer_Mesh")))
        layout = QtGui.QVBoxLayout(self.form)
        layout.addLayout(self.make_fields())
        self.problem = self.label("problem", ERROR_STYLE)
        layout.addWidget(self.problem)
        self.warning = self.label("order_warning", WARNING_STYLE)
        layout.addWidget(self.warning)
        buttons = QtGui.QHBoxLayout()
        self.mesh_button = self.named(QtGui.QPushButton("Mesh"), "mesh")
        self.mesh_button.clicked.connect(self.mesh)
        self.cancel_button = self.named(QtGui.QPushButton("Cancel meshing"), "cancel")
        self.cancel_button.clicked.connect(self.cancel)
        self.cancel_button.setEnabled(False)
        buttons.addWidget(self.mesh_button)
        buttons.addWidget(self.cancel_button)
        layout.addLayout(buttons)
        self.bar = self.named(QtGui.QProgressBar(), "progress_bar")
        layout.addWidget(self.bar)
        layout.addWidget(QtGui.QLabel("Progress:"))
        self.progress = self.named(QtGui.QPlainTextEdit(), "progress")
        self.progress.setReadOnly(True)
        self.progress.setMaximumHeight(self.progress.fontMetrics().lineSpacing() * 12)  # the stages and a margin
        layout.addWidget(self.progress)
        self.summary = self.label("summary", "")
        layout.addWidget(self.summary)
        self.process = None  # the running mesher
        self.load()
        self.show_status()

    @staticmethod
    def named(widget, name):
        widget.setObjectName(name)
        return widget

    def label(self, name, style):
        label = self.named(QtGui.QLabel(), name)
        label.setWordWrap(True)
        label.setStyleSheet(style)
        return label

    def make_fields(self):
        fields = QtGui.QFormLayout()
        self.part = self.named(QtGui.QComboBox(), "part")
        self.layers = self.named(QtGui.QSpinBox(), "layers")
        self.layers.setRange(0, 999)  # the mesher says which counts it takes
        self.size = self.named(QtGui.QDoubleSpinBox(), "size")
        self.size.setRange(0.0, 1e6)
        self.size.setDecimals(3)
        self.size.setSuffix(" mm")
        self.size.setSpecialValueText("auto (wall thickness)")
        self.sizing = self.named(QtGui.QComboBox(), "sizing")
        self.sizing.addItems(list(meshing.SIZINGS))
        self.aspect = self.named(QtGui.QDoubleSpinBox(), "aspect")
        self.aspect.setRange(0.0, 1000.0)
        self.aspect.setSpecialValueText("off")
        self.order = self.named(QtGui.QSpinBox(), "order")
        self.order.setRange(1, 2)
        self.drop_junctions = self.named(QtGui.QCheckBox("leave out ribs and bosses"), "drop_junctions")
        for name, widget in (("Part", self.part), ("Layers", self.layers), ("Size", self.size),
                             ("Sizing", self.sizing), ("Aspect", self.aspect), ("Order", self.order),
                             ("Junctions", self.drop_junctions)):
            fields.addRow(name + ":", widget)
        self.part.currentIndexChanged.connect(self.check)
        self.sizing.currentIndexChanged.connect(self.check)
        for spin in (self.layers, self.size, self.aspect, self.order):
            spin.valueChanged.connect(self.check)
        return fields

    # ---- widgets <-> object --------------------------------------------------------------------

    def load(self):
        if self.obj.Part is None:
            self.part.addItem("(choose a solid)", "")
        for part in meshable_parts(self.obj.Document, self.obj.Part):
            self.part.addItem(part.Label if part.Label == part.Name else "{} ({})".format(part.Label, part.Name), part.Name)
        self.layers.setValue(self.obj.Layers)
        self.size.setValue(self.obj.Size.Value)
        self.sizing.setCurrentIndex(self.sizing.findText(self.obj.Sizing))
        self.aspect.setValue(self.obj.Aspect)
        self.order.setValue(self.obj.Order)
        self.drop_junctions.setChecked(self.obj.DropJunctions)
        self.check()

    def selected_part(self):
        name = self.part.itemData(self.part.currentIndex())
        return self.obj.Document.getObject(name) if name else None

    def options(self):
        return dict(layers=self.layers.value(), size=self.size.value(), sizing=self.sizing.currentText(),
                    aspect=self.aspect.value(), order=self.order.value(), drop_junctions=self.drop_junctions.isChecked())

    def apply(self):
        opts = self.options()
        self.obj.Part = self.selected_part()
        self.obj.Layers, self.obj.Size, self.obj.Sizing = opts["layers"], opts["size"], opts["sizing"]
        self.obj.Aspect, self.obj.Order = opts["aspect"], opts["order"]
        self.obj.DropJunctions = opts["drop_junctions"]

    # ---- checks, meshing, results ----------------------------------------------------------------

    def check(self):
        """Says in the panel why the part or the options cannot be meshed; Mesh only when they can."""
        problem = meshing.part_problem(self.selected_part()) or meshing.option_problem(self.options())
        self.problem.setText(problem or "")
        self.problem.setVisible(bool(problem))
        self.mesh_button.setEnabled(not problem)
        warning = meshing.order_warning(self.order.value())
        self.warning.setText(warning)
        self.warning.setVisible(bool(warning))

    def mesh(self):
        """Applies the options and starts the mesher as a child process; its stages fill the progress bar as they
        come, and when it ends the mesh object takes its answer (finished)."""
        self.apply()
        self.progress.clear()
        self.summary.clear()
        self.run = mesher.Run(self.obj.Part.Shape.exportBrepToString(), meshing.options(self.obj), self.obj.Force)
        self.stderr, self.partial, self.cancelled = [], "", False
        self.finished_stages = 0
        self.bar.setRange(0, BAR_STEPS * (len(mesher.STAGES) + (self.obj.Order == 2)))
        self.bar.setValue(0)
        self.bar.setFormat("%p%")
        self.process = QtCore.QProcess(self.form)
        self.process.readyReadStandardError.connect(self.read_progress)
        self.process.finished.connect(self.finished)
        command = self.run.command()
        self.set_running(True)
        self.process.start(command[0], command[1:])
        if not self.process.waitForStarted(10000):
            self.process = None
            self.set_running(False)
            self.run.discard()
            self.summary.setText("Failed: the mesher {} could not be started".format(command[0]))
            self.summary.setStyleSheet(ERROR_STYLE)

    def read_progress(self):
        try:
            data = bytes(self.process.readAllStandardError()) if self.process is not None else b""
        except RuntimeError:  # the panel, and its QProcess with it, was deleted while the run ended
            data = b""
        text = self.partial + data.decode(errors="replace")
        lines = text.split("\n")
        self.partial = lines.pop()
        for line in lines:
            stage, now = mesher.progress_text(line), mesher.running(line)
            if now is not None:
                self.show_running(*now)
            elif stage is None:
                self.stderr.append(line)
            else:
                self.progress.appendPlainText(stage)
                self.finished_stages += 1
                self.bar.setValue(min(BAR_STEPS * self.finished_stages, self.bar.maximum()))
                self.bar.setFormat("%p%")

    def show_running(self, stage, done, total):
        """The bar: the finished stages, and the running one's share (its done / total, if it says); its name."""
        share = done / total if total > 0 else 0
        self.bar.setValue(min(int(BAR_STEPS * (self.finished_stages + share)), self.bar.maximum()))
        self.bar.setFormat("{} %p%".format(stage))

    def finished(self, code, status):
        """The child ended: cancelled (nothing changes), or its mesh or error goes to the object by a recompute."""
        self.read_progress()
        self.stderr.append(self.partial)
        self.process, run = None, self.run
        self.set_running(False)
        if self.cancelled:
            run.discard()
            self.close_when_done = False
            self.summary.setText("Cancelled: the mesh and the document are as they were.")
            self.summary.setStyleSheet("")
            return
        try:
            self.obj.Proxy.answer = run.answer(code, "\n".join(self.stderr), crashed=status == CRASH_EXIT)
        except Exception as error:  # the object's execute raises it, as a recompute that meshed would
            self.obj.Proxy.answer = error
        self.obj.touch()
        self.obj.Document.recompute()
        self.show_status()
        if self.obj.isValid():
            self.obj.ViewObject.show()
            self.obj.Part.ViewObject.hide()
        if self.close_when_done:  # OK was pressed: close as it would have
            self.close()

    close_when_done = False  # OK started (or waits for) the run: the panel closes when it ends

    def cancel(self):
        """Ends the running mesher (within a second: it is killed); the mesh and the document stay as they were."""
        if self.process is not None:
            self.cancelled = True
            self.process.kill()
            self.process.waitForFinished(1000)

    def running(self):
        return self.process is not None

    def set_running(self, running):
        for widget in (self.mesh_button, self.part, self.layers, self.size, self.sizing, self.aspect, self.order,
                       self.drop_junctions):
            widget.setEnabled(not running)
        self.cancel_button.setEnabled(running)
        if not running:
            self.check()

    def show_status(self):
        self.summary.setText(self.obj.Status)
        self.summary.setStyleSheet("" if self.obj.isValid() else ERROR_STYLE)

    # ---- task dialog ---------------------------------------------------------------------------------

    def getStandardButtons(self):
        # The flags themselves: FreeCAD 1.1 (PySide6) wants the enum, 0.20 (PySide2) takes it as an int.
        return QtGui.QDialogButtonBox.Ok | QtGui.QDialogButtonBox.Cancel

    def accept(self):
        """OK: keeps the options. If they (or the part) changed since the last meshing, meshes first in the child
        process, as Mesh does (FreeCAD stays responsive), and closes when that ends; else closes now."""
        if self.running():
            self.close_when_done = True
            return False
        changed = (self.options() != meshing.options(self.obj) or self.selected_part() != self.obj.Part
                   or bool({"Touched", "Invalid"} & set(self.obj.State)))
        self.apply()
        if changed and not self.problem.text():
            self.close_when_done = True
            self.mesh()
            return False
        self.close()
        self.obj.Document.recompute()
        return True

    def reject(self):
        self.cancel()
        self.close()
        return True

    def close(self):
        FreeCADGui.getDocument(self.obj.Document).resetEdit()
