"""Issue 15: scale does not matter. The same part in metres (x 0.001), in millimetres and x 1000 gives the same
mesh, scaled: the same numbers of hexes and nodes, the same quad layout, the same quality and volume error,
the mesh's extent scaled with the part's, and every boundary node on its CAD face within the CAD's own
tolerance (1e-7 of the file's unit: in metres, 7e-5 of the hat's wall). Four parts: the hat section with full-round ends (bends, round rims), the spherical cap cut by a
plane, the strip whose top wall and round end are one B-spline face (split where the wall meets the rim) and the
plate with a near-full-round hole (its chordal rim moved between the walls' rim edges), each scaled with Gmsh's OpenCASCADE (which writes its surfaces as B-splines at every scale: the case
where wall nodes landed 2.4 walls off their faces in metres before the part was met at one size).

Not byte for byte: 0.001 is not a binary fraction, and the bubble packing amplifies the last bit of a
coordinate into a slightly different packing (node positions differ by up to 2 % of the part at one scale
from another, the counts do not).

Run by CTest as: /usr/bin/python3 test_scale.py --hexlayer PATH --source DIR
"""
import json
import os
import subprocess
import tempfile
import unittest

import numpy as np

import harness
from inp import read_inp

PARTS = ["hat_round_ends", "cap_cut_by_plane", "strip_skin_round", "plate_hole_full_round"]
SCALES = [0.001, 1.0, 1000.0]


def scaled_copy(step, factor, out):
    import gmsh
    gmsh.initialize(readConfigFiles=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.occ.importShapes(step)
        gmsh.model.occ.synchronize()
        gmsh.model.occ.dilate(gmsh.model.getEntities(3), 0, 0, 0, factor, factor, factor)
        gmsh.model.occ.synchronize()
        gmsh.write(out)
    finally:
        gmsh.finalize()


def mesh(step, tmp, name):
    out, report = os.path.join(tmp, name + ".inp"), os.path.join(tmp, name + ".json")
    done = subprocess.run([harness.args.hexlayer, "mesh", step, "-o", out, "--report", report, "--quiet"],
                          capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        raise AssertionError(f"{name}: exit {done.returncode}: {done.stderr[-2000:]}")
    with open(report) as f:
        r = json.load(f)
    nodes, elements, _ = read_inp(out)
    x = np.array(list(nodes.values()))
    return r, len(nodes), len(elements), x.max(axis=0) - x.min(axis=0)


class Scale(unittest.TestCase):
    def test_a_part_meshes_alike_at_every_scale(self):
        with tempfile.TemporaryDirectory() as tmp:
            for part in PARTS:
                step = os.path.join(harness.args.source, "Resources", "samples", "rims", part + ".step")
                runs = {}
                for factor in SCALES:
                    copy = os.path.join(tmp, f"{part}_{factor:g}.brep")
                    scaled_copy(step, factor, copy)
                    runs[factor] = mesh(copy, tmp, f"{part}_{factor:g}")
                base, base_nodes, base_hexes, base_extent = runs[1.0]
                for factor, (r, nodes, hexes, extent) in runs.items():
                    with self.subTest(part=part, scale=factor):
                        print(f"{part} x {factor:g}: {hexes} hexes, {nodes} nodes, SJ {r['scaled_jacobian']['min']:.3f} / "
                              f"{r['scaled_jacobian']['avg']:.4f}, volume {100 * r['volume']['relative_error']:+.3f} %, "
                              f"boundary deviation {r['boundary_deviation']['max_relative']:.1e} of the wall")
                        self.assertEqual((hexes, nodes), (base_hexes, base_nodes))
                        self.assertEqual(r["quad_mesh"]["layout"], base["quad_mesh"]["layout"])
                        np.testing.assert_allclose(extent / factor, base_extent, rtol=2e-3)  # in the input's units
                        self.assertAlmostEqual(r["thickness"] / factor, base["thickness"], delta=1e-6 * base["thickness"])
                        self.assertAlmostEqual(r["scaled_jacobian"]["min"], base["scaled_jacobian"]["min"], delta=0.02)
                        self.assertAlmostEqual(r["scaled_jacobian"]["avg"], base["scaled_jacobian"]["avg"], delta=0.002)
                        self.assertAlmostEqual(r["volume"]["relative_error"], base["volume"]["relative_error"], delta=5e-4)
                        # At most the CAD's own tolerance: OpenCASCADE's smallest, 1e-7 of the file's unit, is 7e-5
                        # of the hat's wall in metres.
                        self.assertLessEqual(r["boundary_deviation"]["max_relative"], 2e-4)
                        self.assertEqual(r["inverted_hexes"], 0)


if __name__ == "__main__":
    harness.main()
