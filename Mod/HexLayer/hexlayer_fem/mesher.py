"""The `hexlayer` executable, run as a child process: the workbench meshes out of FreeCAD's process, so a crash in
OpenCASCADE, TetGen or Gmsh is a message, not a lost session, and the workbench needs no compiled module of its
own (it loads in any FreeCAD, whatever its Python, Qt or OpenCASCADE).

The part goes to the child as a BREP file (FreeCAD's face numbering kept); the child writes its progress on stderr
(`--machine`): "@progress <stage>: <seconds> s" per finished stage (and notes), "@running <stage>" when a stage
starts and "@running <stage> <done> <total>" as a long one goes on (a few times a second at most); and its whole
result as a JSON index and a binary
file of arrays (`--result`), read back here into arrays named as pyhexlayer.MeshResult's. Its exit code becomes the error class pyhexlayer raises.
No GUI and no FreeCAD needed: the task panel runs the same command line with QProcess (task_panel.py).
"""
import functools
import json
import os
import shutil
import signal
import subprocess
import tempfile
import types

import numpy as np

BUNDLED = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "bin", "hexlayer")
PROGRESS = "@progress "
RUNNING = "@running "
# The stages the child reports one line each for (pipeline.cpp), for a progress bar; "quadratic" with Order 2.
STAGES = ("geometry", "wall_sides", "mixed_faces", "bubbles", "tets", "tet_filter", "chordal_surface", "chordal_rim",
          "quad_mesh", "sweep", "rim", "rim_cap", "smoothing", "surface_groups", "quality")


class HexLayerError(Exception):
    """The mesher refused or failed; `code` is the CLI's exit code (pyhexlayer's classes have the same names)."""
    code = 5


class UsageError(HexLayerError):
    code = 2


class InputError(HexLayerError):
    code = 3


class GeometryError(HexLayerError):
    code = 4


class ValidationError(HexLayerError):
    code = 6


class MesherStopped(HexLayerError):
    """The child ended without an answer: killed, crashed, or cancelled."""


ERRORS = {cls.code: cls for cls in (UsageError, InputError, GeometryError, ValidationError)}


def executable():
    """The hexlayer executable: $HEXLAYER_EXECUTABLE, else the one installed with the workbench (bin/), else PATH's."""
    for candidate in (os.environ.get("HEXLAYER_EXECUTABLE"), BUNDLED, shutil.which("hexlayer")):
        if candidate and os.path.isfile(candidate) and os.access(candidate, os.X_OK):
            return candidate
    raise MesherStopped("the hexlayer executable is not installed: run scripts/install-workbench.sh "
                        "(it copies it to {})".format(BUNDLED))


def option_arguments(opts, force=False):
    """The CLI arguments of the workbench's options (meshing.options: layers, size, sizing, aspect, order,
    drop_junctions; shell: the mid-surface shell too)."""
    args = ["--layers", str(opts["layers"]), "--sizing", str(opts["sizing"]), "--order", str(opts["order"])]
    if opts.get("size", 0) > 0:
        args += ["--size", repr(float(opts["size"]))]
    if opts.get("aspect", 0) != 0:
        args += ["--aspect", repr(float(opts["aspect"]))]
    if opts.get("drop_junctions"):
        args.append("--drop-junctions")
    if opts.get("shell"):
        args.append("--shell")
    if force:
        args.append("--force")
    return args


@functools.lru_cache(maxsize=256)
def _check(arguments):
    done = subprocess.run([executable(), "check"] + list(arguments), capture_output=True, text=True, timeout=60)
    return done.returncode, error_message(done.stderr)


def check_options(**opts):
    """Raises UsageError with the CLI's message if an option value is not supported (`hexlayer check`)."""
    code, message = _check(tuple(option_arguments(opts)))
    if code != 0:
        raise ERRORS.get(code, HexLayerError)(message)


def error_message(stderr, part_file=None):
    """The child's error without its "hexlayer: error: " prefix, the temporary file named as the part."""
    lines = stderr.strip().splitlines()
    errors = [line.split("error: ", 1)[1] for line in lines if line.startswith(("hexlayer: error: ", "hexlayer: internal error: "))]
    message = errors[-1] if errors else (lines[-1] if lines else "the mesher gave no message")
    return message.replace("'{}'".format(part_file), "the part") if part_file else message


