#!/usr/bin/python3
# SPDX-License-Identifier: AGPL-3.0-or-later
"""Generate the HexLayer sample STEP files (thin-walled single solids, units mm).

Usage:
    /usr/bin/python3 scripts/make_samples.py [OUTPUT_DIR]

OUTPUT_DIR defaults to Resources/samples relative to the repository root.
Needs the Gmsh Python API with its OpenCASCADE kernel: on Debian 12 that is the
package python3-gmsh (4.8), importable only by Debian's /usr/bin/python3.

Every part is built with gmsh.model.occ, checked to be exactly one volume whose
CAD volume matches the analytic volume (relative error <= 1e-6), written as
STEP, then read back and checked again (one volume, same volume, every edge
shared by exactly two face uses, i.e. a closed shell; a sphere's pole, a
degenerate edge of length 0, by one). The STEP header
timestamp is replaced with a fixed one so that re-running the script produces
byte-identical files. A README.md with a table of the parts is written too.
"""

import math
import os
import re
import sys
from collections import Counter
from contextlib import contextmanager

try:
    import gmsh
except ImportError:
    sys.exit("make_samples.py: cannot import gmsh. Install the Debian package "
             "python3-gmsh (apt-get install -y python3-gmsh) and run this "
             "script with /usr/bin/python3.")

occ = gmsh.model.occ
PI = math.pi
REL_TOL = 1e-6
FIXED_TIMESTAMP = "2000-01-01T00:00:00"
MAX_BYTES = 100 * 1024


@contextmanager
def quiet_stdout():
    """Silence the OpenCASCADE STEP translator, which prints its statistics to
    file descriptor 1 whatever General.Terminal says."""
    sys.stdout.flush()
    saved = os.dup(1)
    devnull = os.open(os.devnull, os.O_WRONLY)
    try:
        os.dup2(devnull, 1)
        yield
    finally:
        os.dup2(saved, 1)
        os.close(devnull)
        os.close(saved)


# ---------------------------------------------------------------------------
# Geometry helpers
# ---------------------------------------------------------------------------

def extrude_profile(segments, length):
    """Build a closed planar profile in the XZ plane (y = 0) and extrude it by
    `length` along +Y. Returns the tag of the resulting volume.

    `segments` is a closed chain of ("line", (x1, z1), (x2, z2)) and
    ("arc", (x1, z1), (xc, zc), (x2, z2)) items; consecutive items share
    their end / start points exactly.
    """
    points = {}

    def pt(p):
        key = (round(p[0], 12), round(p[1], 12))
        if key not in points:
            points[key] = occ.addPoint(p[0], 0.0, p[1])
        return points[key]

    curves = []
    centres = set()
    for i, seg in enumerate(segments):
        nxt = segments[(i + 1) % len(segments)]
        assert seg[-1] == nxt[1], f"profile not closed between items {i} and {i + 1}"
        if seg[0] == "line":
            curves.append(occ.addLine(pt(seg[1]), pt(seg[2])))
        elif seg[0] == "arc":
            (x1, z1), (xc, zc), (x2, z2) = seg[1], seg[2], seg[3]
            r1 = math.hypot(x1 - xc, z1 - zc)
            r2 = math.hypot(x2 - xc, z2 - zc)
            assert abs(r1 - r2) < 1e-12, f"arc {i}: endpoints not on one circle"
            c = occ.addPoint(xc, 0.0, zc)   # centre: construction point only
            curves.append(occ.addCircleArc(pt(seg[1]), c, pt(seg[3])))
            centres.add(c)
        else:
            raise ValueError(seg[0])
    # Drop the arc centre points, otherwise they stay in the model as free
    # vertices and end up in the STEP file as an extra wireframe product.
    occ.remove([(0, c) for c in sorted(centres)])
    loop = occ.addCurveLoop(curves)
    surf = occ.addPlaneSurface([loop])
    out = occ.extrude([(2, surf)], 0.0, length, 0.0)
    vols = [tag for dim, tag in out if dim == 3]
    assert len(vols) == 1, out
    return vols[0]


