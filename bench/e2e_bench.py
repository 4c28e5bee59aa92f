#!/usr/bin/python3
"""End-to-end benchmark of `medusa run`: wall time, CPU time and peak memory per stage.

Runs `medusa run --timings` on
  * large_3d:  the CompuCell3D run in bench/data/large_3d (4,945 cells, 11 frames), and its first
               --flatness-frames frames (default 6) to check that peak memory is flat in the frames;
  * random20k: a synthetic random walk (bench/make_random_walk.py; --cells, default 20,000, over
               --synthetic-frames, default 10; seed printed),
and, on the same frames, GUDHI's static alpha complex at the same radius plus its persistence, per
frame (gudhi.AlphaComplex(points, precision='exact' / 'fast').create_simplex_tree(max_alpha_square =
rho^2: GUDHI's alpha filtration value is the squared radius), then persistence()). It prints one table
with, per run: wall and CPU seconds per stage (reading, kinetic, medusa store, filtrations,
reduction, exports), peak RSS, kinetic events and events per second, the store's size, GUDHI's total
times and the ratios of medusa's end-to-end time to them; then the targets (large_3d end to end
within 120 s on 2 cores and 2 GiB, peak memory within 10% from 6 to 11 frames).

Subsets for quick runs: --frames N keeps the first N frames of every run; --cells N shrinks the
synthetic run. Example (a few minutes today):
  /usr/bin/python3 bench/e2e_bench.py --frames 2 --cells 2000 --flatness-frames 0
Run with /usr/bin/python3 (python3-gudhi). The medusa binary defaults to build/pipeline/cli/medusa.
"""
import argparse
import csv
import gzip
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
LARGE_3D = os.path.join(HERE, "data", "large_3d", "cells.csv.gz")
STAGES = ["reading", "kinetic", "medusa_store", "filtrations", "reduction", "exports"]


def read_frames(path):
    """{mcs: [row, ...]}: the CSV rows (dicts) of each frame, in file order."""
    frames = {}
    with gzip.open(path, "rt", newline="") as f:
        reader = csv.DictReader(f)
        for row in reader:
            frames.setdefault(int(row["mcs"]), []).append(row)
    return frames


def write_subset(source, target, count):
    """The rows of the first `count` frames (by MCS) of a CC3D cells CSV, unchanged."""
    with gzip.open(source, "rt", newline="") as f:
        header = f.readline()
        lines = f.readlines()
    keep = sorted({int(line.split(",", 1)[0]) for line in lines})[:count]
    wanted = set(keep)
    with gzip.open(target, "wt", newline="") as out:
        out.write(header)
        out.writelines(line for line in lines if int(line.split(",", 1)[0]) in wanted)
    return len(keep)


def run_medusa(args, name, data, work):
    store = os.path.join(work, name + ".h5")
    timings = os.path.join(work, name + ".timings.json")
    command = [args.medusa, "run", "--force", data, "-o", store, "--timings", timings, "--quiet", "--radius", args.radius,
               "--threads", str(args.threads)]
    print(f"[{name}] {' '.join(command)}", file=sys.stderr, flush=True)
    start = time.monotonic()
    result = subprocess.run(command, capture_output=True, text=True, timeout=args.timeout)
    wall = time.monotonic() - start
    if result.returncode != 0:
        sys.exit(f"[{name}] medusa run failed ({result.returncode}): {result.stderr.strip()}")
    with open(timings) as f:
        t = json.load(f)
    t["process_wall_seconds"] = wall
    print(f"[{name}] {wall:.1f} s wall, peak RSS {t['peak_rss_bytes'] / 2**20:.0f} MiB", file=sys.stderr, flush=True)
    return t


def gudhi_baseline(data, radius, precision):
    """Seconds of GUDHI's static alpha complex (up to rho^2) plus persistence, summed over the frames."""
    import gudhi

    rho2 = float(radius) ** 2
    total, cpu, simplices = 0.0, 0.0, 0
    for mcs, rows in sorted(read_frames(data).items()):
        points = [[float(r["xCOM"]), float(r["yCOM"]), float(r["zCOM"])] for r in rows]
        start, start_cpu = time.perf_counter(), time.process_time()
        tree = gudhi.AlphaComplex(points=points, precision=precision).create_simplex_tree(max_alpha_square=rho2)
        tree.persistence()
        total += time.perf_counter() - start
        cpu += time.process_time() - start_cpu
        simplices += tree.num_simplices()
    return {"seconds": total, "cpu_seconds": cpu, "simplices": simplices}


def mib(n):
    return f"{n / 2**20:.0f} MiB"


