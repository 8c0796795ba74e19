"""The mid-surface shell (`hexlayer mesh --shell`, issue 20): the quad mesh of the chordal surface written as S4 /
S8R shell elements with *NODAL THICKNESS, node sets per CAD face; solved by CalculiX against references HexLayer
takes no part in (tests/python/ccx_tet10.py: the same CAD meshed by Gmsh in tet10 and solved as C3D10).

 - The 100 x 20 x 2 mm steel cantilever plate, 10 N at the tip in -z, as S8R (2 mm quads): clamped (every DOF) on the
   root's node set, the tip's node set loaded by the consistent nodal forces of a uniform edge load (1/6, 2/3, 1/6 of
   each element edge's share). The tet10 reference (size 1, all DOFs of the root face held, 10 N as a uniform
   traction on the tip face) gives -1.1687 mm, 0.07 % from the converged -1.1695 mm of the issue.
 - The wedge plate (80 x 40, thickness 1 at x = 0 to 4 at x = 80) clamped at its thick end and loaded at its thin
   end: the nodal thickness follows 1 + 3 x / 80, and the deflection is compared with the tet10 model.
 - Every sample part that meshes as hexes gives a shell: one element per quad, a thickness near the wall's, a node
   set on every CAD face, the plate's and the cylinder segment's area within 0.5 % of their mid-surface's; so do the
   real parts that mesh as hexes (the Ender-3 L-bracket without its bosses, the AnalysisSitus sheet-metal part).

Run by CTest as: /usr/bin/python3 test_shell.py --hexlayer PATH --source DIR
"""
import json
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

import harness
from inp import read_inp

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from ccx_tet10 import run_ccx, solve_tet10  # noqa: E402

E, NU, F = 210000.0, 0.3, 10.0
PLATE = (100.0, 20.0, 2.0)
TET_SIZE = 1.0  # mm, the plate's tet10 reference element size
WEDGE_TET_SIZE = 2.0  # mm, the wedge's (1 mm: -0.093777 mm, 0.07 % apart, 12 times the time)
SAMPLES = ("plate", "plate_holes", "cantilever", "lbracket", "uchannel", "hat_holes", "cylinder_shell",
           "spherical_cap", "housing", "twisted_strip", "wedge_plate")


def sample(name):
    return os.path.join(harness.args.source, "Resources", "samples", name + ".step")