def drill(vol, holes):
    """Cut vertical (Z) through holes. `holes` = list of (x, y, z_bottom, z_top, d)."""
    tools = []
    for x, y, zb, zt, d in holes:
        tools.append((3, occ.addCylinder(x, y, zb - 1.0, 0.0, 0.0, (zt - zb) + 2.0, d / 2.0)))
    out, _ = occ.cut([(3, vol)], tools)
    vols = [tag for dim, tag in out if dim == 3]
    assert len(vols) == 1, out
    return vols[0]


def quarter_annulus(r_in, r_out):
    return PI / 4.0 * (r_out ** 2 - r_in ** 2)


# ---------------------------------------------------------------------------
# Parts. Each builder creates the solid in the current model and returns
# (analytic_volume, description dict for the README).
# ---------------------------------------------------------------------------

def plate():
    L, W, t = 60.0, 40.0, 2.0
    occ.addBox(0, 0, 0, L, W, t)
    return L * W * t, dict(dims="60 × 40 × 2 flat plate", wall="2")


def plate_holes():
    L, W, t, d = 80.0, 50.0, 2.0, 8.0
    centres = [(15.0, 12.0), (65.0, 12.0), (15.0, 38.0), (65.0, 38.0)]
    box = occ.addBox(0, 0, 0, L, W, t)
    drill(box, [(x, y, 0.0, t, d) for x, y in centres])
    vol = L * W * t - len(centres) * PI * (d / 2) ** 2 * t
    return vol, dict(dims="80 × 50 × 2 plate, 4 through holes Ø8 at "
                          "(15,12), (65,12), (15,38), (65,38)", wall="2")


def cantilever():
    L, W, t = 100.0, 10.0, 2.0
    occ.addBox(0, 0, 0, L, W, t)
    return L * W * t, dict(dims="100 × 10 × 2 strip (CalculiX beam test)", wall="2")


def lbracket():
    # Profile in XZ, outer corner at the origin: horizontal leg along +X
    # (bottom/outer face z = 0, 40 long to the outer face x = 0 of the
    # vertical leg), vertical leg along +Z (outer face x = 0, 30 high to the
    # outer face z = 0). Bend centre (ro, ro); inner radius ri, outer ro.
    t, ri, H, V, W = 3.0, 3.0, 40.0, 30.0, 25.0
    ro = ri + t
    c = (ro, ro)
    segs = [
        ("line", (H, 0.0), (ro, 0.0)),          # outer face of horizontal leg
        ("arc", (ro, 0.0), c, (0.0, ro)),       # outer bend, R = ro
        ("line", (0.0, ro), (0.0, V)),          # outer face of vertical leg
        ("line", (0.0, V), (t, V)),             # top end
        ("line", (t, V), (t, ro)),              # inner face of vertical leg
        ("arc", (t, ro), c, (ro, t)),           # inner bend, R = ri
        ("line", (ro, t), (H, t)),              # inner face of horizontal leg
        ("line", (H, t), (H, 0.0)),             # free end
    ]
    extrude_profile(segs, W)
    area = (H - ro) * t + (V - ro) * t + quarter_annulus(ri, ro)
    return area * W, dict(dims="L-bracket, legs 40 (horizontal) × 30 (vertical) to "
                               "outer faces, width 25, bend R3 inner / R6 outer",
                          wall="3")


