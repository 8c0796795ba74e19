"""Issue 3's modelled parts, meshed with the default (adaptive) sizing, 2 layers: the cylinder shell
segment, the spherical cap, the filleted housing shelled to 2.5 mm, the twisted strip, the wedge plate
(1 -> 4 mm) and the bent hat section with holes (Resources/samples, scripts/make_samples.py).

Every part: no inverted hex, volume within 1 % of the CAD's, every boundary node within 1e-6 mm of
its CAD face, the part's topology, and the target scaled Jacobian (average >= 0.95, minimum >= 0.5)
with a structured quad mesh (block_grids): a grid on the four-cornered parts (the hat with a pocket of
four blocks around each hole) and an O-grid (a core and four blocks) on the cap and the housing, whose
rims have no corners.

Run by CTest as: /usr/bin/python3 test_curved_parts.py --hexlayer PATH --source DIR
"""
import json
import os
import subprocess
import tempfile
import unittest

import harness

# Measured 2026-11-24 (hexes, SJ min, SJ avg, volume error, structured blocks):
PARTS = ["cylinder_shell",  # 1240, 0.998, 0.999, -0.12 %, 1
         "twisted_strip",   # 1020, 0.986, 0.999, -0.07 %, 1
         "wedge_plate",     # 3116, 0.997, 1.000, -0.01 %, 1
         "spherical_cap",   # 2552, 0.862, 0.994, -0.12 %, 5 (O-grid)
         "housing",         # 4144, 0.751, 0.984, -0.80 %, 5 (O-grid)
         "hat_holes"]       # 6858, 0.880, 0.987, -0.76 %, 17 (grid, 4 pockets)
O_GRID = {"spherical_cap", "housing"}


def mesh(part):
    step = os.path.join(harness.args.source, "Resources", "samples", part + ".step")
    with tempfile.TemporaryDirectory() as tmp:
        report = os.path.join(tmp, "r.json")
        done = subprocess.run([harness.args.hexlayer, "mesh", step, "-o", os.path.join(tmp, "m.inp"), "--report", report,
                               "--quiet"], capture_output=True, text=True, timeout=600)
        if done.returncode != 0:
            raise AssertionError(f"{part}: exit {done.returncode}: {done.stderr[-2000:]}")
        with open(report) as f:
            r = json.load(f)
    print(f"{part}: {r['hexes']} hexes, SJ min {r['scaled_jacobian']['min']:.3f} avg {r['scaled_jacobian']['avg']:.4f}, "
          f"volume {100 * r['volume']['relative_error']:+.3f} %, boundary deviation {r['boundary_deviation']['max']:.1e} mm")
    return r


class CurvedParts(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.reports = {part: mesh(part) for part in PARTS}

    def test_every_part_is_sound_and_fits_its_cad(self):
        for part, r in self.reports.items():
            with self.subTest(part=part):
                self.assertEqual(r["sizing"], "adaptive")
                self.assertEqual(r["inverted_hexes"], 0)
                self.assertLess(abs(r["volume"]["relative_error"]), 0.01)
                self.assertLessEqual(r["boundary_deviation"]["max"], 1e-6)
                self.assertTrue(r["boundary"]["watertight"], r["boundary"])
                self.assertTrue(r["boundary"]["same_topology_as_cad"], r["boundary"])
                self.assertTrue(r["validation"]["passed"], r["validation"])

    def test_every_part_meets_the_quality_target(self):
        for part, r in self.reports.items():
            with self.subTest(part=part):
                self.assertGreaterEqual(r["scaled_jacobian"]["avg"], 0.95)
                self.assertGreaterEqual(r["scaled_jacobian"]["min"], 0.5)

    def test_quads_are_structured_blocks(self):
        for part, r in self.reports.items():
            with self.subTest(part=part):
                q = r["quad_mesh"]
                self.assertEqual(q["layout"], "o-grid" if part in O_GRID else "grid")
                expected = 5 if part in O_GRID else 1 + 4 * {"hat_holes": 4}.get(part, 0)
                self.assertEqual(q["structured_patches"], expected)


if __name__ == "__main__":
    harness.main()
