"""The mesher out of FreeCAD's process (hexlayer_fem/mesher.py): the workbench runs the hexlayer executable as a
child, needs no compiled module of its own, and a child that is killed or crashes is a message in Status.

Run: freecadcmd -t test_hexlayer_process -M tests/freecad (see hexlayer_testing for the environment).
"""
import os
import shutil
import stat
import subprocess
import tempfile
import textwrap
import unittest

import HexLayer
from hexlayer_fem import mesher

import hexlayer_testing as t


def fake_mesher(folder, body):
    """An executable shell script standing in for hexlayer."""
    path = os.path.join(folder, "hexlayer")
    with open(path, "w") as f:
        f.write("#!/bin/sh\n" + body + "\n")
    os.chmod(path, os.stat(path).st_mode | stat.S_IEXEC)
    return path


class MesherDies(unittest.TestCase):
    """A child killed from outside (SIGKILL) or crashing (SIGABRT) mid-run: the mesh object fails with the reason
    in Status, FreeCAD goes on, and the next meshing with the real mesher works."""

    def setUp(self):
        self.folder = tempfile.mkdtemp(prefix="hexlayer_fake_")
        self.addCleanup(shutil.rmtree, self.folder)
        self.addCleanup(os.environ.pop, "HEXLAYER_EXECUTABLE", None)
        self.addCleanup(mesher._check.cache_clear)

    def test_killed_or_crashed_child_is_a_message(self):
        doc = t.new_document(self)
        plate = t.add_plate(doc)
        for signal_name, body in (("SIGKILL", 'case "$1" in check) exit 0;; esac\necho "@progress geometry: 0.01 s" >&2\nkill -9 $$'),
                                  ("SIGABRT", 'case "$1" in check) exit 0;; esac\nkill -6 $$')):
            with self.subTest(signal_name):
                os.environ["HEXLAYER_EXECUTABLE"] = fake_mesher(self.folder, body)
                mesh = HexLayer.makeMesh(doc, plate)
                t.assert_fails(self, mesh, "the mesher stopped: killed by signal " + signal_name)
        os.environ.pop("HEXLAYER_EXECUTABLE")
        mesh = HexLayer.makeMesh(doc, plate)
        doc.recompute()
        self.assertTrue(mesh.isValid(), mesh.Status)
        self.assertGreater(mesh.FemMesh.VolumeCount, 0)

    def test_running_lines_are_parsed_not_taken_for_errors(self):
        self.assertEqual(mesher.running("@running quad_mesh 3 39\n"), ("quad_mesh", 3, 39))
        self.assertEqual(mesher.running("@running wall_sides"), ("wall_sides", 0, 0))
        self.assertIsNone(mesher.running("@progress quad_mesh: 1.20 s"))
        self.assertIsNone(mesher.running("hexlayer: error: x"))

    def test_progress_lines_come_per_stage(self):
        lines = []
        result = mesher.mesh_brep(t.add_plate(t.new_document(self)).Shape.exportBrepToString(), progress=lines.append,
                                  layers=2, size=0, sizing="adaptive", aspect=0, order=1, drop_junctions=False)
        stages = [line.split(":")[0] for line in lines]
        self.assertEqual([s for s in mesher.STAGES if s in stages], list(mesher.STAGES), "every stage, in order")
        self.assertEqual(result.report["hexes"], len(result.hexes))


class WithoutTheCompiledModule(unittest.TestCase):
    """The installed workbench with its pyhexlayer module removed, in a FreeCAD of its own: meshing, the FemMesh, the
    options check and the stage views all work, and pyhexlayer is never imported."""

    def test_workbench_needs_no_compiled_module(self):
        mod = os.path.dirname(os.path.dirname(os.path.abspath(mesher.__file__)))
        home = tempfile.mkdtemp(prefix="hexlayer_home_")
        self.addCleanup(shutil.rmtree, home)
        target = os.path.join(home, "share", "FreeCAD", "Mod", "HexLayer")
        shutil.copytree(mod, target, ignore=shutil.ignore_patterns("pyhexlayer*", "__pycache__"))
        script = os.path.join(home, "run.py")
        with open(script, "w") as f:
            f.write(textwrap.dedent("""
                import sys
                import FreeCAD
                import HexLayer
                from hexlayer_fem import meshing
                doc = FreeCAD.newDocument("NoModule")
                box = doc.addObject("Part::Box", "Plate")
                box.Length, box.Width, box.Height = 100, 20, 2
                mesh = HexLayer.makeMesh(doc, box)
                doc.recompute()
                views = HexLayer.makeStageViews(mesh)
                print("RESULT", mesh.isValid(), mesh.FemMesh.VolumeCount, mesh.Order, "pyhexlayer" in sys.modules,
                      sorted(views), meshing.option_problem(dict(layers=0, size=0, sizing="adaptive", aspect=0, order=2,
                                                                 drop_junctions=False)))
                """))
        env = dict(os.environ, HOME=home, XDG_DATA_HOME=os.path.join(home, "share"), PYTHONPATH="")
        done = subprocess.run(["freecadcmd", script], capture_output=True, text=True, timeout=300, env=env)
        line = [l for l in done.stdout.splitlines() if l.startswith("RESULT")]
        self.assertTrue(line, done.stdout[-2000:] + done.stderr[-2000:])
        self.assertIn("RESULT True", line[0])
        self.assertIn(" 2 False ['ChordalSurface', 'ExplodedLayers', 'QuadMesh', 'Quality']", line[0])
        self.assertIn("Layers must be between 1 and 64, got 0", line[0])
        hexes = int(line[0].split()[2])
        self.assertGreater(hexes, 0)