def uchannel():
    # Profile in XZ: web on z in [0, t], x in [0, B]; flanges up to z = Hf.
    t, ri, B, Hf, L = 2.0, 2.0, 30.0, 20.0, 60.0
    ro = ri + t
    cl, cr = (ro, ro), (B - ro, ro)
    segs = [
        ("line", (0.0, Hf), (0.0, ro)),              # left flange, outside
        ("arc", (0.0, ro), cl, (ro, 0.0)),           # left bend, outer
        ("line", (ro, 0.0), (B - ro, 0.0)),          # web, outside
        ("arc", (B - ro, 0.0), cr, (B, ro)),         # right bend, outer
        ("line", (B, ro), (B, Hf)),                  # right flange, outside
        ("line", (B, Hf), (B - t, Hf)),              # right flange top
        ("line", (B - t, Hf), (B - t, ro)),          # right flange, inside
        ("arc", (B - t, ro), cr, (B - ro, t)),       # right bend, inner
        ("line", (B - ro, t), (ro, t)),              # web, inside
        ("arc", (ro, t), cl, (t, ro)),               # left bend, inner
        ("line", (t, ro), (t, Hf)),                  # left flange, inside
        ("line", (t, Hf), (0.0, Hf)),                # left flange top
    ]
    extrude_profile(segs, L)
    area = (B - 2 * ro) * t + 2 * (Hf - ro) * t + 2 * quarter_annulus(ri, ro)
    return area * L, dict(dims="U-channel, web 30 wide × flanges 20 high (outside), "
                               "length 60, bends R2 inner / R4 outer", wall="2")


def hat_holes():
    # Profile in XZ (outside dimensions): flanges x in [0, F] and
    # [F + T, 2F + T] with bottom face z = 0; walls with outer faces at x = F
    # and x = F + T; top with outer face at z = Hh. Total width 60, height 20.
    # At the top bends the outer (R = ro) arc is on the outside of the hat; at
    # the flange bends the concave side is the wall's outer face / the
    # flange's top face, so the inner (R = ri) arc is there.
    t, ri, F, Hh, T, L = 1.5, 2.0, 15.0, 20.0, 30.0, 80.0
    ro = ri + t
    Wt = 2 * F + T
    xl, xr = F, F + T                      # outer faces of the walls
    cbl = (xl - ri, t + ri)                # bottom-left bend centre
    ctl = (xl + ro, Hh - ro)               # top-left bend centre
    ctr = (xr - ro, Hh - ro)               # top-right bend centre
    cbr = (xr + ri, t + ri)                # bottom-right bend centre
    segs = [
        ("line", (0.0, 0.0), (cbl[0], 0.0)),                 # left flange bottom
        ("arc", (cbl[0], 0.0), cbl, (xl + t, cbl[1])),       # bottom-left bend, R = ro
        ("line", (xl + t, cbl[1]), (xl + t, ctl[1])),        # left wall, inside
        ("arc", (xl + t, ctl[1]), ctl, (ctl[0], Hh - t)),    # top-left bend, R = ri
        ("line", (ctl[0], Hh - t), (ctr[0], Hh - t)),        # top, underside
        ("arc", (ctr[0], Hh - t), ctr, (xr - t, ctr[1])),    # top-right bend, R = ri
        ("line", (xr - t, ctr[1]), (xr - t, cbr[1])),        # right wall, inside
        ("arc", (xr - t, cbr[1]), cbr, (cbr[0], 0.0)),       # bottom-right bend, R = ro
        ("line", (cbr[0], 0.0), (Wt, 0.0)),                  # right flange bottom
        ("line", (Wt, 0.0), (Wt, t)),                        # right flange end
        ("line", (Wt, t), (cbr[0], t)),                      # right flange top
        ("arc", (cbr[0], t), cbr, (xr, cbr[1])),             # bottom-right bend, R = ri
        ("line", (xr, cbr[1]), (xr, ctr[1])),                # right wall, outside
        ("arc", (xr, ctr[1]), ctr, (ctr[0], Hh)),            # top-right bend, R = ro
        ("line", (ctr[0], Hh), (ctl[0], Hh)),                # top, outside
        ("arc", (ctl[0], Hh), ctl, (xl, ctl[1])),            # top-left bend, R = ro
        ("line", (xl, ctl[1]), (xl, cbl[1])),                # left wall, outside
        ("arc", (xl, cbl[1]), cbl, (cbl[0], t)),             # bottom-left bend, R = ri
        ("line", (cbl[0], t), (0.0, t)),                     # left flange top
        ("line", (0.0, t), (0.0, 0.0)),                      # left flange end
    ]
    vol = extrude_profile(segs, L)
    d_top, d_fl = 6.0, 5.0
    holes = [
        (Wt / 2, L / 4, Hh - t, Hh, d_top),
        (Wt / 2, 3 * L / 4, Hh - t, Hh, d_top),
        (cbl[0] / 2, L / 2, 0.0, t, d_fl),
        (Wt - cbl[0] / 2, L / 2, 0.0, t, d_fl),
    ]
    drill(vol, holes)
    area = (2 * cbl[0] * t                        # flanges
            + 2 * (ctl[1] - cbl[1]) * t           # walls
            + (ctr[0] - ctl[0]) * t               # top
            + 4 * quarter_annulus(ri, ro))        # bends
    holes_vol = sum(PI * (d / 2) ** 2 * t for *_, d in holes)
    return area * L - holes_vol, dict(
        dims="hat section, flanges 15 wide, walls 20 high, top 30 wide (outside; "
             "overall 60 × 20), length 80, bends R2 inner / R3.5 outer, "
             "2 × Ø6 holes through the top at (30,20), (30,60), "
             "1 × Ø5 hole through each flange at (6.5,40), (53.5,40)",
        wall="1.5")


