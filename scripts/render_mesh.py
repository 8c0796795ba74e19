#!/usr/bin/python3
# SPDX-License-Identifier: AGPL-3.0-or-later
"""Render the boundary of a HexLayer .vtu mesh to a PNG, faces coloured by the hex's scaled Jacobian.

draw_hex_mesh() draws any hex mesh (points, hexes, SJ per hex); scripts/compare_gmsh.py uses it.

Usage: /usr/bin/python3 scripts/render_mesh.py MESH.vtu OUT.png [--title TEXT] [--elev DEG] [--azim DEG]
Needs Debian's python3-meshio and python3-matplotlib.
"""
import argparse
import collections

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import meshio  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

# Outward faces of a VTK hexahedron (corners 0-3 bottom, 4-7 top).
HEX_FACES = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]


def boundary_faces(hexes):
    """Faces used by exactly one hex, with the index of that hex."""
    seen = collections.defaultdict(list)
    for h, hexa in enumerate(hexes):
        for f in HEX_FACES:
            nodes = tuple(hexa[list(f)])
            seen[tuple(sorted(nodes))].append((h, nodes))
    return [uses[0] for uses in seen.values() if len(uses) == 1]


def draw_hex_mesh(ax, points, hexes, sj, elev=28, azim=-58, zoom=1.6, centre=None):
    """Draw the boundary faces of any hex mesh (VTK corner order) on a 3D axes, coloured by each hex's SJ.
    With centre, a close-up: only the faces whose middle lies in the ball of the zoomed view around centre."""
    lo, hi = points.min(0), points.max(0)
    half = (hi - lo).max() / 2 / zoom
    faces = boundary_faces(hexes)
    if centre is None:
        centre = (lo + hi) / 2
    else:
        faces = [(h, nodes) for h, nodes in faces if np.linalg.norm(points[list(nodes)].mean(0) - centre) <= half]
    polys = [points[list(nodes)] for _, nodes in faces]
    colors = plt.cm.viridis(np.clip(np.array([sj[h] for h, _ in faces]), 0, 1))
    # Light the faces by their normal so the layers and bends read in a still picture.
    normals = np.array([np.cross(p[2] - p[0], p[3] - p[1]) for p in polys])
    normals /= np.maximum(np.linalg.norm(normals, axis=1), 1e-30)[:, None]
    light = np.array([0.3, -0.5, 0.8]) / np.linalg.norm([0.3, -0.5, 0.8])
    shade = 0.55 + 0.45 * np.abs(normals @ light)
    colors[:, :3] *= shade[:, None]
    ax.add_collection3d(Poly3DCollection(polys, facecolors=colors, edgecolors=(0, 0, 0, 0.55), linewidths=0.25))
    for setter, c in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), centre):
        setter(c - half, c + half)
    ax.set_box_aspect((1, 1, 1))
    ax.view_init(elev, azim)
    ax.set_axis_off()


def add_sj_colorbar(fig, ax):
    sm = plt.cm.ScalarMappable(cmap="viridis", norm=plt.Normalize(0, 1))
    fig.colorbar(sm, ax=ax, shrink=0.6, label="scaled Jacobian (Verdict)")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("mesh")
    ap.add_argument("png")
    ap.add_argument("--title", default="")
    ap.add_argument("--elev", type=float, default=28)
    ap.add_argument("--azim", type=float, default=-58)
    ap.add_argument("--zoom", type=float, default=1.6, help="magnification of the whole part")
    a = ap.parse_args()
    m = meshio.read(a.mesh)
    hexes = m.cells_dict["hexahedron"]
    sj = m.cell_data_dict["scaled_jacobian"]["hexahedron"]
    fig = plt.figure(figsize=(11, 8), dpi=120)
    ax = fig.add_subplot(projection="3d")
    draw_hex_mesh(ax, m.points, hexes, sj, a.elev, a.azim, a.zoom)
    add_sj_colorbar(fig, ax)
    ax.set_title(a.title or f"{len(hexes)} hexes, scaled Jacobian min {sj.min():.2f}, avg {sj.mean():.3f}")
    fig.savefig(a.png, bbox_inches="tight")


if __name__ == "__main__":
    main()
