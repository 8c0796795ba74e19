#!/usr/bin/python3
# SPDX-License-Identifier: AGPL-3.0-or-later
"""HexLayer speed and scale benchmark (issue 6). Not part of the test suite.

Meshes parts with the `hexlayer` CLI and, in the same run, Gmsh's 3D tet mesh of the same part at
the same size (what a FreeCAD FEM user runs today). Prints, per case: wall time and peak memory of
each, hexes per second, the time of every HexLayer stage (the report's timings_s) and the ratio
HexLayer / Gmsh. Writes all numbers as JSON, and optionally a scaling plot.

Usage (Debian's /usr/bin/python3, which has python3-gmsh and matplotlib):
    bench/bench.py [--hexlayer build/hexlayer] [--suite target|scaling|samples|many|junctions|all]
                   [--threads N] [--out out/bench] [--plot docs/scaling.png]
                   [--no-gmsh-above HEXES] [--timeout SECONDS] [--repeat N]

With --repeat N each part is meshed N times by HexLayer and by Gmsh, alternately, and the medians are reported
(Gmsh's own time moves by up to 40 % from run to run on a shared machine); the row lists every run's pair too.

Suite `many` (issue 19): parts with many features, at HexLayer's default size (the wall thickness): the keyboard
plate, the plate with 200 holes and the perforated tube of `scripts/make_samples.py --only many` (written into
OUT/many), and every
part of ../shared/parts/real, as a user meshes it (junctions meshed, the default since issue 18). Per part it prints the CAD faces too, and its --plot is
time against the number of CAD faces.
"""
import argparse
import json
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

# Gmsh's tet mesh of a STEP file at one size, run in its own process so that its time and memory
# are measured like HexLayer's. Prints the tet count and Gmsh's own meshing time.
GMSH_TETS = r"""
import sys, time, gmsh
step, size = sys.argv[1], float(sys.argv[2])
gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
gmsh.model.occ.importShapes(step)
gmsh.model.occ.synchronize()
gmsh.option.setNumber("Mesh.MeshSizeMin", size)
gmsh.option.setNumber("Mesh.MeshSizeMax", size)
start = time.perf_counter()
gmsh.model.mesh.generate(3)
seconds = time.perf_counter() - start
tags, _ = gmsh.model.mesh.getElementsByType(4)
print(len(gmsh.model.getEntities(2)), len(tags), seconds)
gmsh.finalize()
"""


def make_plate(path, length, width, thickness, holes):
    """A box plate with vertical through holes (x, y, radius), written as STEP by Gmsh's OCC
    (whose STEP writer prints its statistics on file descriptor 1: sent to /dev/null)."""
    import gmsh
    sys.stdout.flush()
    saved, devnull = os.dup(1), os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, 1)
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        occ = gmsh.model.occ
        box = occ.addBox(0, 0, 0, length, width, thickness)
        if holes:
            occ.cut([(3, box)], [(3, occ.addCylinder(x, y, -1, 0, 0, thickness + 2, r)) for x, y, r in holes])
        occ.synchronize()
        gmsh.write(path)
    finally:
        gmsh.finalize()
        os.dup2(saved, 1)
        os.close(saved), os.close(devnull)


def run_measured(command, timeout, env=None):
    """Runs a command; returns (exit code, stdout, stderr, wall seconds, peak RSS in MiB). The peak
    is the kernel's for the process and every child it waited for (wait4, RUSAGE_BOTH)."""
    out_path, err_path = "/tmp/hexlayer_bench_%d.out" % os.getpid(), "/tmp/hexlayer_bench_%d.err" % os.getpid()
    with open(out_path, "w") as out, open(err_path, "w") as err:
        start = time.perf_counter()
        proc = subprocess.Popen(command, stdout=out, stderr=err, env=env)
        deadline = start + timeout
        while True:
            pid, status, usage = os.wait4(proc.pid, os.WNOHANG)
            if pid:
                break
            if time.perf_counter() > deadline:
                proc.kill()
                pid, status, usage = os.wait4(proc.pid, 0)
                break
            time.sleep(0.01)
        wall = time.perf_counter() - start
    proc.returncode = os.waitstatus_to_exitcode(status)
    with open(out_path) as out, open(err_path) as err:
        stdout, stderr = out.read(), err.read()
    os.remove(out_path), os.remove(err_path)
    return proc.returncode, stdout, stderr, wall, usage.ru_maxrss / 1024.0