def cylinder_shell():
    # Annular sector in the XY plane (mid radius 30, wall 2, 120° from +X
    # towards +Y), extruded along +Z: the rims are the two radial planes
    # and the two planes z = 0 and z = Lz.
    rm, t, deg, Lz = 30.0, 2.0, 120.0, 40.0
    ri, ro = rm - t / 2, rm + t / 2
    a = math.radians(deg)
    c, s = math.cos(a), math.sin(a)
    p = [occ.addPoint(ri, 0, 0), occ.addPoint(ro, 0, 0),
         occ.addPoint(ro * c, ro * s, 0), occ.addPoint(ri * c, ri * s, 0)]
    centre = occ.addPoint(0, 0, 0)             # construction point only
    curves = [occ.addLine(p[0], p[1]),
              occ.addCircleArc(p[1], centre, p[2]),
              occ.addLine(p[2], p[3]),
              occ.addCircleArc(p[3], centre, p[0])]
    occ.remove([(0, centre)])
    surf = occ.addPlaneSurface([occ.addCurveLoop(curves)])
    occ.extrude([(2, surf)], 0.0, 0.0, Lz)
    vol = a / 2 * (ro ** 2 - ri ** 2) * Lz
    return vol, dict(dims="cylindrical shell segment, mid radius 30 (R29 inner / "
                          "R31 outer), 120° of arc from +X, 40 long along Z "
                          "(axis = Z axis)", wall="2")


def spherical_cap():
    # Spherical shell (centre at the origin) cut by a cone with its apex at
    # the centre, half-angle 35° around +Z: the rim is a conical face normal
    # to the shell (a plane cut would give a wide planar rim instead).
    rm, t, deg = 50.0, 2.0, 35.0
    ri, ro = rm - t / 2, rm + t / 2
    a = math.radians(deg)
    h = ro + 5.0
    cone = occ.addCone(0, 0, 0, 0, 0, h, 0.0, h * math.tan(a))
    outer = occ.addSphere(0, 0, 0, ro)
    inner = occ.addSphere(0, 0, 0, ri)
    cap, _ = occ.intersect([(3, outer)], [(3, cone)])
    out, _ = occ.cut(cap, [(3, inner)])
    assert len([tag for dim, tag in out if dim == 3]) == 1, out
    vol = 2 * PI / 3 * (1 - math.cos(a)) * (ro ** 3 - ri ** 3)
    return vol, dict(dims="spherical cap, mid radius 50 (R49 inner / R51 outer, "
                          "centre at the origin), half-angle 35° around +Z, rim "
                          "cut by the cone through the centre", wall="2")


def filleted_box_volume(L, W, H, r):
    """Volume of the box [0,L]x[0,W]x[0,H] with its 4 vertical and 4 bottom
    edges rounded with radius r (top edges sharp): the points below z = H
    within r of the core [r,L-r]x[r,W-r]x[r,inf) -- core, 5 slabs, 4 vertical
    and 4 bottom quarter cylinders, 4 eighth spheres."""
    a, b, h = L - 2 * r, W - 2 * r, H - r
    return (a * b * h + 2 * r * (a + b) * h + r * a * b
            + PI * r ** 2 * h + PI * r ** 2 / 2 * (a + b)
            + 2 * PI / 3 * r ** 3)


