"""CalculiX solves the .inp of a meshed cantilever strip (100 x 10 x 2 mm, steel): the tip deflection
under an end load must match Euler-Bernoulli beam theory, delta = F L^3 / (3 E I), within 3 % (2 mm quads, 2 layers of C3D8I).

Run by CTest as: /usr/bin/python3 test_calculix_cantilever.py --hexlayer PATH --source DIR
"""
import os
import subprocess
import tempfile
import unittest

import harness

L, B, T = 100.0, 10.0, 2.0   # length (x), width (y), thickness (z) of Resources/samples/cantilever.step
E, NU, F = 210000.0, 0.3, 10.0


def read_nodes(inp):
    nodes, in_nodes = {}, False
    with open(inp) as f:
        lines = f.readlines()
    for line in lines:
        if line.startswith("*"):
            in_nodes = line.upper().startswith("*NODE")
            continue
        if in_nodes and line.strip():
            i, x, y, z = line.split(",")[:4]
            nodes[int(i)] = (float(x), float(y), float(z))
    return nodes


def tip_deflection(dat, tip):
    uz, reading = [], False
    with open(dat) as f:
        lines = f.readlines()
    for line in lines:
        if "displacements" in line:
            reading = True
            continue
        parts = line.split()
        if reading and len(parts) == 4 and parts[0].isdigit() and int(parts[0]) in tip:
            uz.append(float(parts[3]))
    return sum(uz) / len(uz)


class CalculixCantilever(unittest.TestCase):
    def test_tip_deflection_matches_beam_theory(self):
        with tempfile.TemporaryDirectory() as tmp:
            inp = os.path.join(tmp, "mesh.inp")
            step = os.path.join(harness.args.source, "Resources", "samples", "cantilever.step")
            done = subprocess.run([harness.args.hexlayer, "mesh", step, "-o", inp, "--layers", "2", "--size", "2", "--quiet"],
                                  capture_output=True, text=True, timeout=600)
            self.assertEqual(done.returncode, 0, done.stderr[-2000:])
            nodes = read_nodes(inp)
            fixed = [i for i, p in nodes.items() if abs(p[0]) < 1e-6]
            tip = [i for i, p in nodes.items() if abs(p[0] - L) < 1e-6]
            self.assertGreater(len(fixed), 4)
            self.assertGreater(len(tip), 4)
            with open(os.path.join(tmp, "job.inp"), "w") as job:
                job.write(f"*INCLUDE, INPUT={inp}\n")
                job.write(f"*MATERIAL, NAME=STEEL\n*ELASTIC\n{E}, {NU}\n*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n")
                job.write("*NSET, NSET=FIXED\n" + "".join(f"{i},\n" for i in fixed))
                job.write("*NSET, NSET=TIP\n" + "".join(f"{i},\n" for i in tip))
                # Clamp without blocking the Poisson contraction of the root section (beam theory has none):
                # u_x and u_z held on the root face, u_y on one root node only.
                job.write(f"*BOUNDARY\nFIXED, 1, 1\nFIXED, 3, 3\n{fixed[0]}, 2, 2\n*STEP\n*STATIC\n*CLOAD\n")
                job.write("".join(f"{i}, 3, {F / len(tip)}\n" for i in tip))
                job.write("*NODE PRINT, NSET=TIP\nU\n*END STEP\n")
            solved = subprocess.run(["ccx", "-i", "job"], cwd=tmp, capture_output=True, text=True, timeout=600,
                                    env={**os.environ, "OMP_NUM_THREADS": "1"})
            self.assertEqual(solved.returncode, 0, solved.stdout[-2000:])
            delta = tip_deflection(os.path.join(tmp, "job.dat"), set(tip))
            beam = F * L ** 3 / (3 * E * B * T ** 3 / 12)
            print(f"tip deflection {delta:.5f} mm, beam theory {beam:.5f} mm, ratio {delta / beam:.4f}")
            self.assertAlmostEqual(delta / beam, 1.0, delta=0.03)


if __name__ == "__main__":
    harness.main()
