#!/usr/bin/python3
# SPDX-License-Identifier: AGPL-3.0-or-later
"""Compare HexLayer's meshes with Gmsh's all-hex meshes by subdivision of tets, part by part.

Usage: /usr/bin/python3 scripts/compare_gmsh.py --hexlayer build/hexlayer [--out docs] [STEP ...]
Needs Debian's python3-gmsh, python3-meshio, python3-numpy and python3-matplotlib.

For each part: HexLayer with default options (its report gives the size, the wall thickness), then Gmsh on the
same STEP with Mesh.MeshSizeMin = Mesh.MeshSizeMax = that size and Mesh.SubdivisionAlgorithm = 2. Both meshes
are measured here with one Verdict scaled Jacobian (SJ); ours is checked against the SJ in HexLayer's report.
Writes OUT/comparison.md, OUT/comparison_sj_histograms.png and OUT/comparison_<part>.png.
"""
import argparse
import glob
import json
import os
import platform
import subprocess
import sys
import tempfile
import time

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import meshio  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import render_mesh  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REAL_PART = os.path.join(REPO, "..", "shared", "parts", "real", "ender3_x_motor_bracket_flatplate.step")
NOT_THIN = {"thick_block"}
PICTURED_PART = "plate_holes"
CLOSE_UP_ZOOM = 6
GOOD_SJ = 0.9
GMSH_HEXAHEDRON = 5
GMSH_DEFAULTS_STATED = ("Mesh.Algorithm", "Mesh.Algorithm3D", "Mesh.Optimize", "General.NumThreads")
# For corner k of a VTK/Gmsh hexahedron, the far ends of its edges e1, e2, e3 (right-handed for a positive hex).
CORNER_EDGES = np.array([[1, 3, 4], [2, 0, 5], [3, 1, 6], [0, 2, 7], [7, 5, 0], [4, 6, 1], [5, 7, 2], [6, 4, 3]])
# Natural coordinates (xi, eta, zeta) of the 8 corners.
CORNER_SIGNS = np.array([[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1],
                         [-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]], dtype=float)


# ---- measures of a hex mesh -------------------------------------------------------------------------------

def scaled_jacobian(points, hexes):
    """Verdict hex SJ: min over the 8 corners of det[e1 e2 e3] / (|e1||e2||e3|); -1 for a degenerate edge."""
    x = points[hexes]                                             # (n, 8, 3)
    e = x[:, CORNER_EDGES] - x[:, :, None, :]                     # (n, 8 corners, 3 edges, 3)
    det = np.einsum("nki,nki->nk", e[:, :, 0], np.cross(e[:, :, 1], e[:, :, 2]))
    lengths = np.linalg.norm(e, axis=3).prod(axis=2)
    sj = np.where(lengths > 0, det / np.where(lengths > 0, lengths, 1), -1.0)
    return sj.min(axis=1)


def hex_volumes(points, hexes):
    """Volume of each trilinear hex: det J integrated by 2x2x2 Gauss (exact for a trilinear map)."""
    x = points[hexes]
    volume = np.zeros(len(hexes))
    for s in CORNER_SIGNS / np.sqrt(3.0):
        f = 1 + CORNER_SIGNS * s                                  # (8, 3): 1 + c_d s_d
        grad = CORNER_SIGNS * f[:, [1, 0, 0]] * f[:, [2, 2, 1]] / 8  # dN_i / d(xi, eta, zeta)
        volume += np.linalg.det(np.einsum("nid,ie->nde", x, grad))
    return volume


def require_pure_hex(types, hexahedron, mesher):
    if list(types) != [hexahedron]:
        raise RuntimeError(f"{mesher} mesh is not all hexes: element types {list(types)}")


def summary(sj, mesh_volume, cad_volume, seconds):
    return {"hexes": len(sj), "sj_min": float(sj.min()), "sj_avg": float(sj.mean()),
            "good_share": float(np.mean(sj >= GOOD_SJ)), "inverted": int(np.sum(sj <= 0)),
            "volume_error": (mesh_volume - cad_volume) / cad_volume, "seconds": seconds, "sj": sj}


# ---- the two meshers ----------------------------------------------------------------------------------------