def filleted_box(x0, y0, z0, L, W, H, r):
    """Box with its 4 vertical and 4 bottom edges filleted with radius r."""
    box = occ.addBox(x0, y0, z0, L, W, H)
    occ.synchronize()
    edges = []
    curves = sorted({abs(c) for _, f in gmsh.model.getBoundary([(3, box)], combined=False,
                                                               oriented=False)
                     for _, c in gmsh.model.getBoundary([(2, f)], combined=False,
                                                        oriented=False)})
    for c in curves:
        xmin, ymin, zmin, xmax, ymax, zmax = gmsh.model.getBoundingBox(1, c)
        # (bounding boxes are padded by the tolerance: compare with 1e-3)
        if zmax - zmin > 1e-3 or zmax < z0 + 1e-3:     # vertical or bottom edge
            edges.append(c)
    assert len(edges) == 8, edges
    out = occ.fillet([box], edges, [r])
    assert len(out) == 1 and out[0][0] == 3, out
    return out[0][1]


def housing():
    # Open-top box housing: the outer solid (80 x 60 x 30, vertical and bottom
    # edges R8, exact cylinders and sphere corners) minus the inner one offset
    # inward by the wall (R8 - 2.5 = R5.5), which sticks out through the top,
    # so the wall is 2.5 everywhere and the open top is a flat rim at z = 30.
    L, W, H, r, t = 80.0, 60.0, 30.0, 8.0, 2.5
    outer = filleted_box(0, 0, 0, L, W, H, r)
    inner = filleted_box(t, t, t, L - 2 * t, W - 2 * t, H, r - t)   # top at z = H + t
    out, _ = occ.cut([(3, outer)], [(3, inner)])
    assert len([tag for dim, tag in out if dim == 3]) == 1, out
    vol = filleted_box_volume(L, W, H, r) - filleted_box_volume(L - 2 * t, W - 2 * t, H - t, r - t)
    return vol, dict(dims="open-top box housing, outside 80 × 60 × 30, vertical "
                          "and bottom edges rounded R8 outside / R5.5 inside "
                          "(sphere corners), top open", wall="2.5")


def twisted_strip():
    # 100 x 20 x 2 strip along X (section centred on the X axis, 20 along Y
    # at x = 0), twisted 90° about X over its length (to 20 along Z at
    # x = 100). Gmsh 4.8 has no occ.twist: a ThruSections (B-spline) solid
    # through the section rotated every 100/N. Each section has area 20 x 2,
    # so the exact volume is 100 x 20 x 2 (Cavalieri); with N = 8 the CAD
    # volume is within 2e-8 of it and the faces within 1e-6 mm of the exact
    # twisted surfaces (N = 5 would be 7e-6 off in volume, over REL_TOL).
    L, W, t, n = 100.0, 20.0, 2.0, 8
    wires, lines = [], []
    for i in range(n + 1):
        x, th = L * i / n, PI / 2 * i / n
        c, s = math.cos(th), math.sin(th)
        pts = [occ.addPoint(x, y * c - z * s, y * s + z * c)
               for y, z in ((-W / 2, -t / 2), (W / 2, -t / 2), (W / 2, t / 2), (-W / 2, t / 2))]
        ls = [occ.addLine(pts[j], pts[(j + 1) % 4]) for j in range(4)]
        wires.append(occ.addWire(ls))
        lines += ls
    occ.addThruSections(wires, makeSolid=True, makeRuled=False)
    # The section wires stay in the model as free curves: drop them.
    occ.remove([(1, c) for c in lines], recursive=True)
    return L * W * t, dict(dims="100 × 20 × 2 strip along X, twisted 90° about "
                                "its long axis (the X axis) over its length "
                                "(B-spline faces through 9 sections)", wall="2")


