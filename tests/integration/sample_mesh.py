"""Meshing a bundled sample part with the CLI and checking its hexes with tools of this folder, not the mesher's
report (shared by the scripts that test the sample folders: rims, thickness steps, air gaps)."""
import os
import subprocess
import sys
import tempfile
import unittest

import harness
from cad import face_distances, opened, surface_euler_characteristic
from inp import hex_arrays, read_inp

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from hex_geometry import boundary_euler_characteristic, hex_scaled_jacobians, hex_volumes  # noqa: E402


def mesh_step(step, layers, out, report=None):
    """STEP meshed with `layers` layers into the .inp OUT (and its JSON report into `report` if given); returns its
    hexes as hex_arrays gives them (x, hexes, index) and its sets. Raises AssertionError with the CLI's exit code and
    message if it fails, or if an element is not an 8-node hex."""
    label = f"{os.path.basename(step)}, {layers} layers"
    done = subprocess.run([harness.args.hexlayer, "mesh", step, "-o", out, "--layers", str(layers), "--quiet",
                           *(["--report", report] if report else [])], capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        raise AssertionError(f"{label}: exit {done.returncode}: {done.stderr[-2000:]}")
    nodes, elements, sets = read_inp(out)
    if not elements or any(len(e) != 8 for _, e in elements):
        raise AssertionError(f"{label}: not every element an 8-node hex")
    return (*hex_arrays(nodes, elements), sets)


def mesh_sample(folder, part, layers, tmp):
    """Resources/samples/FOLDER/PART.step meshed with `layers` layers into TMP (mesh_step); returns the STEP path, then
    what mesh_step returns."""
    step = os.path.join(harness.args.source, "Resources", "samples", folder, part + ".step")
    return (step, *mesh_step(step, layers, os.path.join(tmp, f"{part}_{layers}.inp")))


def check_hexes(test, gmsh, x, hexes, quality, allowed, label, exact_volume=None):
    """Every hex of positive volume, the scaled Jacobian's minimum and average at least `quality` (a pair), the mesh
    volume within `allowed` (relative) of the CAD's as Gmsh's OpenCASCADE computes it (`gmsh`: the STEP opened), or
    of `exact_volume`; prints a line headed `label`."""
    volumes = hex_volumes(x, hexes)
    sj = hex_scaled_jacobians(x, hexes)
    test.assertGreater(volumes.min(), 0)
    test.assertGreaterEqual(sj.min(), quality[0])
    test.assertGreaterEqual(sj.mean(), quality[1])
    cad_volume = exact_volume or sum(gmsh.model.occ.getMass(3, t) for _, t in gmsh.model.getEntities(3))
    error = (volumes.sum() - cad_volume) / cad_volume
    test.assertLessEqual(abs(error), allowed, f"volume {100 * error:+.2f} %, allowed {100 * allowed:.2f} %")
    print(f"{label}: {len(hexes)} hexes, SJ min {sj.min():.3f} avg {sj.mean():.3f}, volume {100 * error:+.2f} % "
          f"(allowed {100 * allowed:.2f} %)")


def check_sample(test, folder, part, layers, quality, allowed, wall):
    """Resources/samples/FOLDER/PART.step meshed with `layers` layers (mesh_sample) and checked: its hexes
    (check_hexes: `quality`, `allowed`), every boundary node within 1e-6 mm of the CAD face it is grouped on, the part's
    topology (Gmsh's triangles of about `wall` mm). A part named ...metres is in metres: the distances scaled by 1e-3."""
    step, x, hexes, index, sets = mesh_sample(folder, part, layers, test.tmp.name)
    scale = 1e-3 if part.endswith("metres") else 1.0
    with opened(step) as gmsh:  # the CAD as Gmsh's OpenCASCADE reads it, not as hexlayer does
        check_hexes(test, gmsh, x, hexes, quality, allowed, f"{part}, {layers} layers")
        for face, worst in face_distances(gmsh, x, index, sets).items():
            test.assertLessEqual(worst, 1e-6 * scale, f"Face{face}: a node {worst:.2e} off it")
    test.assertEqual(boundary_euler_characteristic(hexes), surface_euler_characteristic(step, wall * scale),
                     "the part's topology")


class MeshTest(unittest.TestCase):
    """Tests that write meshes: a temporary folder for them (`tmp`); over sample parts, check_each runs
    `check(part, layers)` for each part at each layer count as a subtest."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def check_each(self, parts, layer_counts):
        for part in parts:
            for layers in layer_counts:
                with self.subTest(part=part, layers=layers):
                    self.check(part, layers)