def peak_stage(m):
    """The first stage after which the process had reached its peak RSS."""
    after = m.get("peak_rss_bytes_after_stage")
    if not after:
        return "-"
    return next((s for s in STAGES if after[s] >= m["peak_rss_bytes"]), "-")


def frame_rss(m):
    """Peak RSS when the first and the last frame were reached (flat in frames: the two are close)."""
    at = m.get("peak_rss_bytes_at_frame")
    return f"{mib(at[0])} / {mib(at[-1])}" if at else "-"


def table(results):
    names = list(results)
    rows = [("cells", lambda r: str(r["medusa"]["cells"])), ("frames", lambda r: str(r["medusa"]["frames"])),
            ("radius", lambda r: r["medusa"]["radius"]), ("threads", lambda r: str(r["medusa"]["threads"]))]
    for stage in STAGES:
        rows.append((f"{stage} s (wall / cpu)",
                     lambda r, s=stage: f"{r['medusa']['stage_seconds'][s]:.2f} / {r['medusa']['stage_cpu_seconds'][s]:.2f}"))
    rows += [
        ("total s (wall / cpu)", lambda r: f"{r['medusa']['total_seconds']:.2f} / {r['medusa']['total_cpu_seconds']:.2f}"),
        ("process wall s", lambda r: f"{r['medusa']['process_wall_seconds']:.2f}"),
        ("peak RSS", lambda r: mib(r["medusa"]["peak_rss_bytes"])),
        ("peak RSS after kinetic", lambda r: mib(r["medusa"].get("peak_rss_bytes_after_stage", {}).get("kinetic", 0))),
        ("peak RSS reached in", lambda r: peak_stage(r["medusa"])),
        ("peak RSS at frame 1 / K", lambda r: frame_rss(r["medusa"])),
        ("kinetic events", lambda r: str(r["medusa"]["events"])),
        ("events/s (kinetic wall)", lambda r: f"{r['medusa']['events_per_second']:.0f}"),
        ("store size", lambda r: f"{r['medusa']['store']['bytes'] / 2**20:.1f} MiB"),
        ("store cells", lambda r: str(r["medusa"]["store"]["cells"])),
    ]
    def gudhi_row(r, p):
        g = r.get("gudhi", {}).get(p)
        return f"{g['seconds']:.2f} / {g['cpu_seconds']:.2f}" if g else "-"

    def ratio_row(r, p):
        g = r.get("gudhi", {}).get(p)
        if not g or g["seconds"] <= 0 or g["cpu_seconds"] <= 0:
            return "-"
        m = r["medusa"]
        return f"{m['process_wall_seconds'] / g['seconds']:.1f}x / {m['total_cpu_seconds'] / g['cpu_seconds']:.1f}x"

    for precision in ("exact", "fast"):
        rows.append((f"GUDHI {precision} s (wall / cpu)", lambda r, p=precision: gudhi_row(r, p)))
        rows.append((f"medusa / GUDHI {precision} (wall / cpu)", lambda r, p=precision: ratio_row(r, p)))
    rows.append(("GUDHI simplices (all frames)",
                 lambda r: str(r["gudhi"]["exact"]["simplices"]) if "exact" in r.get("gudhi", {}) else "-"))
    width = max(len(label) for label, _ in rows)
    widths = [max(len(n), max(len(f(results[n])) for _, f in rows)) for n in names]
    lines = ["  ".join([" " * width] + [n.rjust(w) for n, w in zip(names, widths)])]
    for label, f in rows:
        lines.append("  ".join([label.ljust(width)] + [f(results[n]).rjust(w) for n, w in zip(names, widths)]))
    return "\n".join(lines)