def wedge_plate():
    # Bottom face z = 0 flat, top face sloped from z = 1 at x = 0 to z = 4 at
    # x = 80, 40 wide along Y.
    L, W, t0, t1 = 80.0, 40.0, 1.0, 4.0
    extrude_profile([
        ("line", (0.0, 0.0), (L, 0.0)),
        ("line", (L, 0.0), (L, t1)),
        ("line", (L, t1), (0.0, t0)),
        ("line", (0.0, t0), (0.0, 0.0)),
    ], W)
    return L * W * (t0 + t1) / 2, dict(dims="80 × 40 plate, flat bottom z = 0, "
                                            "sloped top: thickness 1 at x = 0 to 4 "
                                            "at x = 80", wall="1 → 4 (linear in x)")


def thick_block():
    a = 20.0
    occ.addBox(0, 0, 0, a, a, a)
    return a ** 3, dict(dims="20 × 20 × 20 cube (not thin; for error tests)", wall="— (solid)")


PARTS = [
    ("plate", plate),
    ("plate_holes", plate_holes),
    ("cantilever", cantilever),
    ("lbracket", lbracket),
    ("uchannel", uchannel),
    ("hat_holes", hat_holes),
    ("thick_block", thick_block),
    # Curved parts after the others: OpenCASCADE numbers the STEP PRODUCT name
    # by the count of files written in the session, so appending keeps the
    # earlier files byte-identical.
    ("cylinder_shell", cylinder_shell),
    ("spherical_cap", spherical_cap),
    ("housing", housing),
    ("twisted_strip", twisted_strip),
    ("wedge_plate", wedge_plate),
]


# ---------------------------------------------------------------------------
# Checks and output
# ---------------------------------------------------------------------------

def single_volume_mass():
    vols = gmsh.model.getEntities(3)
    assert len(vols) == 1, f"expected exactly one volume, got {vols}"
    tag = vols[0][1]
    return tag, occ.getMass(3, tag)


def check_no_free_entities():
    """The model must hold nothing but the one solid: every point, curve and
    surface has to bound something of higher dimension."""
    free = [(d, t) for d in (0, 1, 2) for _, t in gmsh.model.getEntities(d)
            if len(gmsh.model.getAdjacencies(d, t)[0]) == 0]
    assert not free, f"free (unattached) entities in the model: {free}"


def check_closed(vol_tag):
    """Every edge of the solid must be used exactly twice by its faces (seam
    edges of periodic faces are used twice by the same face). Degenerate
    edges -- the pole of a spherical face, collapsed to a point, length 0 --
    are used once, by that face."""
    faces = gmsh.model.getBoundary([(3, vol_tag)], combined=False, oriented=False)
    uses = Counter()
    for _, f in faces:
        for _, c in gmsh.model.getBoundary([(2, abs(f))], combined=False, oriented=False):
            uses[abs(c)] += 1
    bad = {c: n for c, n in uses.items()
           if n != 2 and not (n == 1 and occ.getMass(1, c) < 1e-9)}
    assert not bad, f"open shell: edge uses {bad}"
    return len(faces)


def check_volume(name, got, expected):
    rel = abs(got - expected) / expected
    print(f"  {name}: CAD volume {got:.9f} mm^3, analytic {expected:.9f} mm^3, "
          f"rel. error {rel:.2e}")
    assert rel <= REL_TOL, f"{name}: volume mismatch (rel. error {rel:.3e})"


def write_step(path):
    with quiet_stdout():
        gmsh.write(path)
    with open(path, "r", encoding="ascii") as fh:
        text = fh.read()
    # FILE_NAME('<name>','<ISO timestamp>',...): fix the timestamp.
    text, n = re.subn(r"(FILE_NAME\('[^']*',')[^']*(')",
                      r"\g<1>" + FIXED_TIMESTAMP + r"\g<2>", text, count=1)
    assert n == 1, "STEP header FILE_NAME not found"
    # A single solid is exactly one product with one MANIFOLD_SOLID_BREP.
    for entity in ("PRODUCT(", "MANIFOLD_SOLID_BREP(", "CLOSED_SHELL("):
        n = text.count("= " + entity)
        assert n == 1, f"{path}: {n} x {entity[:-1]} (expected 1)"
    assert "OPEN_SHELL" not in text, f"{path}: contains an OPEN_SHELL"
    with open(path, "w", encoding="ascii", newline="") as fh:
        fh.write(text)


