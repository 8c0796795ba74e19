#!/usr/bin/python3
# SPDX-License-Identifier: AGPL-3.0-or-later
"""Generate the hard and bad CAD inputs of the robustness test table (tests/integration/test_robustness.py).

Usage:
    /usr/bin/python3 scripts/make_bad_inputs.py [OUTPUT_DIR]

OUTPUT_DIR defaults to tests/data/robustness. Needs FreeCAD 0.20's Part module (Debian's freecad, importable
from /usr/bin/python3 through /usr/lib/freecad-python3/lib). Units mm. Every file is small (a few kB); the
STEP header timestamp is fixed, as in scripts/make_samples.py, so re-running gives the same files.

Made here: shapes without a solid (a lone face, a wire, an open shell), several solids, a thick block, a
plate with a rib (T-junction), a plate with a pin under a wider head (a junction refused), small features below
the default element size (a hole, fillets, chamfers, a short edge, a sliver face), and damaged files (garbage bytes,
truncated STEP and BREP, a STEP named .brep).
"""
import os
import re
import sys

sys.path.append("/usr/lib/freecad-python3/lib")
try:
    import FreeCAD  # noqa: F401  (loads the Part module's dependencies)
    import Part
except ImportError:
    sys.exit("make_bad_inputs.py: cannot import FreeCAD; install Debian's freecad and run with /usr/bin/python3")

from FreeCAD import Vector

FIXED_TIMESTAMP = "2000-01-01T00:00:00"
MAX_BYTES = 64 * 1024


def plate(length=60.0, width=40.0, thickness=2.0):
    return Part.makeBox(length, width, thickness)


def prism(points, height):
    """A polygon in the XY plane extruded by `height` along +Z."""
    wire = Part.makePolygon([Vector(x, y, 0) for x, y in points] + [Vector(*points[0], 0)])
    return Part.Face(wire).extrude(Vector(0, 0, height))


def vertical_edges(shape):
    return [e for e in shape.Edges if abs(e.Vertexes[0].Point.z - e.Vertexes[-1].Point.z) > 1e-9]


def top_edges(shape, z):
    return [e for e in shape.Edges if all(abs(v.Point.z - z) < 1e-9 for v in e.Vertexes)]


# ---- shapes without one closed solid ---------------------------------------------------------------------

def lone_face():
    return plate().Faces[0]


def wire():
    return Part.makePolygon([Vector(0, 0, 0), Vector(60, 0, 0), Vector(60, 40, 0), Vector(0, 0, 0)])


def open_shell():
    return Part.Shell(plate().Faces[:5])  # a box without its top: an open shell


def two_plates():
    return Part.Compound([plate(), plate().translated(Vector(0, 60, 0))])


# ---- geometry the method refuses -------------------------------------------------------------------------

def thick_block():
    return Part.makeBox(30, 20, 15)  # wall 15 over a 39 mm diagonal: not a thin section


def t_junction():
    rib = Part.makeBox(60, 2, 12).translated(Vector(0, 19, 2))  # a rib standing on the plate's middle
    return plate().fuse(rib).removeSplitter()


def mushroom_pin():
    # A pin (Ø3) under a wider head (Ø6 x 2) standing on the plate: no thin sheet, and no column (the head's underside
    # looks back at the plate), so its junction is refused.
    pin = Part.makeCylinder(1.5, 8, Vector(30, 20, 1))
    head = Part.makeCylinder(3, 2, Vector(30, 20, 9))
    return plate().fuse([pin, head]).removeSplitter()


# ---- small features below the default element size (the 2 mm wall) ---------------------------------------

def small_hole():
    return plate().cut(Part.makeCylinder(0.25, 4, Vector(30, 20, -1)))


def small_fillets():
    p = plate()
    return p.makeFillet(0.3, vertical_edges(p))


def small_chamfers():
    p = plate()
    return p.makeChamfer(0.2, top_edges(p, 2.0))


def short_edge():
    # A 0.02 mm step in the long side: two short edges and a 0.02 mm wide lateral face.
    return prism([(0, 0), (60, 0), (60, 40), (30, 40), (30, 39.98), (0, 39.98)], 2.0)


def sliver_face():
    # A 0.05 mm wide strip fused to the plate's side, its top and bottom faces kept apart: sliver faces.
    return plate().fuse(Part.makeBox(60, 0.05, 2).translated(Vector(0, 40, 0)))


SHAPES = {
    "lone_face.step": lone_face,
    "lone_face.iges": lone_face,
    "wire.step": wire,
    "open_shell.step": open_shell,
    "open_shell.brep": open_shell,
    "two_plates.step": two_plates,
    "thick_block.step": thick_block,
    "t_junction.step": t_junction,
    "mushroom_pin.step": mushroom_pin,
    "small_hole.step": small_hole,
    "small_fillets.step": small_fillets,
    "small_chamfers.step": small_chamfers,
    "short_edge.step": short_edge,
    "sliver_face.step": sliver_face,
    "plate.brep": plate,
}


def write_shape(shape, path):
    if path.endswith(".brep"):
        shape.exportBrep(path)
        return
    if path.endswith(".iges"):
        shape.exportIges(path)
    else:
        shape.exportStep(path)
    with open(path, encoding="ascii") as f:
        text = f.read()
    text = re.sub(r"(FILE_NAME\('[^']*',')[^']*(')", r"\g<1>" + FIXED_TIMESTAMP + r"\g<2>", text, count=1)
    text = re.sub(r"(FILE_NAME\(')[^']*(')", r"\g<1>" + os.path.basename(path) + r"\g<2>", text, count=1)
    text = re.sub(r"\d\dH\d{8}\.\d{6}", "15H20000101.000000", text)  # IGES: the file's and the model's dates
    with open(path, "w", encoding="ascii", newline="") as f:
        f.write(text)


def damaged_files(outdir):
    """Damaged copies of good files: the first part of each (cut mid-entity), garbage, the wrong format."""
    with open(os.path.join(outdir, "plate.brep"), "rb") as f:
        brep = f.read()
    with open(os.path.join(outdir, "small_hole.step"), "rb") as f:
        step = f.read()
    garbage = bytes((i * 7919 + 13) % 256 for i in range(4096))  # deterministic "random" bytes
    return {
        "truncated.brep": brep[: len(brep) * 6 // 10],
        "truncated.step": step[: len(step) // 2],
        "garbage.step": garbage,
        "garbage.brep": garbage,
        "garbage.iges": garbage,
        "step_text.brep": step,  # a STEP file named .brep
        "plate.txt": step,        # an extension no reader has
    }


def main(argv):
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    outdir = argv[1] if len(argv) > 1 else os.path.join(root, "tests", "data", "robustness")
    os.makedirs(outdir, exist_ok=True)
    for name, make in SHAPES.items():
        write_shape(make(), os.path.join(outdir, name))
    for name, data in damaged_files(outdir).items():
        with open(os.path.join(outdir, name), "wb") as f:
            f.write(data)
    for name in sorted(os.listdir(outdir)):
        size = os.path.getsize(os.path.join(outdir, name))
        assert size <= MAX_BYTES, f"{name} is {size} bytes (limit {MAX_BYTES})"
        print(f"{name}: {size} bytes")


if __name__ == "__main__":
    main(sys.argv)
