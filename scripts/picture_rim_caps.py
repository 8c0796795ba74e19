"""docs/round_rim_plate.png: the near-full-round plate (Resources/samples/rims/plate_full_round.step) meshed by
hexlayer, its surface coloured by each hex's scaled Jacobian, and the section through one rim column of a long
side with 2 and 3 layers (the sweep's hexes and the rim cap's).

Usage: /usr/bin/python3 scripts/picture_rim_caps.py --hexlayer build/hexlayer [--out docs/round_rim_plate.png]
"""
import argparse
import os
import subprocess
import sys
import tempfile

import matplotlib
import meshio
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tests", "python"))
from hex_geometry import HEX_FACES, boundary_faces, hex_scaled_jacobians  # noqa: E402

def mesh(hexlayer, layers, tmp):
    step = os.path.join(HERE, "..", "Resources", "samples", "rims", "plate_full_round.step")
    out = os.path.join(tmp, f"plate_{layers}.vtu")
    subprocess.run([hexlayer, "mesh", step, "-o", out, "--layers", str(layers), "--quiet"], check=True)
    m = meshio.read(out)
    x, hexes = m.points, m.cells_dict["hexahedron"]
    return x, hexes, hex_scaled_jacobians(x, hexes)


def section(x, hexes, sj):
    """The hex faces in the plane of the rim column nearest the middle of the side y = min: (quads in (y, z), SJ)."""
    ymin = x[:, 1].min()
    near = x[np.abs(x[:, 1] - ymin) < 1e-6]
    x0 = near[np.argmin(np.abs(near[:, 0] - x[:, 0].mean())), 0]
    quads, colour = [], []
    for h, e in enumerate(hexes):
        for f in HEX_FACES:
            p = x[[e[i] for i in f]]
            if np.all(np.abs(p[:, 0] - x0) < 1e-4) and p[:, 1].max() < ymin + 5:
                quads.append(p[:, [1, 2]])
                colour.append(sj[h])
    return quads, colour


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--hexlayer", required=True)
    ap.add_argument("--out", default=os.path.join(HERE, "..", "docs", "round_rim_plate.png"))
    a = ap.parse_args()
    cmap, norm = plt.get_cmap("viridis"), plt.Normalize(0, 1)
    fig = plt.figure(figsize=(14, 6.5))
    with tempfile.TemporaryDirectory() as tmp:
        meshes = {layers: mesh(a.hexlayer, layers, tmp) for layers in (2, 3)}
    x, hexes, sj = meshes[2]
    ax = fig.add_axes([0.0, 0.05, 0.55, 0.9], projection="3d")
    quads, owners = boundary_faces(hexes)
    ax.add_collection3d(Poly3DCollection(x[quads], facecolors=cmap(norm(sj[owners])), edgecolors="k", linewidths=0.2))
    lo, hi = x.min(0), x.max(0)
    ax.set_xlim(lo[0], hi[0]), ax.set_ylim(lo[1], hi[1]), ax.set_zlim(-7, 9)
    ax.set_box_aspect((hi[0] - lo[0], hi[1] - lo[1], 16), zoom=1.0)
    ax.view_init(28, -60)
    ax.set_axis_off()
    ax.set_title(f"plate_full_round, 2 layers: {len(hexes)} hexes, SJ min {sj.min():.2f} avg {sj.mean():.3f}")
    for i, layers in enumerate((2, 3)):
        x, hexes, sj = meshes[layers]
        quads, colour = section(x, hexes, sj)
        ax = fig.add_axes([0.58, 0.55 - 0.47 * i, 0.34, 0.38])
        ax.add_collection(PolyCollection(quads, facecolors=cmap(norm(colour)), edgecolors="k", linewidths=0.8))
        ax.autoscale()
        ax.set_aspect("equal")
        ax.set_title(f"section of a long side, {layers} layers: cap hexes min {min(colour):.2f}")
        ax.set_xlabel("y (mm)"), ax.set_ylabel("z (mm)")
    bar = fig.add_axes([0.94, 0.15, 0.015, 0.7])
    fig.colorbar(plt.cm.ScalarMappable(norm=norm, cmap=cmap), cax=bar, label="scaled Jacobian")
    fig.savefig(a.out, dpi=80)


if __name__ == "__main__":
    main()