def plate_step(path):
    """The 100 x 20 x 2 plate as a STEP file (Gmsh's OpenCASCADE)."""
    import gmsh
    gmsh.initialize(readConfigFiles=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.occ.addBox(0, 0, 0, *PLATE)
        gmsh.model.occ.synchronize()
        gmsh.write(path)
    finally:
        gmsh.finalize()
    return path


def read_thickness(path):
    """{node id: thickness} of the *NODAL THICKNESS block, and the *SHELL SECTION line."""
    thickness, section, reading = {}, None, False
    with open(path) as f:
        for line in f:
            if line.startswith("*"):
                reading = line.upper().startswith("*NODAL THICKNESS")
                section = line.strip() if line.upper().startswith("*SHELL SECTION") else section
            elif reading and line.strip():
                node, value = line.split(",")
                thickness[int(node)] = float(value)
    return thickness, section


def element_types(path):
    with open(path) as f:
        return {line.split("TYPE=")[1].split(",")[0] for line in f if line.upper().startswith("*ELEMENT")}


class Shell:
    """One `hexlayer mesh --shell` run: nodes, elements, node sets, thickness and the report."""

    def __init__(self, tmp, cad, *options):
        self.inp = os.path.join(tmp, os.path.basename(cad) + ".inp")
        report = self.inp + ".json"
        done = subprocess.run([harness.args.hexlayer, "mesh", cad, "-o", self.inp, "--shell", "--report", report,
                               *options], capture_output=True, text=True, timeout=900)
        self.returncode, self.stdout, self.stderr = done.returncode, done.stdout, done.stderr
        if done.returncode != 0:
            return
        self.nodes, self.elements, self.sets = read_inp(self.inp)
        self.thickness, self.section = read_thickness(self.inp)
        with open(report) as f:
            self.report = json.load(f)

    def set_at(self, axis, value):
        """The one FACEk node set whose nodes all lie at coordinate `axis` = value."""
        found = [name for name, ids in self.sets.items() if name.startswith("FACE") and ids
                 and all(abs(self.nodes[n][axis] - value) < 1e-6 for n in ids)]
        if len(found) != 1:
            raise AssertionError("expected one face set at {} = {}, found {}".format("xyz"[axis], value, found))
        return self.sets[found[0]]


def edge_weights(shell, on_edge):
    """{node: length share} of the shell's boundary edges whose nodes are all in on_edge: consistent nodal weights
    of a uniform line load (S8R: 1/6, 2/3, 1/6 of the edge's length; S4: 1/2, 1/2)."""
    weights = {}
    for _, ids in shell.elements:
        corners, mids = ids[:4], ids[4:]
        for k in range(4):
            a, b = corners[k], corners[(k + 1) % 4]
            edge = (a, b, mids[k]) if mids else (a, b)
            if not all(n in on_edge for n in edge):
                continue
            length = np.linalg.norm(np.subtract(shell.nodes[a], shell.nodes[b]))
            shares = (1 / 6, 1 / 6, 2 / 3) if mids else (0.5, 0.5)
            for n, s in zip(edge, shares):
                weights[n] = weights.get(n, 0.0) + s * length
    return weights


def solve_shell(tmp, shell, root, tip, force):
    """The shell deck: steel, every DOF of `root` held, `force` (3,) spread over the edge `tip` by edge_weights.
    Returns the load-weighted mean displacement of the tip (3,)."""
    weights = edge_weights(shell, set(tip))
    total = sum(weights.values())
    with open(os.path.join(tmp, "job.inp"), "w") as job:
        job.write("*MATERIAL, NAME=SHELL_MATERIAL\n*ELASTIC\n{!r}, {!r}\n".format(E, NU))
        job.write("*INCLUDE, INPUT={}\n".format(shell.inp))
        job.write("*NSET, NSET=ROOT\n" + "".join("{},\n".format(n) for n in root))
        job.write("*NSET, NSET=TIP\n" + "".join("{},\n".format(n) for n in tip))
        job.write("*BOUNDARY\nROOT, 1, 6\n*STEP\n*STATIC\n*CLOAD\n")
        job.write("".join("{}, {}, {:.12e}\n".format(n, d + 1, force[d] * w / total)
                          for n, w in sorted(weights.items()) for d in range(3) if force[d]))
        job.write("*NODE PRINT, NSET=TIP\nU\n*END STEP\n")
    u = run_ccx(tmp)
    return sum(u[n] * w for n, w in weights.items()) / total


class CantileverPlate(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.step = plate_step(os.path.join(cls.tmp.name, "plate.step"))
        cls.reference = solve_tet10(cls.step, TET_SIZE, lambda c: abs(c[0]) < 1e-6,
                                    lambda c: abs(c[0] - PLATE[0]) < 1e-6, (0.0, 0.0, -F), (E, NU))

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def deflection(self, order):
        with tempfile.TemporaryDirectory() as tmp:
            shell = Shell(tmp, self.step, "--order", str(order))
            self.assertEqual(shell.returncode, 0, shell.stderr[-2000:])
            self.assertEqual(element_types(shell.inp), {"S8R" if order == 2 else "S4"})
            root, tip = shell.set_at(0, 0.0), shell.set_at(0, PLATE[0])
            return solve_shell(tmp, shell, root, tip, (0.0, 0.0, -F))[2]

    def test_s8r_tip_deflection_within_2_percent_of_the_converged_solid(self):
        delta = self.deflection(2)
        reference = self.reference.area_mean[2]
        print("\nS8R shell: tip deflection {:.5f} mm, Gmsh tet10 ({} nodes) {:.5f} mm, ratio {:.4f}; converged "
              "-1.1695 mm: ratio {:.4f}".format(delta, self.reference.nodes, reference, delta / reference,
                                               delta / -1.1695))
        self.assertLess(reference, 0)
        self.assertAlmostEqual(delta / reference, 1.0, delta=0.02)

    def test_s4_tip_deflection_within_2_percent(self):
        # S4, not S4R: CalculiX expands S4R into C3D8R, whose hourglass modes bent this plate 28 times too far
        delta = self.deflection(1)
        print("\nS4 shell: tip deflection {:.5f} mm, ratio to tet10 {:.4f}".format(
            delta, delta / self.reference.area_mean[2]))
        self.assertAlmostEqual(delta / self.reference.area_mean[2], 1.0, delta=0.02)


class WedgePlate(unittest.TestCase):
    """80 x 40, flat bottom z = 0, thickness 1 at x = 0 to 4 at x = 80."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.shell = Shell(cls.tmp.name, sample("wedge_plate"), "--order", "2")

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_nodal_thickness_follows_the_wedge(self):
        self.assertEqual(self.shell.returncode, 0, self.shell.stderr[-2000:])
        x = np.array([self.shell.nodes[n][0] for n in sorted(self.shell.thickness)])
        t = np.array([self.shell.thickness[n] for n in sorted(self.shell.thickness)])
        error = np.abs(t / (1 + 3 * x / 80) - 1)
        print("\nwedge: nodal thickness {:.4f} .. {:.4f}, largest error {:.3%}".format(t.min(), t.max(), error.max()))
        self.assertLess(error.max(), 0.005)
        self.assertIn("NODAL THICKNESS", self.shell.section)

    def test_deflection_within_2_percent_of_the_solid(self):
        with tempfile.TemporaryDirectory() as tmp:
            delta = solve_shell(tmp, self.shell, self.shell.set_at(0, 80.0), self.shell.set_at(0, 0.0),
                                (0.0, 0.0, -F))[2]
        reference = solve_tet10(sample("wedge_plate"), WEDGE_TET_SIZE, lambda c: abs(c[0] - 80) < 1e-6,
                                lambda c: abs(c[0]) < 1e-6, (0.0, 0.0, -F), (E, NU))
        print("\nwedge S8R: thin-end deflection {:.5f} mm, Gmsh tet10 ({} nodes) {:.5f} mm, ratio {:.4f}".format(
            delta, reference.nodes, reference.area_mean[2], delta / reference.area_mean[2]))
        self.assertAlmostEqual(delta / reference.area_mean[2], 1.0, delta=0.02)


class Samples(unittest.TestCase):
    def test_every_sample_gives_a_shell(self):
        for name in SAMPLES:
            with self.subTest(name), tempfile.TemporaryDirectory() as tmp:
                shell = Shell(tmp, sample(name), "--order", "2")
                self.assertEqual(shell.returncode, 0, shell.stderr[-2000:])
                r = shell.report
                s = r["shell"]
                self.assertEqual(s["elements"], r["quad_mesh"]["quads"])
                self.assertEqual(len(shell.elements), s["elements"])
                self.assertTrue(all(len(ids) == 8 for _, ids in shell.elements))
                self.assertEqual(sorted(shell.thickness), sorted(shell.nodes), "a thickness at every node")
                self.assertGreater(min(shell.thickness.values()), 0)
                if name != "wedge_plate":  # 1 -> 4: WedgePlate checks every node against the wedge's law
                    self.assertAlmostEqual(s["thickness"]["median"] / r["thickness"], 1.0, delta=0.1)
                faces = r["surface_groups"]["cad_faces"]
                empty = [k for k in range(1, faces + 1) if not shell.sets.get("FACE{}".format(k))]
                self.assertEqual(empty, [], "a node set on every CAD face")
                self.assertTrue(shell.sets["RIM"])
                print("\n{}: {} S8R, thickness {:.3f} / {:.3f} / {:.3f}, area {:.2f} vs walls' mean {:.2f} "
                      "({:+.3%})".format(name, s["elements"], *[s["thickness"][k] for k in ("min", "median", "max")],
                                          s["area"]["shell"], s["area"]["cad_mid_surface"],
                                          s["area"]["relative_error"]))
                if name in ("plate", "plate_holes", "cantilever", "cylinder_shell"):
                    self.assertLess(abs(s["area"]["relative_error"]), 0.005)

    def test_real_parts_give_a_shell(self):
        # the real parts that mesh as hexes (test_real_parts.py): the LCD support without its bosses, the sheet-metal
        # part with rounded flange corners
        parts = (("ender3_lcd_support_Lbracket.step", 2.0), ("analysissitus_sheet_metal_54_SHELLONLY.brep", 1.2))
        for name, wall in parts:
            with self.subTest(name), tempfile.TemporaryDirectory() as tmp:
                part = os.path.join(harness.args.source, "..", "shared", "parts", "real", name)
                shell = Shell(tmp, part, "--order", "2", "--drop-junctions")
                self.assertEqual(shell.returncode, 0, shell.stderr[-2000:])
                s = shell.report["shell"]
                print("\n{}: {} S8R, thickness {:.3f} / {:.3f} / {:.3f}, area {:+.3%} vs the walls' mean".format(
                    name, s["elements"], *[s["thickness"][k] for k in ("min", "median", "max")],
                    s["area"]["relative_error"]))
                self.assertEqual(s["elements"], shell.report["quad_mesh"]["quads"])
                self.assertAlmostEqual(s["thickness"]["median"] / wall, 1.0, delta=0.01)
                self.assertLess(abs(s["area"]["relative_error"]), 0.01)
                self.assertTrue(shell.sets["RIM"])

    def test_vtu_and_msh_hold_8_node_quads_and_the_thickness(self):
        import meshio
        with tempfile.TemporaryDirectory() as tmp:
            for ext in ("vtu", "msh"):
                out = os.path.join(tmp, "plate." + ext)
                done = subprocess.run([harness.args.hexlayer, "mesh", sample("plate"), "-o", out, "--shell",
                                       "--order", "2", "--quiet"], capture_output=True, text=True, timeout=600)
                self.assertEqual(done.returncode, 0, done.stderr)
                m = meshio.read(out)
                self.assertEqual(list(m.cells_dict), ["quad8"])
                self.assertTrue(np.allclose(m.points[:, 2], 1.0), "on the mid-plane of the 2 mm plate")
                self.assertTrue(np.allclose(m.point_data["thickness"], 2.0))


if __name__ == "__main__":
    harness.main()