def targets(results, large_frames, flat_name):
    lines = []
    full = "large_3d" in results and large_frames == 11
    if full:
        m = results["large_3d"]["medusa"]
        lines.append(f"large_3d end to end {m['process_wall_seconds']:.1f} s (target <= 120 s on 2 cores): "
                     + ("met" if m["process_wall_seconds"] <= 120 else "NOT met"))
        lines.append(f"large_3d peak RSS {mib(m['peak_rss_bytes'])} (target <= 2048 MiB): "
                     + ("met" if m["peak_rss_bytes"] <= 2 * 2**30 else "NOT met"))
    else:
        lines.append("large_3d time and memory targets: not measured (needs all 11 frames)")
    if flat_name in results and "large_3d" in results:
        a = results[flat_name]["medusa"]
        b = results["large_3d"]["medusa"]
        change = (b["peak_rss_bytes"] - a["peak_rss_bytes"]) / a["peak_rss_bytes"]
        verdict = "met" if abs(change) < 0.10 else "NOT met"
        if not full or a["frames"] != 6:
            verdict += f" (on {a['frames']} vs {b['frames']} frames, not the target's 6 vs 11)"
        lines.append(f"peak RSS flat in frames: {mib(a['peak_rss_bytes'])} at {a['frames']} frames, "
                     f"{mib(b['peak_rss_bytes'])} at {b['frames']} frames, {100 * change:+.1f}% (target < 10%): {verdict}")
    synthetic = [n for n in results if n.startswith("random")]
    for n in synthetic:
        m = results[n]["medusa"]
        lines.append(f"{n}: completed, {m['cells']} cells x {m['frames']} frames in {m['process_wall_seconds']:.1f} s")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--medusa", default=os.path.join(ROOT, "build", "pipeline", "cli", "medusa"))
    parser.add_argument("--runs", default="large_3d,random20k", help="comma-separated: large_3d, random20k")
    parser.add_argument("--frames", type=int, default=None, help="keep only the first N frames of every run")
    parser.add_argument("--cells", type=int, default=20000, help="cells of the synthetic run")
    parser.add_argument("--synthetic-frames", type=int, default=10)
    parser.add_argument("--seed", type=int, default=20261122, help="seed of the synthetic run")
    parser.add_argument("--flatness-frames", type=int, default=6,
                        help="also run large_3d on its first N frames for the memory-flatness check (0: skip)")
    parser.add_argument("--radius", default="auto", help="passed to medusa run; GUDHI uses the radius medusa used")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--skip-gudhi", action="store_true")
    parser.add_argument("--timeout", type=float, default=None, help="seconds allowed per medusa run")
    parser.add_argument("--work", default=None, help="folder for stores and inputs (default: a temporary one)")
    parser.add_argument("--json", default=None, help="also write every figure to this JSON file")
    args = parser.parse_args()
    if not os.access(args.medusa, os.X_OK):
        sys.exit(f"e2e_bench.py: no medusa binary at {args.medusa} (build it, or pass --medusa)")
    work = args.work or tempfile.mkdtemp(prefix="medusa_e2e_")
    os.makedirs(work, exist_ok=True)
    print(f"e2e_bench.py: work folder {work}", file=sys.stderr)

    inputs = []  # (name, csv path)
    large_frames = None
    flat_name = None
    for run in args.runs.split(","):
        if run == "large_3d":
            large_frames = min(11, args.frames or 11)
            path = LARGE_3D
            if large_frames < 11:
                path = os.path.join(work, f"large_3d_{large_frames}frames.csv.gz")
                write_subset(LARGE_3D, path, large_frames)
            inputs.append(("large_3d", path))
            if 0 < args.flatness_frames < large_frames:
                flat_name = f"large_3d_{args.flatness_frames}f"
                flat_path = os.path.join(work, f"large_3d_{args.flatness_frames}frames.csv.gz")
                write_subset(LARGE_3D, flat_path, args.flatness_frames)
                inputs.append((flat_name, flat_path))
        elif run == "random20k":
            frames = min(args.synthetic_frames, args.frames or args.synthetic_frames)
            name = "random20k" if args.cells == 20000 else f"random{args.cells}"
            path = os.path.join(work, f"{name}_{frames}frames.csv.gz")
            subprocess.run([sys.executable, os.path.join(HERE, "make_random_walk.py"), path, "--cells",
                            str(args.cells), "--frames", str(frames), "--seed", str(args.seed)], check=True)
            inputs.append((name, path))
        else:
            sys.exit(f"e2e_bench.py: unknown run {run!r} (large_3d, random20k)")

    results = {}
    for name, path in inputs:
        results[name] = {"input": path, "medusa": run_medusa(args, name, path, work)}
        if not args.skip_gudhi:
            results[name]["gudhi"] = {}
            for precision in ("exact", "fast"):
                print(f"[{name}] GUDHI precision={precision}", file=sys.stderr, flush=True)
                results[name]["gudhi"][precision] = gudhi_baseline(path, results[name]["medusa"]["radius"], precision)

    print(table(results))
    print("(cpu: process CPU seconds, all threads; the builder's CPU time during the kinetic stage is counted in\n"
          " kinetic's, so medusa_store's cpu covers closing and reading back the store only. Peak RSS is VmHWM of\n"
          " the medusa process. GUDHI times are summed over the same frames, in this Python process. Wall ratios use\n"
          " medusa's process wall time, cpu ratios its total CPU time.)")
    print()
    print(targets(results, large_frames, flat_name))
    if args.json:
        with open(args.json, "w") as f:
            json.dump(results, f, indent=1)


if __name__ == "__main__":
    main()