def run_hexlayer(args, case, out_dir):
    report = os.path.join(out_dir, case["name"] + ".json")
    mesh = os.path.join(out_dir, case["name"] + ".inp")
    command = [args.hexlayer, "mesh", case["step"], "-o", mesh, "--report", report, "--quiet",
               "--layers", str(case["layers"]), *case.get("options", [])]
    if case["size"]:  # else HexLayer's default, the wall thickness
        command += ["--size", str(case["size"])]
    env = dict(os.environ, OMP_NUM_THREADS=str(args.threads))
    code, _, stderr, wall, peak = run_measured(command, args.timeout, env)
    result = {"exit_code": code, "wall_s": wall, "peak_mib": peak}
    if code != 0:
        result["error"] = stderr.strip()[-500:]
        return result
    with open(report) as f:
        r = json.load(f)
    result.update(hexes=r["hexes"], size=r["size"], layout=r["quad_mesh"]["layout"],
                  gmsh_tries=r["quad_mesh"].get("gmsh_tries"), timings_s=r["timings_s"],
                  peak_memory_mib=r.get("peak_memory_mib", {}),
                  sj_min=r["scaled_jacobian"]["min"],
                  sj_avg=r["scaled_jacobian"]["avg"], inverted=r["inverted_hexes"],
                  volume_error=r["volume"]["relative_error"], hexes_per_s=r["hexes"] / wall)
    if not args.keep_meshes:
        os.remove(mesh)
    return result


def run_gmsh_tets(args, case, size):
    command = [sys.executable, "-c", GMSH_TETS, case["step"], str(size)]
    code, stdout, stderr, wall, peak = run_measured(command, args.timeout)
    if code != 0:
        return {"exit_code": code, "wall_s": wall, "peak_mib": peak, "error": stderr.strip()[-500:]}
    faces, tets, mesh_s = stdout.split()[-3:]
    return {"exit_code": 0, "wall_s": wall, "peak_mib": peak, "faces": int(faces), "tets": int(tets),
            "generate_s": float(mesh_s), "size": size}


def cases(suite, parts):
    """The benchmark cases: name, STEP file, quad size, layers, expected hexes (for --no-gmsh-above)."""
    target = [dict(name="plate200_holes", step=parts["plate200_holes"], size=2.0, layers=2, hexes=12600)]
    scaling = []
    for name, (length, width) in SHEETS.items():
        hexes = round(2 * length * width / 1.5 ** 2)
        scaling.append(dict(name=name, step=parts[name], size=1.5, layers=2, hexes=hexes))
    samples = [dict(name=s, step=os.path.join(ROOT, "Resources", "samples", s + ".step"), size=size, layers=2, hexes=0)
               for s, size in (("plate_holes", 2.0), ("lbracket", 3.0), ("uchannel", 2.0), ("hat_holes", 1.5))]
    many = [dict(name=n, step=parts[n], size=None, layers=2, hexes=0) for n in MANY]
    if os.path.isdir(REAL):
        many += [dict(name=os.path.splitext(f)[0], step=os.path.join(REAL, f), size=None, layers=2, hexes=0)
                 for f in sorted(os.listdir(REAL)) if f.lower().endswith((".step", ".stp", ".brep"))]
    junctions = [dict(name=s, step=os.path.join(ROOT, "Resources", "samples", "junctions", s + ".step"), size=None,
                      layers=2, hexes=0) for s in JUNCTIONS]
    return {"target": target, "scaling": scaling, "samples": samples, "many": many, "junctions": junctions,
            "all": target + samples + scaling + many + junctions}[suite]


# The junction samples meshed all-hex (issue 18: walls standing on flat and curved walls, ribs crossing, filleted
# feet).
JUNCTIONS = ("plate_rib", "plate_rib_thin", "plate_rib_thick", "plate_rib_split", "plate_rib_inside", "plate_boss",
             "plate_ribs_tee", "shell_rib", "box_partition", "lbracket_gusset", "plate_rib_grid", "plate_rib_fillet",
             "box_rib_fillet", "plate_boss_gussets")
# Parts with many features (scripts/make_samples.py --only many) and the real parts.
MANY = ("keyboard_plate", "plate_200_holes", "perforated_tube")
REAL = os.path.join(os.path.dirname(ROOT), "shared", "parts", "real")


# 3 mm sheets meshed at 1.5 mm in 2 layers: about 1e3, 1e4, 1e5 and 1e6 hexes.
SHEETS = {"sheet_1e3": (45, 25), "sheet_1e4": (150, 75), "sheet_1e5": (475, 237), "sheet_1e6": (1500, 750)}