def mesh_with_hexlayer(hexlayer, step, workdir):
    """Default HexLayer run; SJ measured here from the .vtu and checked against the report and the file's field."""
    name = os.path.splitext(os.path.basename(step))[0]
    vtu, report_path = os.path.join(workdir, name + ".vtu"), os.path.join(workdir, name + ".json")
    start = time.perf_counter()
    done = subprocess.run([hexlayer, "mesh", step, "-o", vtu, "--report", report_path, "--quiet"],
                          capture_output=True, text=True, timeout=600)
    seconds = time.perf_counter() - start
    if done.returncode != 0:
        raise RuntimeError(f"hexlayer exit {done.returncode}: {done.stderr.strip()[-300:]}")
    with open(report_path) as f:
        report = json.load(f)
    m = meshio.read(vtu)
    require_pure_hex([c.type for c in m.cells], "hexahedron", "HexLayer")
    hexes = m.cells_dict["hexahedron"]
    sj = scaled_jacobian(m.points, hexes)
    result = summary(sj, report["volume"]["mesh"], report["volume"]["cad"], seconds)
    reported = report["scaled_jacobian"]
    result.update(report=report, mesh=(m.points, hexes), cell_types=[c.type for c in m.cells],
                  sj_vs_report=max(abs(sj.min() - reported["min"]), abs(sj.mean() - reported["avg"])),
                  sj_vs_file=float(np.abs(sj - m.cell_data_dict["scaled_jacobian"]["hexahedron"]).max()))
    return result


def gmsh_hex_mesh(gmsh):
    """Points, hexes (node indices, Gmsh order = VTK order) and the types of all 3D elements of Gmsh's model."""
    tags, coords, _ = gmsh.model.mesh.getNodes()
    index = np.zeros(int(tags.max()) + 1, dtype=np.int64)
    index[tags.astype(np.int64)] = np.arange(len(tags))
    types, _, _ = gmsh.model.mesh.getElements(3)
    _, nodes = gmsh.model.mesh.getElementsByType(GMSH_HEXAHEDRON)
    hexes = index[np.asarray(nodes, dtype=np.int64)].reshape(-1, 8)
    return coords.reshape(-1, 3), hexes, [int(t) for t in types]


def mesh_with_gmsh(step, size):
    """Gmsh: OCC import, 3D mesh at MeshSizeMin = Max = size, all-hex by subdivision (algorithm 2)."""
    import gmsh
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        start = time.perf_counter()
        gmsh.model.occ.importShapes(step)
        gmsh.model.occ.synchronize()
        gmsh.option.setNumber("Mesh.MeshSizeMin", size)
        gmsh.option.setNumber("Mesh.MeshSizeMax", size)
        gmsh.option.setNumber("Mesh.SubdivisionAlgorithm", 2)
        gmsh.model.mesh.generate(3)
        seconds = time.perf_counter() - start
        defaults = {k: gmsh.option.getNumber(k) for k in GMSH_DEFAULTS_STATED}
        cad_volume = sum(gmsh.model.occ.getMass(d, t) for d, t in gmsh.model.getEntities(3))
        points, hexes, types = gmsh_hex_mesh(gmsh)
    finally:
        gmsh.finalize()
    require_pure_hex(types, GMSH_HEXAHEDRON, "Gmsh")
    sj = scaled_jacobian(points, hexes)
    result = summary(sj, hex_volumes(points, hexes).sum(), cad_volume, seconds)
    result.update(mesh=(points, hexes), element_types=types, cad_volume=cad_volume, defaults=defaults)
    return result


def attempt(mesher, *args):
    try:
        return mesher(*args)
    except Exception as e:  # a mesher that fails on a part is a result of the comparison, not a crash of it
        return {"error": f"{type(e).__name__}: {e}"}


def compare_part(hexlayer, step, workdir):
    ours = attempt(mesh_with_hexlayer, hexlayer, step, workdir)
    size = ours["report"]["size"] if "report" in ours else None
    theirs = attempt(mesh_with_gmsh, step, size) if size else {"error": "no size: HexLayer failed"}
    return {"part": os.path.splitext(os.path.basename(step))[0], "step": step, "size": size,
            "ours": ours, "gmsh": theirs}


# ---- output ----------------------------------------------------------------------------------------------

def sj_text(v):
    return f"{v:.3f}" if abs(v) >= 1e-3 else f"{v:.1e}"


def table_row(part, mesher, r):
    if "error" in r:
        return f"| {part} | {mesher} | failed: {r['error']} | | | | | | |"
    return (f"| {part} | {mesher} | {r['hexes']:,} | {sj_text(r['sj_min'])} | {r['sj_avg']:.3f} | "
            f"{100 * r['good_share']:.1f} % | {r['inverted']} | {100 * r['volume_error']:+.2f} % | "
            f"{r['seconds']:.1f} |")


