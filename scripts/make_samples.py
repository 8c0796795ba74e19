#!/usr/bin/python3
# SPDX-License-Identifier: AGPL-3.0-or-later
"""Generate the HexLayer sample STEP files (thin-walled single solids, units mm).

Usage:
    /usr/bin/python3 scripts/make_samples.py [OUTPUT_DIR] [--only many]

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
The rim parts (RIM_PARTS: full-round ends, fillets, chamfers, oblique and
plane cuts, split faces) go to OUTPUT_DIR/rims with a README.md of their own;
they are written after the others (see the note on PARTS). The junction
parts (JUNCTION_PARTS: ribs, a grid of ribs, a partition, bosses, a gusset,
a filleted rib foot: walls standing on walls) go to OUTPUT_DIR/junctions,
with a README.md of their own, after the rim parts. The parts with many
features (MANY_PARTS: a keyboard plate, a plate with 200 holes, a perforated
tube) are written
to OUTPUT_DIR/many only with `--only many` (alone; bench/bench.py does it
into out/bench: their STEP files are megabytes, too large to bundle).
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
    """Build a closed planar profile in the XZ plane (y = 0) (profile_surface)
    and extrude it by `length` along +Y. Returns the tag of the resulting
    volume."""
    out = occ.extrude([(2, profile_surface(segments))], 0.0, length, 0.0)
    vols = [tag for dim, tag in out if dim == 3]
    assert len(vols) == 1, out
    return vols[0]


def profile_surface(segments):
    """A closed planar profile in the XZ plane (y = 0) as a plane surface;
    returns its tag.

    `segments` is a closed chain of ("line", (x1, z1), (x2, z2)),
    ("arc", (x1, z1), (xc, zc), (x2, z2)) and ("semi", (x1, z1), (xt, zt),
    (x2, z2)) items; consecutive items share their end / start points
    exactly. A "semi" is a half circle (one edge) from (x1, z1) to (x2, z2)
    through its midpoint (xt, zt); its centre is the midpoint of the ends.
    """
    points = {}

    def key(p):
        return (round(p[0], 12), round(p[1], 12))

    def pt(p):
        if key(p) not in points:
            points[key(p)] = occ.addPoint(p[0], 0.0, p[1])
        return points[key(p)]

    # Half circles first (profiles without them make the same calls as
    # before): addCircleArc cannot make a 180° arc (start, centre and end are
    # collinear), so each is a circle arc made with angle limits in the XY
    # plane, turned into the XZ plane; its two end vertices then become the
    # profile's points there, so that the neighbouring lines share them.
    semis = {}
    for i, seg in enumerate(segments):
        if seg[0] != "semi":
            continue
        (x1, z1), (xt, zt), (x2, z2) = seg[1], seg[2], seg[3]
        xc, zc = (x1 + x2) / 2, (z1 + z2) / 2
        r = math.hypot(x1 - xc, z1 - zc)
        assert abs(math.hypot(xt - xc, zt - zc) - r) < 1e-12, f"semi {i}: tip not on the circle"
        assert abs((xt - xc) * (x1 - xc) + (zt - zc) * (z1 - zc)) < 1e-12, \
            f"semi {i}: tip not halfway"
        at = math.atan2(zt - zc, xt - xc)
        before = set(occ.getEntities(0))
        c = occ.addCircle(0.0, 0.0, 0.0, r, angle1=at - PI / 2, angle2=at + PI / 2)
        occ.rotate([(1, c)], 0, 0, 0, 1, 0, 0, PI / 2)     # (x, y, 0) -> (x, 0, y)
        occ.translate([(1, c)], xc, 0.0, zc)
        ends = sorted(set(occ.getEntities(0)) - before)
        assert len(ends) == 2, ends
        for p in (seg[1], seg[3]):
            near = []
            for _, v in ends:
                b = occ.getBoundingBox(0, v)
                if math.hypot((b[0] + b[3]) / 2 - p[0], (b[2] + b[5]) / 2 - p[1]) < 1e-9:
                    near.append(v)
            assert len(near) == 1 and key(p) not in points, (i, p, near)
            points[key(p)] = near[0]
        semis[i] = c

    curves = []
    centres = set()
    for i, seg in enumerate(segments):
        nxt = segments[(i + 1) % len(segments)]
        assert seg[-1] == nxt[1], f"profile not closed between items {i} and {i + 1}"
        if seg[0] == "semi":
            curves.append(semis[i])
        elif seg[0] == "line":
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
    return occ.addPlaneSurface([loop])


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


def rounded_open_box(L, W, H, r, t):
    """Open-top box: the outer solid [0,L]x[0,W]x[0,H] with its vertical and
    bottom edges rounded r (exact cylinders and sphere corners) minus the inner
    one offset inward by the wall t (radius r - t), which sticks out through
    the top, so the wall is t everywhere and the open top is a flat rim at
    z = H. Returns (volume tag, analytic volume)."""
    outer = filleted_box(0, 0, 0, L, W, H, r)
    inner = filleted_box(t, t, t, L - 2 * t, W - 2 * t, H, r - t)   # top at z = H + t
    out, _ = occ.cut([(3, outer)], [(3, inner)])
    vols = [tag for dim, tag in out if dim == 3]
    assert len(vols) == 1, out
    vol = filleted_box_volume(L, W, H, r) - filleted_box_volume(L - 2 * t, W - 2 * t, H - t, r - t)
    return vols[0], vol


def housing():
    # Open-top box housing, outside 80 x 60 x 30, edges R8, wall 2.5.
    _, vol = rounded_open_box(80.0, 60.0, 30.0, 8.0, 2.5)
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
# Bent boxes (written after the junction parts, see main): open boxes whose
# walls meet the floor and each other in SHARP inside edges, as a sheet-metal
# or molded box often does, their outside edges sharp or rounded by less than
# the wall. One sheet bent with a zero inside radius, not walls standing on
# walls.
# ---------------------------------------------------------------------------

# Outside 60 x 40 x 20, wall 2, open at z = 20 (a flat rim).
SHARP_BOX = (60.0, 40.0, 20.0, 2.0)


def sharp_inside_box(r, L=SHARP_BOX[0], W=SHARP_BOX[1], H=SHARP_BOX[2], t=SHARP_BOX[3]):
    """The open box with its 4 vertical and 4 bottom outside edges rounded r
    (exact quarter cylinders, eighth spheres at the bottom corners; r = 0:
    sharp) minus the sharp inner box (the hollow, through the top): every
    inside edge and corner sharp. Returns (volume tag, analytic volume)."""
    outer = filleted_box(0, 0, 0, L, W, H, r) if r > 0 else occ.addBox(0, 0, 0, L, W, H)
    inner = occ.addBox(t, t, t, L - 2 * t, W - 2 * t, H)    # top at z = H + t
    vol = one_volume(occ.cut([(3, outer)], [(3, inner)])[0])
    outside = filleted_box_volume(L, W, H, r) if r > 0 else L * W * H
    return vol, outside - (L - 2 * t) * (W - 2 * t) * (H - t)


def box_dims(r, extra=""):
    rounds = f"outside vertical and bottom edges rounded R{r:g}" if r > 0 else "outside edges sharp"
    return (f"open box, outside {SHARP_BOX[0]:g} × {SHARP_BOX[1]:g} × {SHARP_BOX[2]:g}, inside edges and corners "
            f"sharp, {rounds}{extra}, top open (a flat rim)")


def box_sharp_inside():
    _, volume = sharp_inside_box(1.0)
    return volume, dict(dims=box_dims(1.0, " (0.5 × the wall; eighth spheres at the bottom corners)"), wall="2")


def box_sharp():
    _, volume = sharp_inside_box(0.0)
    return volume, dict(dims=box_dims(0.0), wall="2")


def box_sharp_inside_r025():
    _, volume = sharp_inside_box(0.5)
    return volume, dict(dims=box_dims(0.5, " (0.25 × the wall)"), wall="2")


def box_sharp_inside_metres():
    vol, volume = sharp_inside_box(1.0)
    occ.dilate([(3, vol)], 0, 0, 0, 1e-3, 1e-3, 1e-3)   # OpenCASCADE writes the planes as B-splines
    return volume * 1e-9, dict(dims="box_sharp_inside scaled by 1e-3 (in metres, written as mm: 0.06 × 0.04 "
                                     "× 0.02; planes as B-spline surfaces)", wall="0.002")


def box_sharp_inside_split():
    """box_sharp_inside cut at x = 24 and fused again without unifying: the
    floor's faces, the long walls' faces and the bottom rounds along x split
    in two at the seam."""
    vol, volume = sharp_inside_box(1.0)
    left = one_volume(occ.intersect([(3, vol)], [(3, occ.addBox(-1, -1, -1, 25, 42, 22))], removeTool=True)[0])
    vol2, _ = sharp_inside_box(1.0)
    right = one_volume(occ.intersect([(3, vol2)], [(3, occ.addBox(24, -1, -1, 40, 42, 22))], removeTool=True)[0])
    fuse_volumes([left, right], unify=False)
    return volume, dict(dims=box_dims(1.0, "; fused from its halves x ≤ 24 and x ≥ 24 not unified: the floor's, "
                                           "the long walls' and the bottom rounds' faces split at x = 24"), wall="2")


def box_sharp_holes():
    """box_sharp_inside_r025 with a hole in each long wall and in the floor: a
    round hole D10 through the wall y = 0 (centre x = 30, z = 10), a window
    16 x 8 through the wall y = 40 (x 22..38, z 6..14), a hole D8 through the
    floor at (20, 20): faces with holes for the patch grid."""
    vol, volume = sharp_inside_box(0.5)
    t = SHARP_BOX[3]
    tools = [(3, occ.addCylinder(30, -1, 10, 0, t + 2, 0, 5)), (3, occ.addBox(22, 37, 6, 16, t + 2, 8)),
             (3, occ.addCylinder(20, 20, -1, 0, 0, t + 2, 4))]
    one_volume(occ.cut([(3, vol)], tools)[0])
    volume -= (math.pi * 25 + 16 * 8 + math.pi * 16) * t
    return volume, dict(dims=box_dims(0.5, "; holes through the walls and the floor: D10 in the wall y = 0 at "
                                           "x = 30, z = 10; a window 16 × 8 in the wall y = 40 (x 22..38, z 6..14); "
                                           "D8 in the floor at (20, 20)"), wall="2")


def box_foot():
    """The foot of a U-channel (the Ender-3 support frame's, simplified): a
    foot plate 40 x 30 x 2 and a web 2 thick standing on its edge x = 0 over
    its whole width (one sheet bent sharp), two flanges 2 thick on its edges
    y = 0 and y = 30 for x < 20 only, all 30 high: walls standing on the foot
    that runs on past them (T junctions). Every edge sharp but the foot's two
    far corners (vertical edges at x = 40, rounded R3); two holes D5 in the
    foot at (30, 8) and (30, 22), a hole D10 through the web at
    (y, z) = (15, 18)."""
    pieces = [occ.addBox(0, 0, 0, 40, 30, 2), occ.addBox(0, 0, 0, 2, 30, 30), occ.addBox(0, 0, 0, 20, 2, 30),
              occ.addBox(0, 28, 0, 20, 2, 30)]
    vol = fuse_volumes(pieces)
    occ.synchronize()
    corners = [c for y in (0, 30) for _, c in gmsh.model.getEntitiesInBoundingBox(39.9, y - 0.1, -0.1, 40.1, y + 0.1,
                                                                                  2.1, 1)]
    assert len(corners) == 2, corners
    vol = one_volume(occ.fillet([vol], corners, [3.0]))
    vol = drill(vol, [(30, 8, 0, 2, 5), (30, 22, 0, 2, 5)])
    one_volume(occ.cut([(3, vol)], [(3, occ.addCylinder(-1, 15, 18, 4, 0, 0, 5))])[0])
    volume = 40 * 30 * 2 + 2 * 30 * 28 + 2 * 18 * 2 * 28 - 2 * (1 - math.pi / 4) * 9 * 2
    volume -= 2 * math.pi * 2.5 ** 2 * 2 + math.pi * 25 * 2
    return volume, dict(dims="foot 40 × 30 × 2, a web (x 0..2) over its width and flanges (y 0..2, 28..30) for "
                             "x < 20, all 30 high; sharp edges but the foot's far corners R3; holes D5 in the foot, "
                             "D10 in the web", wall="2")


def box_l_shape():
    """An open box on an L-shaped floor (60 x 40 and 30 x 30 on its side), wall 2, 20 high, every edge sharp: its
    floor has six corners, one reflex (the patch grid cuts it there in two)."""
    outer = fuse_volumes([occ.addBox(0, 0, 0, 60, 40, 20), occ.addBox(0, 40, 0, 30, 30, 20)])
    inner = fuse_volumes([occ.addBox(2, 2, 2, 56, 36, 20), occ.addBox(2, 2, 2, 26, 66, 20)])
    one_volume(occ.cut([(3, outer)], [(3, inner)])[0])
    volume = (60 * 40 + 30 * 30) * 20 - (56 * 36 + 26 * 30) * 18
    return volume, dict(dims="open box on an L-shaped floor (60 × 40 with 30 × 30 on its side at x 0..30), 20 high, "
                             "every edge sharp, top open (a flat rim)", wall="2")


def box_close_holes():
    """box_sharp with two holes D6 through its floor 8 apart (centres (26, 20) and (34, 20)): a wall of 2 between
    them, less than their pockets need (a quad beyond each hole): the floor is the shared grid's, its lines between
    the holes."""
    vol, volume = sharp_inside_box(0.0)
    drill(vol, [(26, 20, 0, SHARP_BOX[3], 6), (34, 20, 0, SHARP_BOX[3], 6)])
    volume -= 2 * math.pi * 9 * SHARP_BOX[3]
    return volume, dict(dims=box_dims(0.0, "; two holes D6 through the floor at (26, 20) and (34, 20)"), wall="2")


def box_diagonal_holes():
    """box_sharp with two holes D6 through its floor on a diagonal, centres (25, 16) and (31, 22): 2.5 apart, their
    extents overlapping along both axes, so that neither the pockets nor the shared grid's lines can part them (Gmsh's
    quads; test_cli_progress's quad budgets)."""
    vol, volume = sharp_inside_box(0.0)
    drill(vol, [(25, 16, 0, SHARP_BOX[3], 6), (31, 22, 0, SHARP_BOX[3], 6)])
    volume -= 2 * math.pi * 9 * SHARP_BOX[3]
    return volume, dict(dims=box_dims(0.0, "; two holes D6 through the floor at (25, 16) and (31, 22)"), wall="2")


def vertical_curves(vol):
    """Edges of `vol` parallel to z (bounding boxes are padded by the tolerance: compare with 1e-3)."""
    out = []
    for c in solid_curves(vol):
        xmin, ymin, _, xmax, ymax, _ = gmsh.model.getBoundingBox(1, c)
        if xmax - xmin < 1e-3 and ymax - ymin < 1e-3:
            out.append(c)
    return out


def chamfer_curves(vol, curves, d):
    """`vol` with the given edges chamfered d x d (45 degrees), each measured on a face next to it."""
    occ.synchronize()
    faces = [gmsh.model.getAdjacencies(1, c)[0][0] for c in curves]
    return one_volume(occ.chamfer([vol], curves, faces, [d] * len(curves)))


def box_chamfered():
    """box_sharp with its 4 vertical and 4 bottom outside edges chamfered 1.5 x 1.5 (45 degrees; a triangle where
    three meet at a bottom corner), every inside edge sharp: the chamfers are the outsides of bends (bend_rounds.hpp).
    The outer box loses c^2 / 2 along each chamfered edge, less 8 c^3 / 3 over the four bottom corners (the prisms'
    overlaps and the corner triangle's tetrahedron)."""
    L, W, H, t = SHARP_BOX
    c = 1.5
    outer = occ.addBox(0, 0, 0, L, W, H)
    outer = chamfer_curves(outer, vertical_curves(outer) + horizontal_curves(outer, 0.0), c)
    inner = occ.addBox(t, t, t, L - 2 * t, W - 2 * t, H)
    one_volume(occ.cut([(3, outer)], [(3, inner)])[0])
    volume = L * W * H - (c * c / 2 * (2 * L + 2 * W + 4 * H) - 8 * c ** 3 / 3) - (L - 2 * t) * (W - 2 * t) * (H - t)
    return volume, dict(dims=box_dims(0.0).replace("outside edges sharp", "outside vertical and bottom edges "
                                                   "chamfered 1.5 × 1.5 (45°)"), wall="2")


def rounded_rectangle_area(a, b, r):
    return a * b - (4 - PI) * r * r


def tray_chamfered():
    """A molded cover's edge (the Framework top cover's, simplified): a tray 80 x 50 x 8, floor 2 (z 0..2), walls 3
    thick, vertical corners rounded R6 outside (R3 inside); the floor's outside edge chamfered 3 x 3 (45 degrees: a
    cone round each corner), its inside edge chamfered 1 x 1. Volume: the rounded prisms less each chamfer's triangle
    swept along the straight edges and, by Pappus, round the corners (its centroid c / 3 in from the edge)."""
    L, W, H, floor, wall, R, c_out, c_in = 80.0, 50.0, 8.0, 2.0, 3.0, 6.0, 3.0, 1.0
    outer = occ.addBox(0, 0, 0, L, W, H)
    outer = one_volume(occ.fillet([outer], vertical_curves(outer), [R]))
    outer = chamfer_curves(outer, horizontal_curves(outer, 0.0), c_out)
    inner = occ.addBox(wall, wall, floor, L - 2 * wall, W - 2 * wall, H)
    inner = one_volume(occ.fillet([inner], vertical_curves(inner), [R - wall]))
    inner = chamfer_curves(inner, horizontal_curves(inner, floor), c_in)
    one_volume(occ.cut([(3, outer)], [(3, inner)])[0])
    straight = 2 * (L - 2 * R) + 2 * (W - 2 * R)

    def chamfer(c, r):
        return c * c / 2 * (straight + 2 * PI * (r - c / 3))

    volume = (rounded_rectangle_area(L, W, R) * H - chamfer(c_out, R)
              - (rounded_rectangle_area(L - 2 * wall, W - 2 * wall, R - wall) * (H - floor) - chamfer(c_in, R - wall)))
    return volume, dict(dims="tray 80 × 50 × 8, floor 2, walls 3, vertical corners R6 outside (R3 inside), the floor's "
                             "outside edge chamfered 3 × 3 (45°), its inside edge 1 × 1, top open (a flat rim)",
                        wall="2 (floor), 3 (walls)", max_bytes=128 * 1024)


def box_rounded_low():
    """A low open box (a tray or a cover's rim) 80 x 50 x 8, wall 2, its vertical corners rounded R6 outside (R4
    inside), the floor's edges sharp inside and out: walls only three times as high as they are thick, whose tears
    (tets across the floor's sharp inside edge dropped as outside) lie near the rim (chordal_rim.hpp's fillTears)."""
    L, W, H, t, R = 80.0, 50.0, 8.0, 2.0, 6.0
    outer = occ.addBox(0, 0, 0, L, W, H)
    outer = one_volume(occ.fillet([outer], vertical_curves(outer), [R]))
    inner = occ.addBox(t, t, t, L - 2 * t, W - 2 * t, H)
    inner = one_volume(occ.fillet([inner], vertical_curves(inner), [R - t]))
    one_volume(occ.cut([(3, outer)], [(3, inner)])[0])
    volume = rounded_rectangle_area(L, W, R) * H - rounded_rectangle_area(L - 2 * t, W - 2 * t, R - t) * (H - t)
    return volume, dict(dims="open box 80 × 50 × 8, vertical corners R6 outside (R4 inside), floor edges sharp, top "
                             "open (a flat rim)", wall="2")


# Written to OUTPUT_DIR after the rim and junction parts (their STEP files stay byte-identical: OpenCASCADE
# numbers the PRODUCT name by the count of files written in the session) and listed in its README.
BENT_BOX_PARTS = [
    ("box_sharp_inside", box_sharp_inside),
    ("box_sharp", box_sharp),
    ("box_sharp_inside_r025", box_sharp_inside_r025),
    ("box_sharp_inside_metres", box_sharp_inside_metres),
    ("box_sharp_inside_split", box_sharp_inside_split),
    ("box_sharp_holes", box_sharp_holes),
    ("box_foot", box_foot),
    ("box_l_shape", box_l_shape),
    ("box_close_holes", box_close_holes),
    ("box_diagonal_holes", box_diagonal_holes),
    ("box_chamfered", box_chamfered),
    ("tray_chamfered", tray_chamfered),
    ("box_rounded_low", box_rounded_low),
]

# ---------------------------------------------------------------------------
# Rim parts (written to the subfolder rims/): thin parts whose rims -- the
# faces across the wall at its free edges -- are not plain flat faces normal
# to the wall, or whose faces are split into several faces where one would do.
# ---------------------------------------------------------------------------

def solid_curves(vol):
    """Tags of the edges of volume `vol` (synchronizes the model)."""
    occ.synchronize()
    return sorted({abs(c) for _, f in gmsh.model.getBoundary([(3, vol)], combined=False,
                                                             oriented=False)
                   for _, c in gmsh.model.getBoundary([(2, f)], combined=False,
                                                      oriented=False)})


def horizontal_curves(vol, z):
    """Edges of `vol` lying in the plane z = const (bounding boxes are padded
    by the tolerance: compare with 1e-3)."""
    out = []
    for c in solid_curves(vol):
        _, _, zmin, _, _, zmax = gmsh.model.getBoundingBox(1, c)
        if zmax - zmin < 1e-3 and abs((zmin + zmax) / 2 - z) < 1e-3:
            out.append(c)
    return out


def horizontal_face(vol, z):
    """The one face of `vol` lying in the plane z = const."""
    occ.synchronize()
    found = []
    for _, f in gmsh.model.getBoundary([(3, vol)], combined=False, oriented=False):
        _, _, zmin, _, _, zmax = gmsh.model.getBoundingBox(2, abs(f))
        if zmax - zmin < 1e-3 and abs((zmin + zmax) / 2 - z) < 1e-3:
            found.append(abs(f))
    assert len(found) == 1, found
    return found[0]


def one_volume(out):
    vols = [tag for dim, tag in out if dim == 3]
    assert len(vols) == 1, out
    return vols[0]


def fuse_volumes(tags, unify=True):
    """Fuse the volumes `tags` into one solid and return its tag. With `unify`
    False OpenCASCADE's face unification is off (Geometry.OCCUnionUnify 0), so
    coplanar faces stay split along the seams of the pieces."""
    saved = gmsh.option.getNumber("Geometry.OCCUnionUnify")
    gmsh.option.setNumber("Geometry.OCCUnionUnify", 1 if unify else 0)
    try:
        out, _ = occ.fuse([(3, tags[0])], [(3, t) for t in tags[1:]])
    finally:
        gmsh.option.setNumber("Geometry.OCCUnionUnify", saved)
    return one_volume(out)


def extrude_polygon_xy(pts, h):
    """Closed polygon in the plane z = 0 (one line per pair of consecutive
    points, collinear points kept), extruded by h along +Z."""
    p = [occ.addPoint(x, y, 0.0) for x, y in pts]
    lines = [occ.addLine(p[i], p[(i + 1) % len(p)]) for i in range(len(p))]
    surf = occ.addPlaneSurface([occ.addCurveLoop(lines)])
    return one_volume(occ.extrude([(2, surf)], 0.0, 0.0, h))


def half_space_y_tilt(z0, deg, above):
    """A box standing for the half-space above (or below) the plane through
    (0, 0, z0) whose normal is +Z turned by `deg` degrees about the Y axis,
    i.e. (sin deg, 0, cos deg); 100 mm across, enough for the tubes."""
    box = occ.addBox(-50.0, -50.0, z0 if above else z0 - 100.0, 100.0, 100.0, 100.0)
    occ.rotate([(3, box)], 0.0, 0.0, z0, 0.0, 1.0, 0.0, math.radians(deg))
    return box


def semicircle_area(t):
    return PI * (t / 2) ** 2 / 2


def lbracket_round_ends():
    # As lbracket (outer corner at the origin, legs to the outer faces x = 0
    # and z = 0), t = 2, bend R2 / R4. Each free end is a half circle of
    # radius t/2 centred on the mid-surface, tangent to both walls; its tip
    # is at x = H (horizontal leg) and z = V (vertical leg).
    t, ri, H, V, W = 2.0, 2.0, 40.0, 30.0, 20.0
    ro, h = ri + t, t / 2
    c = (ro, ro)
    segs = [
        ("line", (H - h, 0.0), (ro, 0.0)),           # outer face of horizontal leg
        ("arc", (ro, 0.0), c, (0.0, ro)),            # outer bend, R = ro
        ("line", (0.0, ro), (0.0, V - h)),           # outer face of vertical leg
        ("semi", (0.0, V - h), (h, V), (t, V - h)),  # top end, full round
        ("line", (t, V - h), (t, ro)),               # inner face of vertical leg
        ("arc", (t, ro), c, (ro, t)),                # inner bend, R = ri
        ("line", (ro, t), (H - h, t)),               # inner face of horizontal leg
        ("semi", (H - h, t), (H, h), (H - h, 0.0)),  # free end, full round
    ]
    extrude_profile(segs, W)
    area = ((H - h - ro) * t + (V - h - ro) * t + quarter_annulus(ri, ro)
            + 2 * semicircle_area(t))
    return area * W, dict(dims="L-bracket, legs 40 (horizontal) × 30 (vertical) to "
                               "outer faces / end tips, width 20, bend R2 inner / R4 "
                               "outer; both free ends full round (half circle R1)",
                          wall="2")


def uchannel_round_ends():
    # As uchannel (web z in [0, t], x in [0, B]; flange tips at z = Hf), length
    # 40; each flange end is a half circle of radius t/2 with its tip at z = Hf.
    t, ri, B, Hf, L = 2.0, 2.0, 30.0, 20.0, 40.0
    ro, h = ri + t, t / 2
    cl, cr = (ro, ro), (B - ro, ro)
    segs = [
        ("line", (0.0, Hf - h), (0.0, ro)),                 # left flange, outside
        ("arc", (0.0, ro), cl, (ro, 0.0)),                  # left bend, outer
        ("line", (ro, 0.0), (B - ro, 0.0)),                 # web, outside
        ("arc", (B - ro, 0.0), cr, (B, ro)),                # right bend, outer
        ("line", (B, ro), (B, Hf - h)),                     # right flange, outside
        ("semi", (B, Hf - h), (B - h, Hf), (B - t, Hf - h)),  # right flange end
        ("line", (B - t, Hf - h), (B - t, ro)),             # right flange, inside
        ("arc", (B - t, ro), cr, (B - ro, t)),              # right bend, inner
        ("line", (B - ro, t), (ro, t)),                     # web, inside
        ("arc", (ro, t), cl, (t, ro)),                      # left bend, inner
        ("line", (t, ro), (t, Hf - h)),                     # left flange, inside
        ("semi", (t, Hf - h), (h, Hf), (0.0, Hf - h)),      # left flange end
    ]
    extrude_profile(segs, L)
    area = ((B - 2 * ro) * t + 2 * (Hf - h - ro) * t + 2 * quarter_annulus(ri, ro)
            + 2 * semicircle_area(t))
    return area * L, dict(dims="U-channel, web 30 wide × flanges 20 high (outside, "
                               "to the tips), length 40, bends R2 inner / R4 outer; "
                               "flange ends full round (half circle R1)", wall="2")


def hat_round_ends():
    # hat_holes' profile (overall 60 × 20, bends R2 / R3.5) without the holes,
    # length 40; each flange end is a half circle of radius t/2 with its tip
    # at x = 0 / x = 60.
    t, ri, F, Hh, T, L = 1.5, 2.0, 15.0, 20.0, 30.0, 40.0
    ro, h = ri + t, t / 2
    Wt = 2 * F + T
    xl, xr = F, F + T
    cbl = (xl - ri, t + ri)
    ctl = (xl + ro, Hh - ro)
    ctr = (xr - ro, Hh - ro)
    cbr = (xr + ri, t + ri)
    segs = [
        ("line", (h, 0.0), (cbl[0], 0.0)),                   # left flange bottom
        ("arc", (cbl[0], 0.0), cbl, (xl + t, cbl[1])),       # bottom-left bend, R = ro
        ("line", (xl + t, cbl[1]), (xl + t, ctl[1])),        # left wall, inside
        ("arc", (xl + t, ctl[1]), ctl, (ctl[0], Hh - t)),    # top-left bend, R = ri
        ("line", (ctl[0], Hh - t), (ctr[0], Hh - t)),        # top, underside
        ("arc", (ctr[0], Hh - t), ctr, (xr - t, ctr[1])),    # top-right bend, R = ri
        ("line", (xr - t, ctr[1]), (xr - t, cbr[1])),        # right wall, inside
        ("arc", (xr - t, cbr[1]), cbr, (cbr[0], 0.0)),       # bottom-right bend, R = ro
        ("line", (cbr[0], 0.0), (Wt - h, 0.0)),              # right flange bottom
        ("semi", (Wt - h, 0.0), (Wt, h), (Wt - h, t)),       # right flange end
        ("line", (Wt - h, t), (cbr[0], t)),                  # right flange top
        ("arc", (cbr[0], t), cbr, (xr, cbr[1])),             # bottom-right bend, R = ri
        ("line", (xr, cbr[1]), (xr, ctr[1])),                # right wall, outside
        ("arc", (xr, ctr[1]), ctr, (ctr[0], Hh)),            # top-right bend, R = ro
        ("line", (ctr[0], Hh), (ctl[0], Hh)),                # top, outside
        ("arc", (ctl[0], Hh), ctl, (xl, ctl[1])),            # top-left bend, R = ro
        ("line", (xl, ctl[1]), (xl, cbl[1])),                # left wall, outside
        ("arc", (xl, cbl[1]), cbl, (cbl[0], t)),             # bottom-left bend, R = ri
        ("line", (cbl[0], t), (h, t)),                       # left flange top
        ("semi", (h, t), (0.0, h), (h, 0.0)),                # left flange end
    ]
    extrude_profile(segs, L)
    area = (2 * (cbl[0] - h) * t                  # flanges (straight part)
            + 2 * (ctl[1] - cbl[1]) * t           # walls
            + (ctr[0] - ctl[0]) * t               # top
            + 4 * quarter_annulus(ri, ro)         # bends
            + 2 * semicircle_area(t))             # round ends
    return area * L, dict(
        dims="hat section as hat_holes without holes (flanges 15, walls 20 high, "
             "top 30 wide outside; overall 60 × 20), length 40, bends R2 inner / "
             "R3.5 outer; flange ends full round (half circle R0.75)",
        wall="1.5")


def rounded_corner_plate(L, W, t, R):
    """Box [0,L]x[0,W]x[0,t] with its 4 vertical edges rounded R."""
    box = occ.addBox(0, 0, 0, L, W, t)
    vertical = []
    for c in solid_curves(box):
        _, _, zmin, _, _, zmax = gmsh.model.getBoundingBox(1, c)
        if zmax - zmin > 1e-3:
            vertical.append(c)
    assert len(vertical) == 4, vertical
    return one_volume(occ.fillet([box], vertical, [R]))


def plate_rim_fillets(r):
    """Plate 50 x 30 x 2, vertical corners R5, then all 16 top and bottom
    perimeter edges (4 lines + 4 corner arcs each side) filleted with r < t/2.

    Volume: the rounded-corner plate, (L W - (4 - pi) R^2) t, minus, for each
    of the two sides, the material the fillet takes off: the cross-section
    A = r^2 (1 - pi/4) (square r x r minus a quarter disc) swept along the 4
    straight edges (total length Ls = 2 (L - 2R) + 2 (W - 2R)) and, by Pappus,
    turned by a quarter turn about each vertical corner axis at the distance
    of its centroid, rc = (R - r) + 2 r / (3 (4 - pi)) (centroid of the
    spandrel from the quarter disc's centre, 2 r / (3 (4 - pi)) along each
    axis, since (r^2 r/2 - pi r^2/4 4r/(3 pi)) / A = 2 r / (3 (4 - pi))):
        V = (L W - (4 - pi) R^2) t - 2 A (Ls + 4 (pi/2) rc).
    """
    L, W, t, R = 50.0, 30.0, 2.0, 5.0
    assert 2 * r < t
    vol = rounded_corner_plate(L, W, t, R)
    edges = horizontal_curves(vol, 0.0) + horizontal_curves(vol, t)
    assert len(edges) == 16, edges
    one_volume(occ.fillet([vol], edges, [r]))
    A = r * r * (1 - PI / 4)
    Ls = 2 * (L - 2 * R) + 2 * (W - 2 * R)
    rc = (R - r) + 2 * r / (3 * (4 - PI))
    return (L * W - (4 - PI) * R * R) * t - 2 * A * (Ls + 2 * PI * rc)


def plate_full_round():
    # r = 0.49 t works in OpenCASCADE 7.6 (0.04 mm of flat rim left between
    # the top and the bottom fillet).
    r = 0.49 * 2.0
    return plate_rim_fillets(r), dict(
        dims="50 × 30 × 2 plate, vertical corners R5, top and bottom perimeter "
             "edges filleted r = 0.98 (= 0.49 t: near-full-round rim, 0.04 flat)",
        wall="2")


def plate_fillet_flat_fillet():
    r = 0.3 * 2.0
    return plate_rim_fillets(r), dict(
        dims="50 × 30 × 2 plate, vertical corners R5, top and bottom perimeter "
             "edges filleted r = 0.6 (= 0.3 t; 0.8 flat rim strip between)",
        wall="2")


def chamfered_plate(d, zs):
    """Box 50 x 30 x 2 with the perimeter edges in the planes z in `zs`
    chamfered d x d (45°). Each chamfered side takes off a layer of height d
    that is a prismatoid with ends L x W and (L - 2d) x (W - 2d) and mid
    section (L - d) x (W - d), of volume d/6 (A0 + 4 Am + A1) (exact for a
    prismatoid)."""
    L, W, t = 50.0, 30.0, 2.0
    box = occ.addBox(0, 0, 0, L, W, t)
    edges, faces = [], []
    for z in zs:
        es = horizontal_curves(box, z)
        assert len(es) == 4, es
        edges += es
        faces += [horizontal_face(box, z)] * len(es)
    one_volume(occ.chamfer([box], edges, faces, [d]))
    layer = d / 6 * (L * W + 4 * (L - d) * (W - d) + (L - 2 * d) * (W - 2 * d))
    return L * W * (t - len(zs) * d) + len(zs) * layer


def plate_chamfer_one_side():
    return chamfered_plate(1.0, [2.0]), dict(
        dims="50 × 30 × 2 plate, top perimeter edges chamfered 1 × 1 (45°, 0.5 t), "
             "bottom edges and vertical corners sharp", wall="2")


def plate_chamfer_both_sides():
    return chamfered_plate(0.8, [0.0, 2.0]), dict(
        dims="50 × 30 × 2 plate, top and bottom perimeter edges chamfered 0.8 × 0.8 "
             "(45°, 0.4 t; 0.4 flat rim strip between), vertical corners sharp",
        wall="2")


def oblique_strip(s):
    """Strip 60 x 20 x 2: profile in XZ a parallelogram, bottom x in [0, 60],
    top x in [s, 60 + s] (both ends slanted the same way, parallel end
    planes), extruded 20 along +Y. Area = base x height = 60 t."""
    L, W, t = 60.0, 20.0, 2.0
    extrude_profile([
        ("line", (0.0, 0.0), (L, 0.0)),
        ("line", (L, 0.0), (L + s, t)),
        ("line", (L + s, t), (s, t)),
        ("line", (s, t), (0.0, 0.0)),
    ], W)
    return L * W * t


def strip_oblique_45():
    t = 2.0
    return oblique_strip(t), dict(
        dims="60 × 20 × 2 strip, both short ends cut by parallel planes tilted "
             "45° about Y (end faces 2√2 = 2.83 wide, meeting top / bottom at "
             "45° / 135°); bottom x 0…60, top x 2…62", wall="2")


def strip_oblique_3x():
    t = 2.0
    s = math.sqrt((3 * t) ** 2 - t ** 2)    # end face 3 t wide: offset 2√2 t
    return oblique_strip(s), dict(
        dims="60 × 20 × 2 strip, both short ends cut by parallel planes tilted "
             "acos(1/3) = 70.5° about Y (end faces 6 = 3 t wide, sharp 19.5° "
             "edges); bottom x 0…60, top x 5.66…65.66", wall="2")


# OpenCASCADE integrates the volume of the extruded rational B-spline face to about 1e-3 (the prism's exact
# volume is the profile's area x W, which its side faces' areas give to 4e-6).
SKIN_VOLUME_TOLERANCE = 2e-3


def skin_strip(L, W, t, wrap=False):
    """Strip L x W x t whose top wall and full-round right end are ONE face: the XZ profile's top line and
    its half circle (radius t/2, centred on the mid-surface, tangent to both walls) are one rational
    quadratic B-spline (control points on the line, then two exact quarter circles, knots at the
    joins), extruded W along +Y: a skin that runs over the wall and wraps round its edge, as other
    CAD systems write a rounded rim. The bottom and the square left end are faces of their own; with
    `wrap`, the bottom line is part of the same B-spline (one face over the top wall, the round end and
    the bottom wall). Area = L t + pi t^2 / 8, checked on 4000 points of the skin (OpenCASCADE integrates the
    rational faces less exactly: SKIN_VOLUME_TOLERANCE, and 20 x that wrapped)."""
    r, w = t / 2, math.sqrt(0.5)
    xz = [(0, t), (L / 2, t), (L, t), (L + r, t), (L + r, r), (L + r, 0), (L, 0)]
    weights, knots, multiplicities = [1, 1, 1, w, 1, w, 1], [0, 1, 2, 3], [3, 2, 2, 3]
    if wrap:
        xz += [(L / 2, 0), (0, 0)]
        weights, knots, multiplicities = weights + [1, 1], knots + [4], [3, 2, 2, 2, 3]
    pts = [occ.addPoint(x, 0, z) for x, z in xz]
    skin = occ.addBSpline(pts, degree=2, weights=weights, knots=knots, multiplicities=multiplicities)
    occ.remove([(0, p) for p in pts[1:-1]])  # the inner control points are not vertices of the part
    if wrap:
        loop = occ.addCurveLoop([skin, occ.addLine(pts[-1], pts[0])])
    else:
        corner = occ.addPoint(0, 0, 0)
        loop = occ.addCurveLoop([skin, occ.addLine(pts[-1], corner), occ.addLine(corner, pts[0])])
    end = occ.addPlaneSurface([loop])
    area = L * t + math.pi * t * t / 8
    occ.synchronize()
    lo, hi = gmsh.model.getParametrizationBounds(1, skin)  # the profile's area from 4000 points on the skin
    xyz = gmsh.model.getValue(1, skin, [lo[0] + (hi[0] - lo[0]) * k / 4000 for k in range(4001)])
    x, z = list(xyz[0::3]) + ([] if wrap else [0.0]), list(xyz[2::3]) + ([] if wrap else [0.0])  # + the corner
    polygon = 0.5 * abs(sum(x[k] * z[k - 1] - x[k - 1] * z[k] for k in range(len(x))))
    assert abs(polygon - area) <= 1e-6 * area, (polygon, area)
    occ.extrude([(2, end)], 0, W, 0)
    return area * W


def strip_skin_round():
    return skin_strip(40.0, 20.0, 2.0), dict(
        dims="40 × 20 × 2 strip with a full-round right end; the top wall and the round end are one "
             "B-spline face (a skin wrapping the edge), bottom and left end separate", wall="2",
        volume_tolerance=SKIN_VOLUME_TOLERANCE)


def strip_skin_round_thin():
    return skin_strip(30.0, 15.0, 1.0), dict(
        dims="30 × 15 × 1 strip, the same skin (top wall and full-round end one B-spline face) at "
             "half the wall", wall="1", volume_tolerance=SKIN_VOLUME_TOLERANCE)


def strip_skin_wrap():
    return skin_strip(40.0, 20.0, 2.0, wrap=True), dict(
        dims="40 × 20 × 2 strip with a full-round right end; the top wall, the round end and the bottom "
             "wall are one B-spline face (a skin wrapping the strip's end), the left end separate", wall="2",
        volume_tolerance=20 * SKIN_VOLUME_TOLERANCE)


def plate_split_rim():
    # Each side of the 50 x 30 outline has two extra (collinear) points, at
    # different places on opposite sides, so each side face is 3 faces.
    L, W, t = 50.0, 30.0, 2.0
    extrude_polygon_xy([
        (0.0, 0.0), (15.0, 0.0), (35.0, 0.0),
        (L, 0.0), (L, 8.0), (L, 20.0),
        (L, W), (40.0, W), (20.0, W),
        (0.0, W), (0.0, 22.0), (0.0, 10.0),
    ], t)
    return L * W * t, dict(dims="50 × 30 × 2 plate, each of the 4 side (rim) faces "
                                "split into 3 coplanar faces (at x = 15, 35 / 20, 40 "
                                "and y = 8, 20 / 10, 22)", wall="2")


def plate_split_walls():
    # Three boxes side by side (x in [0, 20], [20, 32], [32, 50]) fused with
    # Geometry.OCCUnionUnify off, so the coplanar faces stay split along the
    # seams x = 20 and x = 32: top, bottom and the two long sides 3 faces each.
    L, W, t = 50.0, 30.0, 2.0
    xs = [0.0, 20.0, 32.0, L]
    fuse_volumes([occ.addBox(xs[i], 0.0, 0.0, xs[i + 1] - xs[i], W, t) for i in range(3)], unify=False)
    return L * W * t, dict(dims="50 × 30 × 2 plate fused from 3 boxes (x 0…20, "
                                "20…32, 32…50), not unified: top, bottom and long "
                                "sides split into 3 coplanar faces at x = 20, 32",
                           wall="2")


def lbracket_split_bend():
    # lbracket's profile with t = 2, bend R2 / R4, width 20; each bend arc is
    # given as two arcs (outer split at 45°, inner at 30° from the vertical
    # leg: the splits are not radially aligned), and the outer face of the
    # horizontal leg as two collinear lines (split at x = 20).
    t, ri, H, V, W = 2.0, 2.0, 40.0, 30.0, 20.0
    ro = ri + t
    c = (ro, ro)

    def on(r, deg):
        a = math.radians(deg)
        return (c[0] + r * math.cos(a), c[1] + r * math.sin(a))

    mo, mi = on(ro, 225.0), on(ri, 210.0)
    segs = [
        ("line", (H, 0.0), (20.0, 0.0)),        # outer face of horizontal leg, part 1
        ("line", (20.0, 0.0), (ro, 0.0)),       # outer face of horizontal leg, part 2
        ("arc", (ro, 0.0), c, mo),              # outer bend, R = ro, 45°
        ("arc", mo, c, (0.0, ro)),              # outer bend, R = ro, 45°
        ("line", (0.0, ro), (0.0, V)),          # outer face of vertical leg
        ("line", (0.0, V), (t, V)),             # top end
        ("line", (t, V), (t, ro)),              # inner face of vertical leg
        ("arc", (t, ro), c, mi),                # inner bend, R = ri, 30°
        ("arc", mi, c, (ro, t)),                # inner bend, R = ri, 60°
        ("line", (ro, t), (H, t)),              # inner face of horizontal leg
        ("line", (H, t), (H, 0.0)),             # free end
    ]
    extrude_profile(segs, W)
    area = (H - ro) * t + (V - ro) * t + quarter_annulus(ri, ro)
    return area * W, dict(dims="L-bracket, legs 40 × 30 to outer faces, width 20, "
                               "bend R2 / R4 with each bend face split in two "
                               "(outer at 45°, inner at 30° from the vertical leg), "
                               "outer face of the horizontal leg split at x = 20",
                          wall="2")


def cap_cut_by_plane():
    # Spherical shell, centre at the origin, R50 outer / R47.5 inner, keep
    # z >= 30: the rim is the flat annulus r in [sqrt(47.5^2 - 30^2), 40].
    # Cap of a ball of radius R above z = h: pi (R - h)^2 (2 R + h) / 3.
    ro, t, zc = 50.0, 2.5, 30.0
    ri = ro - t
    outer = occ.addSphere(0, 0, 0, ro)
    inner = occ.addSphere(0, 0, 0, ri)
    box = occ.addBox(-ro - 5, -ro - 5, zc, 2 * ro + 10, 2 * ro + 10, ro)
    cap, _ = occ.intersect([(3, outer)], [(3, box)])
    one_volume(occ.cut(cap, [(3, inner)])[0])

    def cap_vol(R):
        return PI * (R - zc) ** 2 * (2 * R + zc) / 3

    rim = ro * math.sqrt(1 - (zc / ro) ** 2) - math.sqrt(ri ** 2 - zc ** 2)
    return cap_vol(ro) - cap_vol(ri), dict(
        dims="spherical shell R50 outer / R47.5 inner (centre at the origin) cut "
             f"by the plane z = 30, upper part: Ø80 × 20, flat annular rim "
             f"{rim:.2f} wide", wall="2.5")


def tube(ro, t, z0, z1):
    """Tube along Z, outer radius ro, wall t, from z0 to z1 (straight ends)."""
    outer = occ.addCylinder(0, 0, z0, 0, 0, z1 - z0, ro)
    inner = occ.addCylinder(0, 0, z0 - 1.0, 0, 0, z1 - z0 + 2.0, ro - t)
    return one_volume(occ.cut([(3, outer)], [(3, inner)])[0])


def tube_cut_45():
    # Tube R15 / R13 along Z from z = 0 to the plane z - x = 50 (normal
    # (-1, 0, 1)/√2, 45° to the axis): z from 35 to 65 on the outside. By
    # symmetry V = ∫∫ (50 + x) dA over the annulus = 50 A.
    ro, t, Lm = 15.0, 2.0, 50.0
    vol = tube(ro, t, 0.0, 80.0)
    vol = one_volume(occ.cut([(3, vol)], [(3, half_space_y_tilt(Lm, -45.0, True))])[0])
    area = PI * (ro ** 2 - (ro - t) ** 2)
    return Lm * area, dict(dims="tube R15 outer / R13 inner along Z, end z = 0 "
                                "square, other end cut by the plane z = 50 + x (45° "
                                "to the axis; elliptic rim), 35…65 long", wall="2")


def tube_cut_45_both():
    # Same tube, ends on the parallel planes z - x = 15 and z - x = 60 (45° to
    # the axis): V = 45 A as above; z from 0 to 75 overall.
    ro, t, z0, z1 = 15.0, 2.0, 15.0, 60.0
    vol = tube(ro, t, -5.0, 80.0)
    vol = one_volume(occ.cut([(3, vol)], [(3, half_space_y_tilt(z1, -45.0, True)),
                                          (3, half_space_y_tilt(z0, -45.0, False))])[0])
    area = PI * (ro ** 2 - (ro - t) ** 2)
    return (z1 - z0) * area, dict(dims="tube R15 outer / R13 inner along Z, both ends "
                                       "cut by parallel planes at 45° to the axis, "
                                       "z = 15 + x and z = 60 + x (45 long on the axis)",
                                  wall="2")


def taper_plate():
    # Thickness 3 at x = 0 to 1 at x = 60, symmetric about z = 0 (both walls
    # inclined), 30 along Y; the ends x = 0, 60 are planes normal to X.
    L, W, t0, t1 = 60.0, 30.0, 3.0, 1.0
    extrude_profile([
        ("line", (0.0, -t0 / 2), (L, -t1 / 2)),
        ("line", (L, -t1 / 2), (L, t1 / 2)),
        ("line", (L, t1 / 2), (0.0, t0 / 2)),
        ("line", (0.0, t0 / 2), (0.0, -t0 / 2)),
    ], W)
    return L * W * (t0 + t1) / 2, dict(dims="60 × 30 plate, symmetric taper (both walls "
                                            "inclined): thickness 3 at x = 0 to 1 at "
                                            "x = 60, square ends", wall="3 → 1 (linear in x)")


def plate_rounded_holes(L, W, holes):
    """Plate L x W x 2 with vertical through holes whose edges are filleted:
    `holes` = (x, y, R, r_top, r_bottom), a fillet radius 0 leaving that edge
    sharp. Every fillet is made in one OpenCASCADE fillet.

    Volume: the plate minus the holes' cylinders minus, per fillet, the
    material it takes off the hole's concave edge: the spandrel A = r^2 (1 -
    pi/4) turned about the hole's axis (Pappus) at the distance of its
    centroid, R + r - 2 r / (3 (4 - pi)) (the fillet's centre is at R + r;
    the spandrel's centroid lies 2 r / (3 (4 - pi)) from it towards the hole,
    as in plate_rim_fillets):
        V = L W t - sum pi R^2 t - sum 2 pi (R + r - 2 r / (3 (4 - pi))) A.
    """
    t = 2.0
    box = occ.addBox(0, 0, 0, L, W, t)
    cylinders = [(3, occ.addCylinder(x, y, -1, 0, 0, t + 2, R)) for x, y, R, _, _ in holes]
    vol = one_volume(occ.cut([(3, box)], cylinders)[0])
    occ.synchronize()
    edges, radii, removed = [], [], 0.0
    for x, y, R, r_top, r_bottom in holes:
        for z, r in ((t, r_top), (0.0, r_bottom)):
            if r <= 0:
                continue
            assert 2 * r < t
            found = [c for c in horizontal_curves(vol, z)
                     if abs(gmsh.model.getBoundingBox(1, c)[0] - (x - R)) < 1e-3
                     and abs(gmsh.model.getBoundingBox(1, c)[4] - (y + R)) < 1e-3]
            assert len(found) == 1, (x, y, z, found)
            edges.append(found[0])
            radii.append(r)
            removed += 2 * PI * (R + r - 2 * r / (3 * (4 - PI))) * r * r * (1 - PI / 4)
    one_volume(occ.fillet([vol], edges, radii))
    return L * W * t - sum(PI * R * R * t for _, _, R, _, _ in holes) - removed


def rounded_hole_plate(L, W, holes, dims):
    """A builder for RIM_PARTS: plate_rounded_holes(L, W, holes) with its README line."""
    return lambda: (plate_rounded_holes(L, W, holes), dict(dims=dims, wall="2"))


ROUNDED_HOLE_PLATES = [
    ("plate_hole_full_round", rounded_hole_plate(
        50.0, 30.0, [(25.0, 15.0, 6.0, 0.98, 0.98)],
        "50 × 30 × 2 plate, one Ø12 through hole at (25, 15) whose top and bottom edges are filleted r = 0.98 "
        "(0.49 t: a near-full-round hole rim)")),
    ("plate_hole_fillet_one_side", rounded_hole_plate(
        50.0, 30.0, [(25.0, 15.0, 6.0, 0.7, 0.0)],
        "50 × 30 × 2 plate, one Ø12 through hole at (25, 15) whose top edge only is filleted r = 0.7 (0.35 t)")),
    ("plate_holes_rounded", rounded_hole_plate(
        70.0, 40.0, [(14.0, 20.0, 5.0, 0.98, 0.98), (36.0, 22.0, 4.0, 0.8, 0.0), (56.0, 14.0, 3.0, 0.5, 0.5),
                     (56.0, 30.0, 3.5, 0.0, 0.6)],
        "70 × 40 × 2 plate, four through holes with filleted edges: Ø10 at (14, 20) near-full-round (r = 0.98 "
        "both edges), Ø8 at (36, 22) top edge r = 0.8 (0.4 t), Ø6 at (56, 14) both edges r = 0.5, Ø7 at "
        "(56, 30) bottom edge only r = 0.6")),
    ("plate_hole_near_rim", rounded_hole_plate(
        50.0, 30.0, [(8.0, 15.0, 4.0, 0.9, 0.9)],
        "50 × 30 × 2 plate, one Ø8 through hole at (8, 15), 3.1 from the rim beyond its fillets, both edges "
        "filleted r = 0.9 (0.45 t)")),
]


def plate_slot_fillet():
    """Plate 60 x 30 x 2 with a through slot (two half circles R3 at x = 20 and 40, y = 15, joined by straight
    sides) whose top edge is filleted r = 0.7. Volume: the plate minus the slot's area (20 x 6 + pi 3^2) x t
    minus the fillet's spandrel A = r^2 (1 - pi/4) swept along the two straight sides (2 x 20) and, by Pappus,
    turned half round each end at the distance of its centroid from the end's axis, 3 + r - 2 r / (3 (4 - pi))
    (plate_rounded_holes)."""
    L, W, t, R, r = 60.0, 30.0, 2.0, 3.0, 0.7
    box = occ.addBox(0, 0, 0, L, W, t)
    ends = [occ.addCylinder(x, 15, -1, 0, 0, t + 2, R) for x in (20.0, 40.0)]
    middle = occ.addBox(20, 15 - R, -1, 20, 2 * R, t + 2)
    slot, _ = occ.fuse([(3, ends[0])], [(3, ends[1]), (3, middle)])
    vol = one_volume(occ.cut([(3, box)], slot)[0])
    occ.synchronize()
    top = [c for c in horizontal_curves(vol, t)
           if gmsh.model.getBoundingBox(1, c)[0] > 20 - R - 1e-3 and gmsh.model.getBoundingBox(1, c)[3] < 40 + R + 1e-3]
    assert len(top) == 4, top  # two half circles, two lines
    one_volume(occ.fillet([vol], top, [r]))
    A = r * r * (1 - PI / 4)
    return L * W * t - (20 * 2 * R + PI * R * R) * t - A * (2 * 20 + 2 * PI * (R + r - 2 * r / (3 * (4 - PI)))), dict(
        dims="60 × 30 × 2 plate, a through slot 26 × 6 (R3 ends at x = 20 and 40, y = 15) whose top edge is "
             "filleted r = 0.7 (0.35 t)",
        wall="2")


# Written after PARTS, in the same session (see the note on PARTS).
RIM_PARTS = [
    ("lbracket_round_ends", lbracket_round_ends),
    ("uchannel_round_ends", uchannel_round_ends),
    ("hat_round_ends", hat_round_ends),
    ("plate_full_round", plate_full_round),
    ("plate_fillet_flat_fillet", plate_fillet_flat_fillet),
    ("plate_chamfer_one_side", plate_chamfer_one_side),
    ("plate_chamfer_both_sides", plate_chamfer_both_sides),
    ("strip_oblique_45", strip_oblique_45),
    ("strip_oblique_3x", strip_oblique_3x),
    ("plate_split_rim", plate_split_rim),
    ("plate_split_walls", plate_split_walls),
    ("lbracket_split_bend", lbracket_split_bend),
    ("cap_cut_by_plane", cap_cut_by_plane),
    ("tube_cut_45", tube_cut_45),
    ("tube_cut_45_both", tube_cut_45_both),
    ("taper_plate", taper_plate),
    ("strip_skin_round", strip_skin_round),
    ("strip_skin_round_thin", strip_skin_round_thin),
    ("strip_skin_wrap", strip_skin_wrap),
    *ROUNDED_HOLE_PLATES,
    ("plate_slot_fillet", plate_slot_fillet),
]

RIM_README_HEAD = [
    "# HexLayer sample parts: rims and split faces",
    "",
    "Small single-solid STEP files (AP214, units mm), all thin-walled, whose rims",
    "(the faces across the wall at its free edges) are not flat faces normal to",
    "the wall -- full-round ends, fillets, chamfers, oblique cuts, a wide planar",
    "rim on a curved shell, a taper -- or whose faces are split into several",
    "faces where one would do.",
]

RIM_README_NOTES = [
    "Profiled parts (`lbracket_round_ends`, `uchannel_round_ends`,",
    "`hat_round_ends`, `lbracket_split_bend`, `strip_oblique_*`, `taper_plate`)",
    "are extrusions along +Y of a closed profile in the XZ plane, like the",
    "profiled parts in `..`. A full-round end is one half circle of radius t/2",
    "centred on the mid-surface, tangent to both walls (one cylindrical face, as",
    "FreeCAD's Part Offset2D of an open line makes). The plates with fillets and",
    "chamfers are OpenCASCADE fillets / chamfers of a box (after rounding its",
    "vertical corners R5 for the fillets); their volumes are checked against",
    "closed formulas (Pappus for the fillets, prismatoid for the chamfers, see",
    "`scripts/make_samples.py`). `plate_split_rim` extrudes a 12-point outline",
    "(collinear points kept); `plate_split_walls` is a fuse of three boxes with",
    "OpenCASCADE's face unification turned off. `cap_cut_by_plane`, `tube_cut_45`",
    "and `tube_cut_45_both` are spheres / cylinders cut by planes; their",
    "spherical and cylindrical faces have a seam edge on the +X side, and the",
    "spherical faces hold the pole (+Z) as a degenerate edge. `strip_skin_round*`",
    "draw the top wall and the full-round end as one rational B-spline curve",
    "(exact line and quarter circles, knots at the joins), extruded: one face that",
    "is partly wall and partly rim. `plate_hole*` and `plate_holes_rounded` are",
    "plates with through holes whose top and / or bottom edges are filleted (a",
    "concave rounded rim; volumes by Pappus, see `plate_rounded_holes`); `plate_hole_near_rim` has one near",
    "the plate's rim, `plate_slot_fillet` a slot (straight and round edges) filleted on top.",
    "",
    "Made by `scripts/make_samples.py` after the parts in `..` (run it with",
    "`/usr/bin/python3`, which needs the Debian package `python3-gmsh`); licence",
    "AGPL-3.0-or-later like the project. The STEP header timestamp is fixed, so",
    "regenerating the files gives byte-identical output.",
    "",
]


# ---------------------------------------------------------------------------
# Junction parts (written to the subfolder junctions/): a wall standing on
# another wall, so that the chordal surface branches (is not 2-manifold):
# ribs, a grid of ribs, a partition, bosses, a gusset. Small, so that a mesh
# of one is a few thousand hexes. The plate under the ribs and bosses is
# PLATE_L x PLATE_W x PLATE_T, [0, 60] x [0, 40] x [0, 2].
# ---------------------------------------------------------------------------

PLATE_L, PLATE_W, PLATE_T = 60.0, 40.0, 2.0
# The grid of ribs and the boxes have 40 faces or so (the plate's top in 9
# pieces; the rounded box alone is 35): over MAX_BYTES.
LARGE_BYTES = 150 * 1024
# The open box of the box parts: outside 60 x 40 x 20, vertical and bottom
# edges R6 outside / R4 inside, wall 2 (rounded_open_box).
BOX = (60.0, 40.0, 20.0, 6.0, 2.0)


def spandrel_area(r):
    """Cross-section of a fillet of radius r in a right-angled concave edge:
    the square r x r minus the quarter disc."""
    return r * r * (1 - PI / 4)


def spandrel_centroid(r):
    """Distance of the spandrel's centroid from either wall of the edge:
    r - 2 r / (3 (4 - pi)) (plate_rim_fillets)."""
    return r - 2 * r / (3 * (4 - PI))


def overlap(a, b):
    """Area common to two footprints (x0, y0, x1, y1, ...)."""
    dx = min(a[2], b[2]) - max(a[0], b[0])
    dy = min(a[3], b[3]) - max(a[1], b[1])
    return max(dx, 0.0) * max(dy, 0.0)


def ribs_volume(ribs):
    """Volume the ribs (x0, y0, x1, y1, h) add above the plane they stand on:
    footprint x height each, less each crossing (the overlap of two
    footprints) x the lower of the two heights. Three ribs may not overlap at
    one place (none do)."""
    vol = sum((x1 - x0) * (y1 - y0) * h for x0, y0, x1, y1, h in ribs)
    for i, a in enumerate(ribs):
        for b in ribs[i + 1:]:
            vol -= overlap(a, b) * min(a[4], b[4])
    return vol


def rib_boxes(ribs, z, split_x=None):
    """Boxes for the ribs (x0, y0, x1, y1, h) standing on the plane z: each
    from z - 1 (into the wall below, so that the fuse overlaps volumes) to
    z + h; cut in two at x = split_x where it crosses that plane."""
    boxes = []
    for x0, y0, x1, y1, h in ribs:
        xs = [x0, split_x, x1] if split_x is not None and x0 < split_x < x1 else [x0, x1]
        boxes += [occ.addBox(xs[i], y0, z - 1.0, xs[i + 1] - xs[i], y1 - y0, h + 1.0)
                  for i in range(len(xs) - 1)]
    return boxes


def foot_edges(vol, z, ribs):
    """Edges of `vol` in the plane z whose middles lie on the outline of a
    rib's footprint: the rib's feet (not the plate's rim)."""
    def on_outline(x, y, rib):
        x0, y0, x1, y1 = rib[:4]
        inside = x0 - 1e-3 < x < x1 + 1e-3 and y0 - 1e-3 < y < y1 + 1e-3
        return inside and min(abs(x - x0), abs(x - x1), abs(y - y0), abs(y - y1)) < 1e-3

    edges = []
    for c in horizontal_curves(vol, z):
        b = gmsh.model.getBoundingBox(1, c)
        if any(on_outline((b[0] + b[3]) / 2, (b[1] + b[4]) / 2, rib) for rib in ribs):
            edges.append(c)
    return edges


def fillet_feet(vol, z, ribs, r):
    """Fillet the feet of the ribs (rectangular footprints) standing on the
    plane z with radius r, in one OpenCASCADE fillet. Returns the material it
    adds: the spandrel A swept along the straight foot edges, plus a mitred
    corner at each corner of a footprint where two foot edges meet (convex
    corners): OpenCASCADE runs both fillets on to where they cross, so the
    corner holds the points under both of them,
        integral over [0, r]^2 of min(f(p), f(q)) dp dq = 2 A c(r)
    = r^3 (5/3 - pi/2), with f(s) = r - sqrt(r^2 - (r - s)^2) the fillet's
    height at distance s from the rib and c(r) the spandrel's centroid
    (spandrel_centroid; not the horn torus of a ball rolled round the
    corner, (pi / 2) A c(r))."""
    edges = foot_edges(vol, z, ribs)
    length = sum(occ.getMass(1, c) for c in edges)
    uses = Counter(abs(v) for c in edges for _, v in gmsh.model.getBoundary([(1, c)], combined=False))
    corners = sum(1 for n in uses.values() if n == 2)
    one_volume(occ.fillet([vol], edges, [r]))
    return spandrel_area(r) * (length + corners * 2 * spandrel_centroid(r))


def rib_plate(ribs, dims, junction, wall="plate 2, rib 2", split=False, fillet=0.0, **info):
    """A builder for JUNCTION_PARTS: the plate with the `ribs` (x0, y0, x1, y1,
    h: footprint and height above the plate) standing on its top, fused. With
    `split` the plate is two boxes (cut at x = 25) and each rib is cut at
    x = 35, fused without unifying faces, so that the coplanar faces stay
    split; with `fillet` r > 0 the ribs' feet are filleted r. Volume: the
    plate + ribs_volume(ribs) + the fillets' (fillet_feet). `info`: more
    keys of make_part's description (max_bytes)."""
    def build():
        L, W, t = PLATE_L, PLATE_W, PLATE_T
        xs = [0.0, 25.0, L] if split else [0.0, L]
        plate = [occ.addBox(xs[i], 0.0, 0.0, xs[i + 1] - xs[i], W, t) for i in range(len(xs) - 1)]
        vol = fuse_volumes(plate + rib_boxes(ribs, t, 35.0 if split else None), unify=not split)
        added = fillet_feet(vol, t, ribs, fillet) if fillet > 0 else 0.0
        return L * W * t + ribs_volume(ribs) + added, dict(dims=dims, wall=wall, junction=junction, **info)
    return build


def boss_plate(ro, ri, h, rh, dims, junction, wall="plate 2, boss 2"):
    """A builder for JUNCTION_PARTS: the plate with a boss at its centre, a
    cylinder of radius ro standing h above its top, with a bore of radius ri
    (none if 0) from the plate's top through the boss and a hole of radius rh
    (none if 0) through the plate; rh = ri is one bore through both (its wall
    flush with the hole's). Volume: the plate + pi (ro^2 - ri^2) h - pi rh^2 t."""
    def build():
        L, W, t = PLATE_L, PLATE_W, PLATE_T
        x, y = L / 2, W / 2
        vol = fuse_volumes([occ.addBox(0.0, 0.0, 0.0, L, W, t),
                            occ.addCylinder(x, y, t - 1.0, 0.0, 0.0, h + 1.0, ro)])
        holes = [(ri, -1.0 if rh == ri else t), (0.0 if rh == ri else rh, -1.0)]
        tools = [(3, occ.addCylinder(x, y, z0, 0.0, 0.0, t + h + 1.0 - z0, r)) for r, z0 in holes if r > 0]
        if tools:
            one_volume(occ.cut([(3, vol)], tools)[0])
        return L * W * t + PI * (ro * ro - ri * ri) * h - PI * rh * rh * t, dict(
            dims=dims, wall=wall, junction=junction)
    return build


def boss_gussets(ro, ri, h, gh, a, length):
    """A builder for JUNCTION_PARTS: plate_boss's plate and boss (outside radius ro, a blind bore ri down to the
    plate's top, h high) with four gussets 2a thick along +-X and +-Y, from the boss's axis to `length` beyond its
    side, gh high above the plate (lower than the boss). A gusset adds gh x its footprint outside the boss's disc:
    2a (ro + length) less the strip |y| <= a of the half disc, a sqrt(ro^2 - a^2) + ro^2 asin(a / ro)."""
    def build():
        L, W, t = PLATE_L, PLATE_W, PLATE_T
        x, y = L / 2, W / 2
        reach = ro + length
        gussets = [occ.addBox(x, y - a, t - 1.0, reach, 2 * a, gh + 1.0),
                   occ.addBox(x - reach, y - a, t - 1.0, reach, 2 * a, gh + 1.0),
                   occ.addBox(x - a, y, t - 1.0, 2 * a, reach, gh + 1.0),
                   occ.addBox(x - a, y - reach, t - 1.0, 2 * a, reach, gh + 1.0)]
        vol = fuse_volumes([occ.addBox(0.0, 0.0, 0.0, L, W, t),
                            occ.addCylinder(x, y, t - 1.0, 0.0, 0.0, h + 1.0, ro)] + gussets)
        one_volume(occ.cut([(3, vol)], [(3, occ.addCylinder(x, y, t, 0.0, 0.0, h + 1.0, ri))])[0])
        outside = 2 * a * reach - (a * math.sqrt(ro * ro - a * a) + ro * ro * math.asin(a / ro))
        return L * W * t + PI * (ro * ro - ri * ri) * h + 4 * gh * outside, dict(
            dims=BOSS_DIMS + "Ø%g outside, %g high, a blind Ø%g bore; four gussets %g thick along ±X and ±Y, "
            "%g long beyond the boss, %g high" % (2 * ro, h, 2 * ri, 2 * a, length, gh),
            wall="plate 2, boss %g, gussets %g" % (ro - ri, 2 * a),
            junction="ring (the boss on the plate) with four T feet on it all round (gussets ending on the boss's "
                     "side and standing on the plate)")
    return build


def box_partition():
    """The open box (BOX) with a partition wall across it at x = 30, as thick
    as the walls and as high (flush with the rim): a slab of the outer solid,
    fused. It adds t x the cavity's cross-section, a (W - 2t) x (H - t)
    rectangle less the two spandrels of the inner bottom edges (radius
    r - t)."""
    L, W, H, r, t = BOX
    vol, volume = rounded_open_box(*BOX)
    slab, _ = occ.intersect([(3, occ.addBox(L / 2 - t / 2, 0.0, 0.0, t, W, H))],
                            [(3, filleted_box(0, 0, 0, L, W, H, r))])
    fuse_volumes([vol, one_volume(slab)])
    section = (W - 2 * t) * (H - t) - 2 * spandrel_area(r - t)
    return volume + t * section, dict(
        dims="open box, outside 60 × 40 × 20, vertical and bottom edges R6 outside / R4 inside, top open; "
             "a partition wall across it at x = 29…31, from the floor to the rim, meeting both long walls",
        wall="2 (walls, floor, partition)",
        junction="T along the floor and up both long walls (an L-shaped foot across the bends), "
                 "two corners where the partition meets a wall and the floor",
        max_bytes=LARGE_BYTES)


def box_rib_fillet():
    """The open box (BOX) with a rib on its floor, x 10…50 at y = 19…21, 8
    high, its foot filleted r = 1 all round (fillet_feet)."""
    t = BOX[4]
    vol, volume = rounded_open_box(*BOX)
    rib = (10.0, 19.0, 50.0, 21.0, 8.0)
    vol = fuse_volumes([vol] + rib_boxes([rib], t))
    added = fillet_feet(vol, t, [rib], 1.0)
    return volume + ribs_volume([rib]) + added, dict(
        dims="open box as box_partition without the partition; a rib on the floor along X, x 10…50, "
             "y 19…21, 8 high (z 2…10), its foot filleted r = 1 all round (ends inside the floor)",
        wall="2 (walls, floor, rib)",
        junction="filleted foot: T along the rib's sides and ends, the fillet a cylinder along each "
                 "side and end, mitred at the corners", max_bytes=LARGE_BYTES)


def shell_rib():
    """A cylindrical shell segment (R29 / R31, 120° from +X, 40 along Z) with
    a rib inside it: the flat annular sector R19…R29 at z = 19…21, running
    along the shell's arc from rim to rim. One T-shaped profile in the XZ
    plane turned 120° about Z; by Pappus the volume is (angle / 2) x the
    sum of (R_out^2 - R_in^2) x height of its two rectangles."""
    ri, ro, Lz, rr, z0, tr, deg = 29.0, 31.0, 40.0, 19.0, 19.0, 2.0, 120.0
    a = math.radians(deg)
    corners = [(ri, 0.0), (ro, 0.0), (ro, Lz), (ri, Lz), (ri, z0 + tr), (rr, z0 + tr), (rr, z0), (ri, z0)]
    segs = [("line", corners[i], corners[(i + 1) % len(corners)]) for i in range(len(corners))]
    one_volume(occ.revolve([(2, profile_surface(segs))], 0, 0, 0, 0, 0, 1, a))
    volume = a / 2 * ((ro ** 2 - ri ** 2) * Lz + (ri ** 2 - rr ** 2) * tr)
    return volume, dict(
        dims="cylindrical shell segment as cylinder_shell (R29 inner / R31 outer, 120° from +X, "
             "40 along Z) with a rib inside: the flat annular sector R19…R29 at z = 19…21 (10 high), "
             "along the arc from rim to rim",
        wall="shell 2, rib 2", junction="T along a curved line (an arc R29), both ends at the rim")


def lbracket_gusset():
    """lbracket (t = 3, bend R3 / R6, width 25) with a gusset 2 thick at its
    middle (y = 11.5…13.5): the triangle with its right angle at the inner
    faces' corner (3, 3) and legs 15 along them, fused (the profile overlaps
    the bracket's legs and bend). It adds 2 x the triangle's area less the
    spandrel of the inner bend (R3) that the bracket already fills."""
    volume, _ = lbracket()
    bracket = occ.getEntities(3)[0][1]
    t, ri, W, a, tg = 3.0, 3.0, 25.0, 15.0, 2.0
    h = t / 2
    corners = [(t, h), (t + a, h), (t + a, t), (t, t + a), (h, t + a), (h, t)]
    gusset = extrude_profile([("line", corners[i], corners[(i + 1) % len(corners)])
                              for i in range(len(corners))], tg)
    occ.translate([(3, gusset)], 0.0, (W - tg) / 2, 0.0)
    fuse_volumes([bracket, gusset])
    return volume + tg * (a * a / 2 - spandrel_area(ri)), dict(
        dims="L-bracket as lbracket (legs 40 × 30 to outer faces, width 25, bend R3 / R6) with a "
             "triangular gusset in the bend at y = 11.5…13.5, legs 15 along the inner faces from "
             "their corner (3, 3)",
        wall="bracket 3, gusset 2", junction="L-gusset: a T on each leg, meeting in the bend")


def box_end_wall_low():
    """box_sharp_inside_r025 (outside R0.5, every inside edge sharp) with its
    end wall x = 0…2 cut down to 10 high between the long walls: they run on up to
    the rim, 20, flush with its outside (its outside and their ends one face,
    their R1 corner rounds on up), as a box with a lower end. It loses the slab
    2 × 36 × 10."""
    L, W, H, t = SHARP_BOX
    vol, volume = sharp_inside_box(0.5)
    h = 10.0
    one_volume(occ.cut([(3, vol)], [(3, occ.addBox(-1.0, t, h, t + 1.0, W - 2 * t, H))])[0])
    return volume - t * (W - 2 * t) * (H - h), dict(
        dims=box_dims(0.5, "; the end wall x = 0…2 only 10 high between the long walls, which run on up to 20 "
                           "flush with its outside"),
        wall="2", junction="T butting on the long walls and the floor: the end wall's foot a U along their rim "
                           "(a butt joint; mitred, the hexes fold where its top meets the long walls)")


RIB = (0.0, 19.0, 60.0, 21.0, 12.0)    # the plate's rib: along X, rim to rim, 2 x 12
BOSS_DIMS = "60 × 40 × 2 plate, a boss at its centre (30, 20), "

JUNCTION_PARTS = [
    ("plate_rib", rib_plate(
        [RIB], "60 × 40 × 2 plate, one rib along X at y = 19…21, 12 high above the plate, rim to rim",
        "T (straight), both ends at the plate's rim")),
    ("plate_rib_grid", rib_plate(
        [(0.0, 12.0, 60.0, 14.0, 10.0), (0.0, 26.0, 60.0, 28.0, 10.0),
         (19.0, 0.0, 21.0, 40.0, 10.0), (39.0, 0.0, 41.0, 40.0, 10.0)],
        "60 × 40 × 2 plate, a grid of ribs 10 high, rim to rim: two along X (y = 12…14, 26…28) and "
        "two along Y (x = 19…21, 39…41)",
        "4 X (ribs crossing), each rib a T on the plate", max_bytes=LARGE_BYTES)),
    ("box_partition", box_partition),
    ("plate_boss", boss_plate(
        4.0, 2.0, 10.0, 0.0, BOSS_DIMS + "Ø8 outside, 10 high above the plate, a blind Ø4 bore down to "
        "the plate's top", "ring (a closed round foot)")),
    ("shell_rib", shell_rib),
    ("lbracket_gusset", lbracket_gusset),
    ("box_rib_fillet", box_rib_fillet),
    # Twins: the rib's ends, place and thickness, two ribs in a T, split
    # faces, a filleted foot on the plate, bosses with a hole through the
    # plate, a bore through it and none.
    ("plate_rib_inside", rib_plate(
        [(10.0, 19.0, 50.0, 21.0, 12.0)], "as plate_rib, the rib x 10…50: both ends inside the plate",
        "T (straight), both ends inside the sheet")),
    ("plate_rib_rim", rib_plate(
        [(0.0, 0.0, 60.0, 2.0, 12.0)], "as plate_rib, the rib at y = 0…2: its outer face one plane "
        "with the plate's side face y = 0", "rib flush with the plate's edge: none in the chordal "
        "surface, an L section with a sharp bend")),
    ("plate_rib_thin", rib_plate(
        [(0.0, 19.5, 60.0, 20.5, 12.0)], "as plate_rib, the rib 1 thick (0.5 × the plate), y = 19.5…20.5",
        "T, rib thinner than the sheet", wall="plate 2, rib 1")),
    ("plate_rib_thick", rib_plate(
        [(0.0, 18.5, 60.0, 21.5, 12.0)], "as plate_rib, the rib 3 thick (1.5 × the plate), y = 18.5…21.5",
        "T, rib thicker than the sheet", wall="plate 2, rib 3")),
    ("plate_ribs_tee", rib_plate(
        [RIB, (29.0, 0.0, 31.0, 20.0, 8.0)], "as plate_rib (rib A, 12 high) and rib B along Y at "
        "x = 29…31, 8 high, from the rim y = 0 to rib A's side y = 19",
        "T of two ribs of different heights (B ends on A's side, not crossing), each a T on the plate")),
    ("plate_rib_split", rib_plate(
        [RIB], "as plate_rib, fused from pieces without unifying faces: the plate's top, bottom and long "
        "sides split at x = 25, the rib's sides and top at x = 35", "T, split coplanar faces", split=True)),
    ("plate_rib_fillet", rib_plate(
        [RIB], "as plate_rib, the rib's foot filleted r = 1 on both sides", "filleted foot (T), the "
        "fillets ending at the plate's rim", fillet=1.0)),
    ("plate_boss_hole", boss_plate(
        4.0, 2.0, 10.0, 1.0, "as plate_boss, and a Ø2 hole through the plate under the bore",
        "ring, with a hole through the plate inside it")),
    ("plate_boss_collar", boss_plate(
        4.0, 2.0, 10.0, 2.0, "as plate_boss, the Ø4 bore through the plate too (its wall "
        "flush with the hole's)", "none in the chordal surface: a collar (the plate turned up round "
        "the hole, a sharp bend), as plate_rib_rim is an L")),
    ("plate_boss_solid", boss_plate(
        1.5, 0.0, 10.0, 0.0, BOSS_DIMS + "a solid pin Ø3 (1.5 × the plate), 10 high, no hole",
        "round foot without a hole (a pin)", wall="plate 2, pin Ø3")),
    ("plate_boss_gussets", boss_gussets(4.0, 2.0, 10.0, 6.0, 1.0, 8.0)),
    # A wall butting on the walls of its own sheet, its outside flush with their ends.
    ("box_end_wall_low", box_end_wall_low),
]


JUNCTION_README_HEAD = [
    "# HexLayer sample parts: junctions (walls standing on walls)",
    "",
    "Small single-solid STEP files (AP214, units mm), all thin-walled, where a",
    "wall stands on another wall: ribs on a plate (one, a grid of crossing ribs,",
    "two of different heights in a T), a partition across an open box, bosses,",
    "a rib on a curved shell, a gusset in an L-bracket's bend, filleted rib feet.",
    "Their chordal surface branches (is not 2-manifold) where the walls meet:",
    "issue 18. Two twins do not branch (`plate_rib_rim`, `plate_boss_collar`):",
    "a rib flush with the plate's edge is an L, a bore through the plate a collar.",
    "The CAD volume (OpenCASCADE's) matches the analytic volume of each part to",
    "1e-6 (relative); how each is derived is below.",
]

JUNCTION_README_NOTES = [
    "The plate under the ribs and bosses is [0, 60] × [0, 40] × [0, 2]; a rib",
    "is a box standing on the plate's top (footprint × height above the plate),",
    "fused (overlapping the plate by 1), so the volume is the plate's plus each",
    "footprint × height, less each crossing's footprint × the lower of the two",
    "heights (`ribs_volume`). `plate_rib_split` is fused from a plate cut at",
    "x = 25 and a rib cut at x = 35 with OpenCASCADE's face unification off.",
    "Bosses: plate + π (R² − r²) h − π r_h² t (bore r from the plate's top,",
    "hole r_h through the plate). `plate_boss_gussets` adds, per gusset (2a",
    "thick, from the boss's axis to l beyond its side R, h_g high), h_g × its",
    "footprint outside the boss's disc: 2a (R + l) − a √(R² − a²) − R² asin(a/R).",
    "`box_partition` and `box_rib_fillet` stand",
    "on the open box of `../housing.step`'s kind (outside 60 × 40 × 20, edges",
    "R6 / R4, wall 2; volume as the housing's: core, slabs, quarter cylinders",
    "and eighth spheres); the partition is the slab x 29…31 of the outer solid,",
    "fused: it adds 2 × the cavity's section, 36 × 18 less two spandrels",
    "(1 − π/4) 4². Filleted feet (r = 1): the spandrel A = r² (1 − π/4) along",
    "each straight foot edge, and at each corner of a footprint OpenCASCADE",
    "runs the two fillets on to where they cross (a mitre, not a rolled torus):",
    "r³ (5/3 − π/2) each (`fillet_feet`). `shell_rib` is one T-shaped profile",
    "(shell R29…R31 × 40, rib R19…R29 × 2) turned 120° about Z: by Pappus",
    "(θ/2) Σ (R_out² − R_in²) h. `lbracket_gusset` adds 2 × (15²/2 − (1 − π/4) 3²):",
    "the gusset's triangle less the spandrel of the inner bend (R3), which the",
    "bracket already fills. `box_end_wall_low` is `../box_sharp_inside_r025.step`",
    "with its end wall x = 0…2 cut down to 10 between the long walls (less",
    "2 × 36 × 10).",
    "",
    "Made by `scripts/make_samples.py` after the parts in `..` and `../rims`",
    "(run it with `/usr/bin/python3`, which needs the Debian package",
    "`python3-gmsh`); licence AGPL-3.0-or-later like the project. The STEP",
    "header timestamp is fixed, so regenerating the files gives byte-identical",
    "output. `tests/integration/test_junction_samples.py` reads them back and",
    "records what `hexlayer mesh` does with them today.",
    "",
]


# ---------------------------------------------------------------------------
# Parts with many features (issue 19: the benchmark varies what users vary),
# OUTPUT_DIR/many, only with --only many (bench/bench.py writes them into
# out/bench): the keyboard plate's STEP file is 3.4 MB, too large to bundle.
# ---------------------------------------------------------------------------

MANY_MAX_BYTES = 8 * 1024 * 1024
KEY_PITCH, KEY_HOLE, NOTCH_W, NOTCH_D = 19.05, 14.0, 3.0, 0.8


def keyboard_plate():
    """A keyboard switch plate: 5 rows x 14 square cutouts 14 x 14 at 19.05
    pitch, each with two clip notches 0.8 deep x 3 wide in the middle of its
    top and bottom sides, in a 1.5 plate with a 9 / 5 margin."""
    rows, cols, t = 5, 14, 1.5
    L, W = cols * KEY_PITCH + 18.0, rows * KEY_PITCH + 10.0
    plate = occ.addBox(0, 0, 0, L, W, t)
    tools = []
    for j in range(rows):
        for i in range(cols):
            cx, cy = 9.0 + (i + 0.5) * KEY_PITCH, 5.0 + (j + 0.5) * KEY_PITCH
            h = KEY_HOLE / 2
            tools.append((3, occ.addBox(cx - h, cy - h, -1, KEY_HOLE, KEY_HOLE, t + 2)))
            for y in (cy + h - 0.1, cy - h - NOTCH_D):  # overlapping the cutout by 0.1
                tools.append((3, occ.addBox(cx - NOTCH_W / 2, y, -1, NOTCH_W, NOTCH_D + 0.1, t + 2)))
    out, _ = occ.cut([(3, plate)], tools)
    assert len([tag for dim, tag in out if dim == 3]) == 1, out
    cutout = KEY_HOLE ** 2 + 2 * NOTCH_W * NOTCH_D
    return (L * W - rows * cols * cutout) * t, dict(
        dims=f"{L:.2f} × {W:.2f} × 1.5 keyboard plate: 5 rows × 14 cutouts 14 × 14 at 19.05 pitch, "
             "each with two 0.8 × 3 clip notches", wall="1.5", max_bytes=MANY_MAX_BYTES)


def plate_200_holes():
    """A 210 x 110 x 2 plate with 200 through holes Ø4 on a 10 mm grid (20 x 10)."""
    L, W, t, d = 210.0, 110.0, 2.0, 4.0
    box = occ.addBox(0, 0, 0, L, W, t)
    drill(box, [(10.0 + 10.0 * i, 10.0 + 10.0 * j, 0.0, t, d) for j in range(10) for i in range(20)])
    return L * W * t - 200 * PI * (d / 2) ** 2 * t, dict(
        dims="210 × 110 × 2 plate, 200 through holes Ø4 on a 10 mm grid (20 × 10)", wall="2",
        max_bytes=MANY_MAX_BYTES)


def radial_hole_volume(r_in, r_out, a, n=4000):
    """Volume a radial hole of radius a removes from a tube wall between radii r_in and r_out: the integral over the
    hole's disc (s across the tube, z along it) of the wall's length on the hole's line, sqrt(r_out^2 - s^2) -
    sqrt(r_in^2 - s^2), with s = a sin(u) (composite Simpson's rule, smooth in u)."""
    def f(u):
        s = a * math.sin(u)
        return 2 * (a * math.cos(u)) ** 2 * (math.sqrt(r_out ** 2 - s ** 2) - math.sqrt(r_in ** 2 - s ** 2))
    h = PI / n
    return h / 3 * sum((1 if k in (0, n) else 4 if k % 2 else 2) * f(-PI / 2 + k * h) for k in range(n + 1))


# OpenCASCADE integrates the volume of the tube's faces bounded by the holes' intersection curves (B-splines
# approximating the cylinders' intersections) to 3.2e-5 of the exact volume (FreeCAD's Shape.Volume gives the same).
TUBE_VOLUME_TOLERANCE = 1e-4


def perforated_tube():
    """A perforated tube: R60 inside, 2 wall, 120 long along z, with 150 radial Ø3 holes, 15 around (8 degrees apart
    from -60 degrees) x 10 along (10 apart from z = 10)."""
    r_in, t, L, d = 60.0, 2.0, 120.0, 3.0
    tube, _ = occ.cut([(3, occ.addCylinder(0, 0, 0, 0, 0, L, r_in + t))], [(3, occ.addCylinder(0, 0, 0, 0, 0, L, r_in))])
    tools = []
    for i in range(15):
        a = math.radians(-60 + 8 * i)
        for k in range(10):
            tools.append((3, occ.addCylinder((r_in - 5) * math.cos(a), (r_in - 5) * math.sin(a), 10.0 + 10 * k,
                                             10 * math.cos(a), 10 * math.sin(a), 0, d / 2)))
    out, _ = occ.cut(tube, tools)
    assert len([tag for dim, tag in out if dim == 3]) == 1, out
    return PI * ((r_in + t) ** 2 - r_in ** 2) * L - 150 * radial_hole_volume(r_in, r_in + t, d / 2), dict(
        dims="tube R60 inside, wall 2, 120 long, 150 radial Ø3 holes (15 around at 8° × 10 along at 10)", wall="2",
        max_bytes=MANY_MAX_BYTES, volume_tolerance=TUBE_VOLUME_TOLERANCE)


MANY_PARTS = [
    ("keyboard_plate", keyboard_plate),
    ("plate_200_holes", plate_200_holes),
    ("perforated_tube", perforated_tube),
]

MANY_README_HEAD = [
    "# HexLayer sample parts: many features",
    "",
    "Thin parts with hundreds of faces, the kind of part users mesh (issue 19):",
    "a keyboard switch plate, a plate with 200 holes and a tube with 150 radial",
    "holes (its faces cylinders). `bench/bench.py --suite",
    "many` writes them here (into its output folder) and times them against",
    "Gmsh's tet mesh, with the real parts of `../shared/parts/real`.",
]

MANY_README_NOTES = [
    "Made by `scripts/make_samples.py` (`--only many` writes this folder alone;",
    "run it with `/usr/bin/python3`, which needs the Debian package",
    "`python3-gmsh`); licence AGPL-3.0-or-later like the project. The STEP header",
    "timestamp is fixed, so regenerating the files gives byte-identical output.",
    "",
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


def check_volume(name, got, expected, tolerance=REL_TOL):
    rel = abs(got - expected) / expected
    print(f"  {name}: CAD volume {got:.9f} mm^3, analytic {expected:.9f} mm^3, "
          f"rel. error {rel:.2e}")
    assert rel <= tolerance, f"{name}: volume mismatch (rel. error {rel:.3e})"


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
    tolerance = info.pop("volume_tolerance", REL_TOL)
    max_bytes = info.pop("max_bytes", MAX_BYTES)
    occ.synchronize()
    tag, mass = single_volume_mass()
    check_no_free_entities()
    check_volume(name, mass, expected, tolerance)
    check_closed(tag)

    path = os.path.join(outdir, name + ".step")
    write_step(path)
    size = os.path.getsize(path)
    assert size < max_bytes, f"{path} is {size} bytes (limit {max_bytes})"

    # Read the file back: one closed solid with the same volume.
    gmsh.clear()
    with quiet_stdout():
        gmsh.open(path)
    tag, mass_back = single_volume_mass()
    check_no_free_entities()
    nfaces = check_closed(tag)
    check_volume(name + " (read back)", mass_back, expected, tolerance)
    print(f"  wrote {path} ({size} bytes, {nfaces} faces)")
    return dict(name=name, volume=expected, faces=nfaces, size=size, **info)  # the analytic volume, checked above


def write_readme(outdir, rows, head=None, notes=None):
    """README.md with a table of the parts, between `head` and `notes` (lists
    of lines; the defaults are those of Resources/samples)."""
    if head is None:
        head = [
            "# HexLayer sample parts",
            "",
            "Small single-solid STEP files (AP214, units mm) for tests and examples.",
            "All parts except `thick_block.step` are thin-walled parts.",
        ]
    # Junction parts have a column more: the kind of junction.
    junction = all("junction" in r for r in rows)
    lines = head + [
        "",
        "| File | Part / dimensions (mm) | Wall thickness (mm) | "
        + ("Junction | " if junction else "") + "CAD volume (mm³) |",
        "|---|---|---|" + ("---|" if junction else "") + "---|",
    ]
    for r in rows:
        kind = f" {r['junction']} |" if junction else ""
        volume = f"{r['volume']:.3f}" if r['volume'] >= 1 else f"{r['volume']:.6e}"   # a part in metres: 1e-5
        lines.append(f"| `{r['name']}.step` | {r['dims']} | {r['wall']} |{kind} {volume} |")
    lines.append("")
    lines += notes if notes is not None else [
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
        "Bent boxes (`box_sharp*`): open boxes whose walls meet the floor and each other",
        "in sharp inside edges and corners (one sheet bent with a zero inside radius),",
        "their outside edges sharp or rounded by less than the wall (quarter cylinders,",
        "eighth spheres at the bottom corners); twins in metres (planes as B-splines) and",
        "with split faces.",
        "",
        "Made by `scripts/make_samples.py` (run it with `/usr/bin/python3`, which",
        "needs the Debian package `python3-gmsh`); licence AGPL-3.0-or-later like the",
        "project. The STEP header timestamp is fixed, so regenerating the files gives",
        "byte-identical output.",
        "",
    ]
    with open(os.path.join(outdir, "README.md"), "w", encoding="utf-8", newline="\n") as fh:
        fh.write("\n".join(lines))


# ---------------------------------------------------------------------------
# Thickness steps (written to the subfolder steps/): a wall going on thinner
# past a step in one or both of its faces (a plate milled thinner from both
# sides, a groove or a round diaphragm in a plate, a thinner band round a
# tube). The thin wall stands on the thick wall's rim face, no more than its
# own thickness above or below it.
# ---------------------------------------------------------------------------

STEP_L, STEP_W, STEP_T = 100.0, 40.0, 3.0   # the plate: [0, 100] x [0, 40] x [0, 3]


def stepped_plate(z0, t, split=False):
    """STEP_L x STEP_W plate, STEP_T thick for x <= 50 and t thick (z0 ... z0 + t)
    beyond; with `split` the thick half fused from two boxes (x 0...25, 25...50)
    not unified, so its faces are split at x = 25."""
    half = STEP_L / 2
    thick = [occ.addBox(0, 0, 0, half / 2, STEP_W, STEP_T), occ.addBox(half / 2, 0, 0, half / 2, STEP_W, STEP_T)]
    if not split:
        thick = [fuse_volumes(thick)]
    fuse_volumes(thick + [occ.addBox(half, 0, z0, half, STEP_W, t)], unify=not split)
    return half * STEP_W * (STEP_T + t)


def step_both_sides():
    return stepped_plate(0.75, 1.5), dict(dims="100 × 40 plate, 3 thick for x ≤ 50, 1.5 thick (z 0.75…2.25) beyond: "
                                               "a step of 0.75 in both faces", wall="3 / 1.5")


def step_unequal():
    return stepped_plate(0.5, 1.5), dict(dims="as step_both_sides, the thin half at z 0.5…2.0: steps of 0.5 below, "
                                              "1.0 above", wall="3 / 1.5")


def step_one_side():
    return stepped_plate(1.5, 1.5), dict(dims="as step_both_sides, the thin half at z 1.5…3: the top flush, a step "
                                              "of 1.5 below", wall="3 / 1.5")


def step_split():
    return stepped_plate(0.75, 1.5, split=True), dict(
        dims="step_both_sides fused from 3 boxes not unified: the thick half's faces split at x = 25", wall="3 / 1.5")


def step_metres():
    volume = stepped_plate(0.75, 1.5)
    occ.dilate(occ.getEntities(3), 0, 0, 0, 1e-3, 1e-3, 1e-3)
    return volume * 1e-9, dict(dims="step_both_sides scaled by 1e-3 (in metres, written as mm)", wall="0.003 / 0.0015")


def step_oblique():
    # The step runs from (40, 0) to (60, 40) (63.4° to x): the thick part x <= 40 + y / 2.
    thick = extrude_polygon_xy([(0.0, 0.0), (40.0, 0.0), (60.0, STEP_W), (0.0, STEP_W)], STEP_T)
    thin = extrude_polygon_xy([(40.0, 0.0), (STEP_L, 0.0), (STEP_L, STEP_W), (60.0, STEP_W)], 1.5)
    occ.translate([(3, thin)], 0, 0, 0.75)
    fuse_volumes([thick, thin])
    return 50 * STEP_W * (STEP_T + 1.5), dict(dims="as step_both_sides, the step oblique: from (40, 0) to (60, 40)",
                                              wall="3 / 1.5")


def groove_both_sides():
    # A flexure hinge: a 10 wide groove across the plate, 0.75 deep in the top and in the bottom.
    plate = occ.addBox(0, 0, 0, STEP_L, STEP_W, STEP_T)
    grooves = [occ.addBox(45, -1, 2.25, 10, STEP_W + 2, 1), occ.addBox(45, -1, -1, 10, STEP_W + 2, 1.75)]
    one_volume(occ.cut([(3, plate)], [(3, g) for g in grooves])[0])
    return STEP_L * STEP_W * STEP_T - 10 * STEP_W * 1.5, dict(
        dims="100 × 40 × 3 plate, a groove 10 wide across it (x 45…55) 0.75 deep in both faces", wall="3 / 1.5")


def diaphragm():
    # A round diaphragm: the plate 1 thick (z 1...2) within R15 of (50, 30).
    plate = occ.addBox(0, 0, 0, STEP_L, 60, STEP_T)
    pockets = [occ.addCylinder(50, 30, 2, 0, 0, 2, 15), occ.addCylinder(50, 30, -1, 0, 0, 2, 15)]
    one_volume(occ.cut([(3, plate)], [(3, c) for c in pockets])[0])
    return STEP_L * 60 * STEP_T - math.pi * 15 ** 2 * 2, dict(
        dims="100 × 60 × 3 plate, 1 thick (z 1…2) within R15 of (50, 30): round pockets 1 deep in both faces",
        wall="3 / 1")


def step_one_side_short():
    # A plate 60 x 80, 2 thick for x <= 40, 1 thick (z 1...2, the top flush) beyond: a short thin end.
    fuse_volumes([occ.addBox(0, 0, 0, 40, 80, 2), occ.addBox(40, 0, 1, 20, 80, 1)])
    return 40 * 80 * 2 + 20 * 80 * 1, dict(dims="60 × 80 plate, 2 thick for x ≤ 40, 1 thick (z 1…2) beyond: a step of "
                                                "1 in one face, the thin end 20 long", wall="2 / 1")


def pocket_one_side():
    # A rectangular pocket 40 x 30, 1 deep, milled into the top of a 100 x 60 x 2 plate.
    plate = occ.addBox(0, 0, 0, 100, 60, 2)
    one_volume(occ.cut([(3, plate)], [(3, occ.addBox(30, 15, 1, 40, 30, 2))])[0])
    return 100 * 60 * 2 - 40 * 30 * 1, dict(dims="100 × 60 × 2 plate, a pocket 40 × 30 (x 30…70, y 15…45) 1 deep in "
                                                 "its top", wall="2 / 1")


def box_lip():
    # An open box 80 x 60 x 25, walls and floor 2 thick, its walls 1 thick (the inner half cut away) over the top 12:
    # the lip of a molded housing's half.
    box = occ.cut([(3, occ.addBox(0, 0, 0, 80, 60, 25))], [(3, occ.addBox(2, 2, 2, 76, 56, 30))])[0]
    one_volume(occ.cut(box, [(3, occ.addBox(1, 1, 13, 78, 58, 13))])[0])
    inside = 76 * 56
    return 80 * 60 * 25 - inside * 23 - (78 * 58 - inside) * 12, dict(
        dims="open box 80 × 60 × 25, walls and floor 2 thick; the walls 1 thick (the inner half cut away) over the "
             "top 12: a lip", wall="2 / 1")


def tube_band():
    # A tube R30 outside, wall 3, 60 long, 1.5 thick (R27.75...R29.25) for z 20...40.
    whole = tube(30.0, 3.0, 0.0, 60.0)
    band = tube(31.0, 5.0, 20.0, 40.0)   # R26...R31 over the band, taken away: two tubes left
    occ.cut([(3, whole)], [(3, band)])
    keep = tube(29.25, 1.5, 20.0, 40.0)
    fuse_volumes([tag for _, tag in occ.getEntities(3) if tag != keep] + [keep])
    return math.pi * ((30 ** 2 - 27 ** 2) * 40 + (29.25 ** 2 - 27.75 ** 2) * 20), dict(
        dims="tube R30 outside, wall 3, 60 long; for z 20…40 1.5 thick (R27.75…R29.25): a step of 0.75 in both "
             "faces", wall="3 / 1.5")


STEP_PARTS = [
    ("step_both_sides", step_both_sides),
    ("step_unequal", step_unequal),
    ("step_one_side", step_one_side),
    ("step_split", step_split),
    ("step_metres", step_metres),
    ("step_oblique", step_oblique),
    ("groove_both_sides", groove_both_sides),
    ("diaphragm", diaphragm),
    ("tube_band", tube_band),
    ("step_one_side_short", step_one_side_short),
    ("pocket_one_side", pocket_one_side),
    ("box_lip", box_lip),
]

STEP_README_HEAD = [
    "# HexLayer sample parts: thickness steps",
    "",
    "Small single-solid STEP files (AP214, units mm unless named metres) whose",
    "wall goes on thinner past a step in one or both of its faces: a plate",
    "milled thinner from both sides (steps equal, unequal, on one side, the",
    "step oblique, faces split, in metres), a groove across a plate, a round",
    "diaphragm, a thinner band round a tube; steps in one face: a plate's short",
    "thin end, a pocket milled into a plate, the lip round an open box's walls.",
]

STEP_README_NOTES = [
    "Made by `scripts/make_samples.py` (`--only steps` writes this folder alone;",
    "run it with `/usr/bin/python3`, which needs the Debian package",
    "`python3-gmsh`); licence AGPL-3.0-or-later like the project. The STEP header",
    "timestamp is fixed, so regenerating the files gives byte-identical output.",
    "",
]


# ---------------------------------------------------------------------------
# Narrow air gaps (written to the subfolder gaps/): a sheet folded back over
# itself, the air between its two legs no wider than about the sheet is thick
# (an open hem of sheet metal, a spring clip).
# ---------------------------------------------------------------------------

HEM_L, HEM_W, HEM_LEG = 100.0, 40.0, 20.0   # the sheet [0, 100] x [0, 40]; the leg folded back over x 80...100


def hem_volume(t, ri, leg=HEM_LEG, length=HEM_L, width=HEM_W):
    return width * ((length + leg) * t + 0.5 * math.pi * ((ri + t) ** 2 - ri ** 2))


def hem(t, ri, leg=HEM_LEG, length=HEM_L, width=HEM_W, split=False):
    """A sheet t thick, z 0...t, folded back at x = length round a half ring of
    inner radius ri: the leg over x length - leg ... length, z t + 2 ri ... 2 t +
    2 ri, the air between 2 ri wide. With `split` the sheet is fused from two
    boxes (x 0...50, 50...length) and the leg from two (split at its middle),
    not unified: their faces split there."""
    ro = ri + t
    ring = occ.cut([(3, occ.addCylinder(length, 0, ro, 0, width, 0, ro))],
                   [(3, occ.addCylinder(length, 0, ro, 0, width, 0, ri))])[0]
    ring = occ.intersect(ring, [(3, occ.addBox(length, -1, -1, ro + 1, width + 2, 2 * ro + 2))])[0]
    cuts = [0.0, 50.0, length] if split else [0.0, length]
    sheet = [occ.addBox(a, 0, 0, b - a, width, t) for a, b in zip(cuts, cuts[1:])]
    legs = [length - leg, length - leg / 2, length] if split else [length - leg, length]
    back = [occ.addBox(a, 0, t + 2 * ri, b - a, width, t) for a, b in zip(legs, legs[1:])]
    fuse_volumes(sheet + back + [tag for _, tag in ring], unify=not split)
    return hem_volume(t, ri, leg, length, width)


def hem_open():
    return hem(1.0, 0.5), dict(dims="sheet 100 × 40 × 1 folded back at x = 100 round R0.5 inside: a leg 20 long "
                                    "over it, the air between 1.0 wide (as thick as the sheet)", wall="1")


def hem_narrow():
    return hem(1.0, 0.3), dict(dims="as hem_open, folded round R0.3: the air 0.6 wide", wall="1")


def hem_thick():
    return hem(2.0, 0.75), dict(dims="as hem_open, 2 thick, folded round R0.75: the air 1.5 wide", wall="2")


def hem_split():
    return hem(1.0, 0.5, split=True), dict(dims="hem_open fused from boxes not unified: the sheet's faces split at "
                                                "x = 50, the leg's at x = 90", wall="1")


def hem_metres():
    volume = hem(1.0, 0.5)
    occ.dilate(occ.getEntities(3), 0, 0, 0, 1e-3, 1e-3, 1e-3)
    # Gmsh's mass of the half ring in metres is 9e-4 off its exact volume (its integration's absolute tolerance).
    return volume * 1e-9, dict(dims="hem_open scaled by 1e-3 (in metres, written as mm)", wall="0.001",
                               volume_tolerance=2e-3)


def spring_clip():
    return hem(1.5, 0.6, leg=30.0, length=30.0, width=20.0), dict(
        dims="two legs 30 × 20 × 1.5 joined by a half ring R0.6 inside: the air between them 1.2 wide", wall="1.5")


GAP_PARTS = [
    ("hem_open", hem_open),
    ("hem_narrow", hem_narrow),
    ("hem_thick", hem_thick),
    ("hem_split", hem_split),
    ("hem_metres", hem_metres),
    ("spring_clip", spring_clip),
]

GAP_README_HEAD = [
    "# HexLayer sample parts: narrow air gaps",
    "",
    "Small single-solid STEP files (AP214, units mm unless named metres): a",
    "sheet folded back over itself, the air between its two legs no wider",
    "than about the sheet is thick (open hems of sheet metal: the air as wide",
    "as the sheet, 0.6 of it, 0.75 of it on a sheet 2 thick, the faces split, in",
    "metres; a spring clip).",
]

GAP_README_NOTES = ["Made by `scripts/make_samples.py` (`--only gaps` writes this folder alone;"] + STEP_README_NOTES[1:]


def make_subfolder(outdir, folder, parts, head, notes):
    """Write `parts` (name, builder) to OUTPUT_DIR/folder with a README.md of
    their own, between `head` and `notes`."""
    subdir = os.path.join(outdir, folder)
    os.makedirs(subdir, exist_ok=True)
    rows = []
    for name, builder in parts:
        print(folder + "/" + name)
        rows.append(make_part(name, builder, subdir))
    write_readme(subdir, rows, head, notes)
    print(f"wrote {len(rows)} STEP files and README.md to {subdir}")


def main(argv):
    repo_root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    only = None
    if len(argv) >= 3 and argv[-2] == "--only":
        only, argv = argv[-1], argv[:-2]
    if len(argv) > 2 or only not in (None, "many", "steps", "gaps"):
        sys.exit("usage: make_samples.py [OUTPUT_DIR] [--only many|steps|gaps]")
    outdir = argv[1] if len(argv) == 2 else os.path.join(repo_root, "Resources", "samples")
    os.makedirs(outdir, exist_ok=True)

    gmsh.initialize(readConfigFiles=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        if only == "many":
            make_subfolder(outdir, "many", MANY_PARTS, MANY_README_HEAD, MANY_README_NOTES)
            return 0
        if only == "steps":
            make_subfolder(outdir, "steps", STEP_PARTS, STEP_README_HEAD, STEP_README_NOTES)
            return 0
        if only == "gaps":
            make_subfolder(outdir, "gaps", GAP_PARTS, GAP_README_HEAD, GAP_README_NOTES)
            return 0
        rows = []
        for name, builder in PARTS:
            print(name)
            rows.append(make_part(name, builder, outdir))
        # The rim parts last (see the note on PARTS), then the junction parts, then the bent boxes (in OUTPUT_DIR).
        make_subfolder(outdir, "rims", RIM_PARTS, RIM_README_HEAD, RIM_README_NOTES)
        make_subfolder(outdir, "junctions", JUNCTION_PARTS, JUNCTION_README_HEAD, JUNCTION_README_NOTES)
        make_subfolder(outdir, "steps", STEP_PARTS, STEP_README_HEAD, STEP_README_NOTES)
        make_subfolder(outdir, "gaps", GAP_PARTS, GAP_README_HEAD, GAP_README_NOTES)
        for name, builder in BENT_BOX_PARTS:
            print(name)
            rows.append(make_part(name, builder, outdir))
        write_readme(outdir, rows)
        print(f"wrote {len(rows)} STEP files and README.md to {outdir}")
    finally:
        gmsh.finalize()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
