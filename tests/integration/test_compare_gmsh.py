"""End-to-end: scripts/compare_gmsh.py on one small part, HexLayer against Gmsh's all-hex by subdivision.

Run by CTest as: /usr/bin/python3 test_compare_gmsh.py --hexlayer PATH --source DIR
"""
import os
import sys
import tempfile
import unittest

import harness


class CompareGmsh(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        sys.path.insert(0, os.path.join(harness.args.source, "scripts"))
        import compare_gmsh
        step = os.path.join(harness.args.source, "Resources", "samples", "plate_holes.step")
        with tempfile.TemporaryDirectory() as work:
            cls.c = compare_gmsh.compare_part(harness.args.hexlayer, step, work)
        cls.ours, cls.gmsh = cls.c["ours"], cls.c["gmsh"]

    def test_measures_of_a_known_hex(self):
        import compare_gmsh
        import numpy as np
        cube = 2.0 * compare_gmsh.CORNER_SIGNS
        sheared = cube + np.outer(cube[:, 2] > 0, [2.0, 0, 0])  # top face slid by half the edge
        mirrored = cube * [1, 1, -1]
        sj = compare_gmsh.scaled_jacobian(np.vstack([cube, sheared, mirrored]), np.arange(24).reshape(3, 8))
        np.testing.assert_allclose(sj, [1, 4 / np.sqrt(20), -1])  # sheared: det 64 over 4 * 4 * sqrt(20)
        volumes = compare_gmsh.hex_volumes(np.vstack([cube, sheared]), np.arange(16).reshape(2, 8))
        np.testing.assert_allclose(volumes, [64, 64])

    def test_both_meshers_ran_at_the_wall_thickness(self):
        self.assertNotIn("error", self.ours)
        self.assertNotIn("error", self.gmsh)
        self.assertEqual(self.c["size"], self.ours["report"]["thickness"])

    def test_both_meshes_are_pure_hex(self):
        self.assertEqual(self.ours["cell_types"], ["hexahedron"])
        self.assertEqual(self.ours["hexes"], self.ours["report"]["hexes"])
        self.assertEqual(self.gmsh["element_types"], [5])
        self.assertGreater(self.gmsh["hexes"], 0)

    def test_our_sj_from_the_vtu_matches_the_report(self):
        self.assertLess(self.ours["sj_vs_report"], 1e-6)
        self.assertLess(self.ours["sj_vs_file"], 1e-6)

    def test_hexlayer_beats_subdivision_on_sj(self):
        self.assertGreater(self.ours["sj_avg"], self.gmsh["sj_avg"])
        self.assertLess(self.gmsh["sj_min"], self.ours["sj_min"])

    def test_both_meshes_fill_the_part(self):
        self.assertLess(abs(self.ours["volume_error"]), 0.03)
        self.assertLess(abs(self.gmsh["volume_error"]), 0.03)


if __name__ == "__main__":
    harness.main()