class Run:
    """One meshing of a BREP text in a private folder: its command line, and reading its answer."""

    def __init__(self, brep_text, opts, force=False):
        self.folder = tempfile.mkdtemp(prefix="hexlayer_")
        self.part = os.path.join(self.folder, "part.brep")
        with open(self.part, "w") as f:
            f.write(brep_text)
        self.result_file = os.path.join(self.folder, "result.json")
        self.arguments = ["mesh", self.part, "-o", os.path.join(self.folder, "mesh.vtu"), "--result", self.result_file,
                          "--machine"] + option_arguments(opts, force)

    def command(self):
        return [executable()] + self.arguments

    def answer(self, returncode, stderr, crashed=False):
        """The result (arrays named as pyhexlayer.MeshResult's), or the error the exit code stands for: a negative
        code is the signal that ended the child; `crashed` without one (QProcess does not say which)."""
        try:
            if crashed:
                raise MesherStopped("the mesher stopped: it crashed or was killed (nothing was changed)")
            if returncode == 0 and os.path.isfile(self.result_file):
                return read_result(self.result_file)
            if returncode is not None and returncode < 0:
                raise MesherStopped("the mesher stopped: killed by signal {} (nothing was changed)".format(signal_name(-returncode)))
            raise ERRORS.get(returncode, HexLayerError)(error_message(stderr, self.part))
        finally:
            self.discard()

    def discard(self):
        """Removes the run's folder (the part, the result)."""
        shutil.rmtree(self.folder, ignore_errors=True)


def signal_name(number):
    try:
        return signal.Signals(number).name
    except ValueError:
        return str(number)


def read_result(path):
    """The --result files (a JSON index and the arrays' binary file beside it) as an object with NumPy arrays, under
    pyhexlayer.MeshResult's names and shapes."""
    with open(path) as f:
        index = json.load(f)
    raw = np.fromfile(os.path.join(os.path.dirname(path), index["binary"]), dtype=np.uint8)

    def array(name):
        a = index["arrays"][name]
        count = int(np.prod(a["shape"])) if a["shape"] else 0
        return np.frombuffer(raw, dtype=np.dtype(a["dtype"]), count=count, offset=a["offset"]).reshape(a["shape"]).copy()

    def group(prefix):
        return {name[len(prefix):]: array(name) for name in index["arrays"] if name.startswith(prefix)}

    names = ("nodes", "hexes", "scaled_jacobian", "chordal_vertices", "chordal_facets", "quad_nodes", "quads", "node_layer")
    # the mid-surface shell, with --shell: as pyhexlayer's shell_* (shell_node_sets: RIM and Face1..FaceN)
    shell = ("shell_nodes", "shell_elements", "shell_thickness")
    return types.SimpleNamespace(report=index["report"], node_sets=group("node_sets/"), face_nodes=group("face_nodes/"),
                                 face_elements=group("face_elements/"),
                                 shell_node_sets=dict(group("shell_node_sets/"), **group("shell_face_nodes/")),
                                 **{name: array(name) for name in names + shell if name in index["arrays"]})


def progress_text(line):
    """The stage's text of one of the child's stderr lines ("geometry: 0.02 s"), or None for any other line."""
    return line[len(PROGRESS):].rstrip("\n") if line.startswith(PROGRESS) else None


def running(line):
    """The running stage of one of the child's stderr lines: (stage, done, total), total 0 if it has said nothing of
    how far it is; None for any other line."""
    if not line.startswith(RUNNING):
        return None
    words = line[len(RUNNING):].split()
    if len(words) == 3 and words[1].isdigit() and words[2].isdigit():
        return words[0], int(words[1]), int(words[2])
    return (words[0], 0, 0) if len(words) == 1 else None


def mesh_brep(brep_text, progress=None, force=False, **opts):
    """Meshes the BREP text in a child process (blocking: the headless path and macros); `progress` gets each
    finished stage's line as the child reports it."""
    run = Run(brep_text, opts, force)
    child = subprocess.Popen(run.command(), stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    stderr = []
    for line in child.stderr:
        stage = progress_text(line)
        if stage is None and running(line) is None:
            stderr.append(line)
        elif stage is not None and progress is not None:
            progress(stage)
    return run.answer(child.wait(), "".join(stderr))
