"""Determinism (issue 5): the same input and options give byte-identical .inp, .vtu and .msh files, whatever
the number of OpenMP threads.

Run by CTest as: /usr/bin/python3 test_determinism.py --hexlayer PATH --source DIR
"""
import hashlib
import os
import subprocess
import tempfile
import unittest

import harness


def digest(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


class Determinism(unittest.TestCase):
    def mesh(self, step, out, threads, *options):
        env = dict(os.environ, OMP_NUM_THREADS=str(threads))
        done = subprocess.run([harness.args.hexlayer, "mesh", step, "-o", out, "--quiet", *options],
                              capture_output=True, text=True, timeout=600, env=env)
        self.assertEqual(done.returncode, 0, done.stderr[-2000:])
        self.assertGreater(os.path.getsize(out), 1000)
        return digest(out)

    def check_twice(self, sample, formats, *options):
        step = os.path.join(harness.args.source, "Resources", "samples", sample)
        with tempfile.TemporaryDirectory() as tmp:
            for ext in formats:
                with self.subTest(sample=sample, format=ext, options=options):
                    first = self.mesh(step, os.path.join(tmp, "a." + ext), 1, *options)
                    second = self.mesh(step, os.path.join(tmp, "b." + ext), 2, *options)
                    self.assertEqual(first, second)

    def test_plate_with_holes_in_every_format(self):
        self.check_twice("plate_holes.step", ("inp", "vtu", "msh"), "--layers", "3")

    def test_adaptive_quadratic_l_bracket(self):
        self.check_twice("lbracket.step", ("inp",), "--sizing", "adaptive", "--order", "2")

    def test_junctions_quadratic(self):
        """Issue 18: ribs (one ending on the other) meshed piece by piece, the gaps round their feet by Gmsh."""
        self.check_twice(os.path.join("junctions", "plate_ribs_tee.step"), ("inp",), "--order", "2")


    def test_real_part_smoothed_in_two_halves(self):
        """Issue 19: a real part whose quads (6 452 nodes) and hexes are smoothed in two halves side by side
        (core/sweep_halves.hpp) and whose walls' rims are snapped on every thread."""
        part = os.path.abspath(os.path.join(harness.args.source, "..", "shared", "parts", "real",
                                            "ender3_support_frame_Uchannel.step"))
        if not os.path.exists(part):
            self.fail(f"{part} is missing: the real parts live in shared/parts/real beside the repository")
        self.check_twice(part, ("inp",))


if __name__ == "__main__":
    harness.main()