def make_parts(out_dir):
    parts = {"plate200_holes": os.path.join(out_dir, "plate200_holes.step")}
    if not os.path.exists(parts["plate200_holes"]):  # the 200 x 100 x 3 plate with four holes
        make_plate(parts["plate200_holes"], 200, 100, 3, [(30, 25, 6), (170, 25, 6), (30, 75, 6), (170, 75, 6)])
    for name, (length, width) in SHEETS.items():
        parts[name] = os.path.join(out_dir, name + ".step")
        if not os.path.exists(parts[name]):
            make_plate(parts[name], length, width, 3, [])
    for name in MANY:
        parts[name] = os.path.join(out_dir, "many", name + ".step")
    return parts


def make_many(out_dir):
    """The parts with many features, by scripts/make_samples.py (a minute: OpenCASCADE's booleans)."""
    if all(os.path.exists(os.path.join(out_dir, "many", n + ".step")) for n in MANY):
        return
    subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "make_samples.py"), out_dir, "--only", "many"],
                   check=True, stdout=subprocess.DEVNULL)


def median_run(runs):
    """The run whose wall time is the median (the lower middle one of an even count), with every run's wall time
    in `walls_s` (in the order they ran)."""
    middle = dict(sorted(runs, key=lambda r: r["wall_s"])[(len(runs) - 1) // 2])
    middle["walls_s"] = [r["wall_s"] for r in runs]
    return middle


def print_row(case, h, g):
    faces = f"{g['faces']:4d} faces  " if g and "faces" in g else ""
    if h["exit_code"] != 0:
        error = h.get("error", "").splitlines()[-1:] or [""]
        print(f"{case['name']:16s} {faces}hexlayer failed (exit {h['exit_code']}) after {h['wall_s']:.2f} s: "
              f"{error[0]}" + (f" | gmsh tets {g['tets']} {g['wall_s']:.2f} s" if g and g["exit_code"] == 0 else ""))
        return
    line = (f"{case['name']:16s} {faces}{h['hexes']:8d} hexes  {h['wall_s']:7.2f} s  {h['peak_mib']:7.0f} MiB  "
            f"{h['hexes_per_s']:9.0f} hex/s  SJ {h['sj_min']:.2f}/{h['sj_avg']:.3f}")
    if g and g["exit_code"] == 0 and g["tets"] == 0:  # a shell without a volume (Gmsh reads no solid)
        line += " | gmsh: no volume to mesh"
    elif g and g["exit_code"] == 0:
        line += (f" | gmsh tets {g['tets']:8d}  {g['wall_s']:7.2f} s  {g['peak_mib']:6.0f} MiB"
                 f" | ratio {h['wall_s'] / g['wall_s']:.2f}")
        if len(h.get("walls_s", [])) > 1:  # --repeat: the medians above, every run's times and ratio here
            runs = ", ".join(f"{a:.2f}/{b:.2f} s = {a / b:.2f}" for a, b in zip(h["walls_s"], g["walls_s"]))
            line += f" (medians of {len(h['walls_s'])}; runs {runs})"
    elif g:
        line += f" | gmsh failed (exit {g['exit_code']})"
    print(line)
    # Per stage: wall time, hexes per second of that stage, the process's peak memory at its end.
    memory = h.get("peak_memory_mib", {})
    stages = "  ".join(f"{k} {v:.2f} s {h['hexes'] / v if v > 0 else 0:.0f} hex/s {memory.get(k, 0):.0f} MiB"
                       for k, v in h["timings_s"].items())
    print(f"{'':16s} stages: {stages}")
    sys.stdout.flush()


def plot(results, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    ok = sorted((r for r in results if r["hexlayer"]["exit_code"] == 0), key=lambda r: r["hexlayer"]["hexes"])
    fig, ax = plt.subplots(figsize=(7, 4.5))
    hexes = [r["hexlayer"]["hexes"] for r in ok]
    ax.loglog(hexes, [r["hexlayer"]["wall_s"] for r in ok], "o-", label="HexLayer total (wall)")
    ax.loglog(hexes, [r["hexlayer"]["timings_s"].get("quad_mesh", 0) for r in ok], "s--",
              label="HexLayer quad_mesh stage (map, block grid, smoothing)")
    with_gmsh = [r for r in ok if r.get("gmsh") and r["gmsh"]["exit_code"] == 0]
    ax.loglog([r["hexlayer"]["hexes"] for r in with_gmsh], [r["gmsh"]["wall_s"] for r in with_gmsh], "^:",
              label="Gmsh 3D tet mesh, same part and size")
    if hexes:  # through the largest case: the smallest is mostly process start-up
        ax.loglog(hexes, [ok[-1]["hexlayer"]["wall_s"] * h / hexes[-1] for h in hexes], color="grey",
                  lw=0.8, label="O(n) through the largest case")
    finish_plot(fig, ax, "hexes", "HexLayer scaling: 3 mm sheets, 1.5 mm quads, 2 layers", 8, path)


def finish_plot(fig, ax, xlabel, title, legend_size, path):
    """Labels, grid and legend of a time plot, written to path."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel("wall time (s)")
    ax.set_title(title)
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=legend_size)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def plot_faces(results, path):
    """Wall time against the number of CAD faces (suite many): HexLayer's, its quad stage's, Gmsh's tet mesh's."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = sorted((r for r in results if r.get("gmsh") and "faces" in r["gmsh"]), key=lambda r: r["gmsh"]["faces"])
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for ok, marker, label in ((True, "o", "HexLayer total (wall)"), (False, "x", "HexLayer, failed or refused")):
        pick = [r for r in rows if (r["hexlayer"]["exit_code"] == 0) == ok]
        ax.semilogy([r["gmsh"]["faces"] for r in pick], [r["hexlayer"]["wall_s"] for r in pick], marker, ls="",
                    label=label)
    meshed = [r for r in rows if r["hexlayer"]["exit_code"] == 0]
    ax.semilogy([r["gmsh"]["faces"] for r in meshed], [r["hexlayer"]["timings_s"].get("quad_mesh", 0) for r in meshed],
                "s", mfc="none", ls="", label="HexLayer quad_mesh stage")
    tets = [r for r in rows if r["gmsh"]["exit_code"] == 0 and r["gmsh"]["tets"] > 0]
    ax.semilogy([r["gmsh"]["faces"] for r in tets], [r["gmsh"]["wall_s"] for r in tets], "^", ls="",
                label="Gmsh 3D tet mesh, same part and size")
    for r in rows:
        ax.annotate(r["case"]["name"][:18], (r["gmsh"]["faces"], r["hexlayer"]["wall_s"]), fontsize=6)
    ax.axhline(30, color="grey", lw=0.8, ls=":", label="30 s")
    finish_plot(fig, ax, "CAD faces", "HexLayer on parts with many features (2 layers, default size)", 7, path)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--hexlayer", default=os.path.join(ROOT, "build", "hexlayer"))
    p.add_argument("--suite", default="target", choices=["target", "scaling", "samples", "many", "junctions", "all"])
    p.add_argument("--only", help="run the cases whose name contains this")
    p.add_argument("--threads", type=int, default=os.cpu_count() or 1, help="OMP_NUM_THREADS for hexlayer")
    p.add_argument("--out", default=os.path.join(ROOT, "out", "bench"))
    p.add_argument("--plot", help="write a time vs hexes PNG here")
    p.add_argument("--no-gmsh-above", type=int, default=200000, help="skip Gmsh's tet mesh above this many hexes")
    p.add_argument("--timeout", type=float, default=3600)
    p.add_argument("--keep-meshes", action="store_true")
    p.add_argument("--max-hexes", type=int, default=0, help="skip cases above this many hexes (0: none)")
    p.add_argument("--repeat", type=int, default=1,
                   help="run HexLayer and Gmsh this many times each, alternately; report the median wall times")
    args = p.parse_args()
    if not os.access(args.hexlayer, os.X_OK):
        sys.exit(f"bench.py: no hexlayer executable at {args.hexlayer}; build first or pass --hexlayer")
    os.makedirs(args.out, exist_ok=True)
    parts = make_parts(args.out)
    if args.suite in ("many", "all"):
        make_many(args.out)
    results = []
    print(f"threads {args.threads}, cores {os.cpu_count()}, load average {os.getloadavg()[0]:.2f}")
    for case in cases(args.suite, parts):
        if args.only and args.only not in case["name"]:
            continue
        if args.max_hexes and case["hexes"] > args.max_hexes:
            print(f"{case['name']:16s} skipped (--max-hexes {args.max_hexes})")
            continue
        hs, gs = [], []
        for _ in range(max(1, args.repeat)):  # alternately, so that both meet the machine as it is then
            hs.append(run_hexlayer(args, case, args.out))
            size = case["size"] or hs[0].get("size") or 2.0  # Gmsh at the size HexLayer used
            if case["hexes"] <= args.no_gmsh_above:
                gs.append(run_gmsh_tets(args, case, size))
        h = median_run(hs)
        g = median_run(gs) if gs else None
        results.append({"case": case, "hexlayer": h, "gmsh": g})
        print_row(case, h, g)
    with open(os.path.join(args.out, f"results_{args.suite}.json"), "w") as f:
        json.dump(results, f, indent=1)
    if args.plot:
        (plot_faces if args.suite == "many" else plot)(results, args.plot)
        print("plot:", args.plot)


if __name__ == "__main__":
    main()