def table(results):
    lines = ["| part (size, mm) | mesher | hexes | SJ min | SJ avg | SJ ≥ 0.9 | SJ ≤ 0 | volume error | time (s) |",
             "|---|---|---:|---:|---:|---:|---:|---:|---:|"]
    for c in results:
        part = f"{c['part']} ({c['size']:g})" if c["size"] else c["part"]
        lines.append(table_row(part, "HexLayer", c["ours"]))
        lines.append(table_row(part, "Gmsh subdivision", c["gmsh"]))
    return "\n".join(lines)


def plot_histograms(results, png):
    done = [c for c in results if "sj" in c["ours"] and "sj" in c["gmsh"]]
    cols = 4
    rows = -(-len(done) // cols)
    fig, axes = plt.subplots(rows, cols, figsize=(4 * cols, 3.2 * rows), dpi=110, squeeze=False)
    lo = min(0.0, *(np.floor(c[m]["sj"].min() * 10) / 10 for c in done for m in ("ours", "gmsh")))
    bins = np.linspace(lo, 1, int(round((1 - lo) / 0.025)) + 1)
    for ax, c in zip(axes.flat, done):
        for key, label, color in (("gmsh", "Gmsh subdivision", "tab:orange"), ("ours", "HexLayer", "tab:blue")):
            sj = c[key]["sj"]
            ax.hist(sj, bins=bins, weights=np.full(len(sj), 100 / len(sj)), color=color, alpha=0.6,
                    label=f"{label} ({len(sj):,} hexes)")
            ax.axvline(sj.min(), color=color, linestyle="--", linewidth=1, label=f"{label} min {sj.min():.2f}")
        ax.set_title(f"{c['part']} (size {c['size']:g} mm)", fontsize=10)
        ax.set_xlabel("scaled Jacobian")
        ax.set_ylabel("% of hexes")
        ax.legend(fontsize=7, loc="upper left")
    for ax in axes.flat[len(done):]:
        ax.set_axis_off()
    fig.tight_layout()
    fig.savefig(png)
    plt.close(fig)


def render_side_by_side(c, png):
    """Both meshes of part c: the whole part above, a close-up around Gmsh's worst hex below."""
    points, hexes = c["gmsh"]["mesh"]
    worst = points[hexes[np.argmin(c["gmsh"]["sj"])]].mean(0)
    fig = plt.figure(figsize=(16, 12), dpi=100)
    axes = [fig.add_subplot(2, 2, i + 1, projection="3d") for i in range(4)]
    for i, (key, label) in enumerate((("ours", "HexLayer"), ("gmsh", "Gmsh all-hex by subdivision"))):
        r = c[key]
        render_mesh.draw_hex_mesh(axes[i], *r["mesh"], r["sj"], zoom=1.5)
        axes[i].set_title(f"{label}: {r['hexes']:,} hexes, SJ min {r['sj_min']:.2f}, avg {r['sj_avg']:.3f}")
        render_mesh.draw_hex_mesh(axes[i + 2], *r["mesh"], r["sj"], elev=40, zoom=CLOSE_UP_ZOOM, centre=worst)
        axes[i + 2].set_title(f"{label}: close-up around Gmsh's worst hex")
    fig.subplots_adjust(wspace=0.02, hspace=-0.1)
    render_mesh.add_sj_colorbar(fig, axes)
    fig.savefig(png, bbox_inches="tight")
    plt.close(fig)


def sj_check_sentence(results):
    ours = [c["ours"] for c in results if "sj_vs_report" in c["ours"]]
    worst_report = max((r["sj_vs_report"] for r in ours), default=float("nan"))
    worst_file = max((r["sj_vs_file"] for r in ours), default=float("nan"))
    return (f"Our SJ computed here from the `.vtu` agrees with the `--report` JSON to {worst_report:.1e} (min and "
            f"avg) and with the per-hex `scaled_jacobian` field of the file to {worst_file:.1e}, so both "
            f"meshes are measured with the same definition.")


def subdivision_sentence(results):
    best = max((c["gmsh"]["sj"].max() for c in results if "sj" in c["gmsh"]), default=float("nan"))
    return (f"The best Gmsh hex over all parts has SJ {best:.3f}: a hex cut from the corner of a regular tet has "
            f"SJ 1/√2 ≈ 0.707 at that corner, where three tet edges meet at 60°, which is why no subdivision hex "
            f"here reaches 0.9.")


def gmsh_defaults_text(results):
    defaults = next((c["gmsh"]["defaults"] for c in results if "defaults" in c["gmsh"]), {})
    return ", ".join(f"`{k} = {v:g}`" for k, v in defaults.items())


def real_part_text(results):
    if not any(os.path.normpath(c["step"]) == os.path.normpath(REAL_PART) for c in results):
        return ""
    return """The real part `ender3_x_motor_bracket_flatplate.step` is Creality's Ender-3 *X motor bracket*
(repository Creality3DPrinting/Ender-3, `Ender-3 Mechanical/STP/X motor bracket.step`, licence GPL-3.0), an
unmodified copy listed in `../shared/parts/real/SOURCES.md`.
"""


def relative(path):
    return os.path.relpath(os.path.abspath(path), REPO)


def markdown(results, command, pictures):
    import gmsh
    parts = "\n".join(f"- `{relative(c['step'])}`" for c in results)
    return f"""# HexLayer vs Gmsh all-hex by subdivision

Generated by `{command}` from the repository root; do not edit by hand.

For each part, HexLayer runs with default options (its quad size is the wall thickness, `size` in the report).
Gmsh {gmsh.__version__} (Debian's `python3-gmsh`) meshes the same STEP through its Python API: OpenCASCADE import,
`Mesh.MeshSizeMin = Mesh.MeshSizeMax =` that same size, `Mesh.SubdivisionAlgorithm = 2` (every tet split into
4 hexes: the all-hex mesh FreeCAD FEM offers today), every other option at its default
({gmsh_defaults_text(results)}). Every 3D element of both meshes is checked to be a hexahedron (a mesh that
is not would be reported as failed). Both meshes are measured by this script with one Verdict scaled
Jacobian (SJ): for each of the 8 corners, det[e1 e2 e3] / (|e1| |e2| |e3|) of its three edges in
right-handed order, the minimum over the corners. {sj_check_sentence(results)}

Conditions: same size parameter, but Gmsh's size is the edge of the tets *before* subdivision, so its hexes
are about half that long and there are more of them; HexLayer's size is the quad edge, and its layers span
the wall. Volume error is the mesh volume against the OpenCASCADE volume of the part. Time is wall-clock on
{os.cpu_count()} cores ({platform.machine()}): for HexLayer the whole CLI run (read STEP, mesh, write `.vtu`;
OpenMP on all cores), for Gmsh the import plus `generate(3)` (thread count above). No benchmark suite is
involved: the parts are the bundled samples (`thick_block.step` left out: it is not thin) and one real part.

{table(results)}

SJ ≤ 0 counts inverted hexes. {subdivision_sentence(results)}

Parts:
{parts}

{real_part_text(results)}
## Scaled Jacobian distribution

![SJ histograms]({pictures['histograms']})

## The meshes of {PICTURED_PART}

Boundary faces coloured by the SJ of their hex.

![{PICTURED_PART}: HexLayer and Gmsh]({pictures['render']})
"""


def default_parts():
    samples = sorted(glob.glob(os.path.join(REPO, "Resources", "samples", "*.step")))
    thin = [p for p in samples if os.path.splitext(os.path.basename(p))[0] not in NOT_THIN]
    return [relative(p) for p in thin] + [relative(REAL_PART)]


def print_progress(c):
    for key in ("ours", "gmsh"):
        r = c[key]
        said = r["error"] if "error" in r else f"{r['hexes']} hexes, SJ min {r['sj_min']:.3f} avg {r['sj_avg']:.3f}"
        print(f"{c['part']}: {key}: {said}", flush=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--hexlayer", default=os.path.join(REPO, "build", "hexlayer"))
    ap.add_argument("--out", default=os.path.join(REPO, "docs"))
    ap.add_argument("steps", nargs="*", help="STEP files, paths relative to the repository (default: the samples)")
    a = ap.parse_args()
    results = []
    with tempfile.TemporaryDirectory() as work:
        for step in a.steps or default_parts():
            results.append(compare_part(os.path.abspath(a.hexlayer), os.path.join(REPO, step), work))
            print_progress(results[-1])
    pictures = {"histograms": "comparison_sj_histograms.png", "render": f"comparison_{PICTURED_PART}.png"}
    plot_histograms(results, os.path.join(a.out, pictures["histograms"]))
    pictured = [c for c in results if c["part"] == PICTURED_PART and "sj" in c["gmsh"]]
    if pictured:
        render_side_by_side(pictured[0], os.path.join(a.out, pictures["render"]))
    command = " ".join(["/usr/bin/python3", relative(sys.argv[0]), *sys.argv[1:]])
    with open(os.path.join(a.out, "comparison.md"), "w") as f:
        f.write(markdown(results, command, pictures))


if __name__ == "__main__":
    main()