def make_part(name, builder, outdir):
    gmsh.clear()
    gmsh.model.add(name)
    expected, info = builder()
    occ.synchronize()
    tag, mass = single_volume_mass()
    check_no_free_entities()
    check_volume(name, mass, expected)
    check_closed(tag)

    path = os.path.join(outdir, name + ".step")
    write_step(path)
    size = os.path.getsize(path)
    assert size < MAX_BYTES, f"{path} is {size} bytes (limit {MAX_BYTES})"

    # Read the file back: one closed solid with the same volume.
    gmsh.clear()
    with quiet_stdout():
        gmsh.open(path)
    tag, mass_back = single_volume_mass()
    check_no_free_entities()
    nfaces = check_closed(tag)
    check_volume(name + " (read back)", mass_back, expected)
    print(f"  wrote {path} ({size} bytes, {nfaces} faces)")
    return dict(name=name, volume=mass, faces=nfaces, size=size, **info)


def write_readme(outdir, rows):
    lines = [
        "# HexLayer sample parts",
        "",
        "Small single-solid STEP files (AP214, units mm) for tests and examples.",
        "All parts except `thick_block.step` are thin-walled parts.",
        "",
        "| File | Part / dimensions (mm) | Wall thickness (mm) | CAD volume (mm³) |",
        "|---|---|---|---|",
    ]
    for r in rows:
        lines.append(f"| `{r['name']}.step` | {r['dims']} | {r['wall']} | {r['volume']:.3f} |")
    lines += [
        "",
        "Profiled parts (`lbracket`, `uchannel`, `hat_holes`) are extrusions of a",
        "closed 2D profile (lines and concentric, tangent arcs), so each bend is a",
        "true cylindrical surface with inner radius r and outer radius r + t.",
        "Profiles lie in the XZ plane and are extruded along +Y; the hole axes are Z.",
        "",
        "Curved parts: `cylinder_shell` is an annular sector extruded along Z (rims:",
        "two radial planes and the planes z = 0, z = 40). `spherical_cap` is a",
        "spherical shell cut by a cone with its apex at the sphere centre, so the rim",
        "is a conical face normal to the shell; its spherical faces hold the sphere's",
        "pole (+Z) as a degenerate edge. `housing` is the outer rounded box minus the",
        "inner one offset inward by the wall, so the wall is 2.5 everywhere, also in",
        "the cylindrical and spherical (corner) blends (OpenCASCADE fillets: each",
        "corner sphere has a degenerate pole edge at its bottom point); the open top",
        "is a flat rim at z = 30. `twisted_strip` is a B-spline ThruSections solid",
        "through 9 rotated sections (within 1e-6 mm of the exact twisted surfaces;",
        "volume exact to 2e-8). `wedge_plate` is a four-sided profile extruded along",
        "+Y; its wall thickness varies linearly along X.",
        "",
        "Made by `scripts/make_samples.py` (run it with `/usr/bin/python3`, which",
        "needs the Debian package `python3-gmsh`); licence AGPL-3.0-or-later like the",
        "project. The STEP header timestamp is fixed, so regenerating the files gives",
        "byte-identical output.",
        "",
    ]
    with open(os.path.join(outdir, "README.md"), "w", encoding="utf-8", newline="\n") as fh:
        fh.write("\n".join(lines))


def main(argv):
    repo_root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    if len(argv) > 2:
        sys.exit("usage: make_samples.py [OUTPUT_DIR]")
    outdir = argv[1] if len(argv) == 2 else os.path.join(repo_root, "Resources", "samples")
    os.makedirs(outdir, exist_ok=True)

    gmsh.initialize(readConfigFiles=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        rows = []
        for name, builder in PARTS:
            print(name)
            rows.append(make_part(name, builder, outdir))
        write_readme(outdir, rows)
        print(f"wrote {len(rows)} STEP files and README.md to {outdir}")
    finally:
        gmsh.finalize()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
