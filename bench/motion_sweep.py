#!/usr/bin/python3
"""Where the kinetic engine beats the static rebuild: kinetic_bench over random walks of growing step.

The kinetic cost of a frame grows with the events between frames (how far cells move against their
spacing); the static rebuild's does not. This runs kinetic_bench on random walks of each size,
dimension and step, several times each (the machine's noise is larger than the differences between
neighbouring steps), and prints one Markdown row per case with the medians:

  events per cell and frame, kinetic and static milliseconds per frame, the ratio over the frames
  that rebuild every certificate (docs/MATH.md §2.3; below 1 the kinetic structure beats the static rebuild), and the lower bound for
  any engine of libkinetic's design (bench/lower_bound/delaunay_skeleton.h), when the skeleton completes: the
  skeleton plus an estimate of the radius certificates' arithmetic, and in the plane the skeleton
  with its alpha layer, measured (the fixed-radius alpha complex maintained, checked against CGAL's
  exact Alpha_shape_2 at the end).

Usage: bench/motion_sweep.py [--bench build/bench/kinetic_bench] [--repeat 3]
                             [--dims 3,2] [--cells 1000,10000] [--steps 0.01,0.03,0.1,0.3,0.7]
"""
import argparse
import re
import statistics
import subprocess
import sys

HEADER = re.compile(r"^== .*\((\d)D\): (\d+) cells, (\d+) frames")
MEAN = re.compile(r"^mean per frame: kinetic ([\d.]+) ms, static ([\d.]+) ms")
REBUILD = re.compile(r"^frames 1\.\.\d+ \(each with its certificate rebuild.*ratio ([\d.]+)")
EVENTS = re.compile(r"^kinetic total .* events (\d+) ")
BOUND = re.compile(r"^lower bound for the kinetic alpha complex: .*: ([\d.]+) of the static rebuilds")
ALPHA = re.compile(r"^alpha skeleton .*?: [\d.]+ ms per slab \(frame rebuilds [\d.]+ of it\), ([\d.]+) of the "
                   r"static rebuilds")


def run_once(bench, dim, cells, step):
    out = subprocess.run([bench, "--random", str(cells), "--dim", str(dim), "--step", str(step)],
                         check=True, capture_output=True, text=True).stdout
    row = {"bound": None, "alpha": None}
    for line in out.splitlines():
        if m := HEADER.match(line):
            row["slabs"] = int(m.group(3)) - 1
        elif m := MEAN.match(line):
            row["kinetic"], row["static"] = float(m.group(1)), float(m.group(2))
        elif m := REBUILD.match(line):
            row["ratio"] = float(m.group(1))
        elif m := EVENTS.match(line):
            row["events"] = int(m.group(1))
        elif m := BOUND.match(line):
            row["bound"] = float(m.group(1))
        elif m := ALPHA.match(line):
            row["alpha"] = float(m.group(1))
    missing = {"slabs", "kinetic", "static", "ratio", "events"} - row.keys()
    if missing:
        sys.exit(f"motion_sweep: kinetic_bench --random {cells} --dim {dim} --step {step}: "
                 f"no {', '.join(sorted(missing))} in its output")
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--bench", default="build/bench/kinetic_bench")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--dims", default="3,2")
    parser.add_argument("--cells", default="1000,10000")
    parser.add_argument("--steps", default="0.01,0.03,0.1,0.3,0.7")
    args = parser.parse_args()
    print("| dim | cells | step | events per cell and frame | kinetic ms/frame | static ms/frame "
          "| ratio, frames with a rebuild | lower bound (estimated) | alpha skeleton (2D, measured) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for dim in (int(d) for d in args.dims.split(",")):
        for cells in (int(c) for c in args.cells.split(",")):
            for step in args.steps.split(","):
                runs = []
                for r in range(args.repeat):
                    print(f"motion_sweep: {dim}D, {cells} cells, step {step}, run {r + 1} of {args.repeat}",
                          file=sys.stderr)
                    runs.append(run_once(args.bench, dim, cells, step))
                med = {k: statistics.median(x[k] for x in runs) for k in ("kinetic", "static", "ratio")}
                bounds = [x["bound"] for x in runs if x["bound"] is not None]
                bound = f"{statistics.median(bounds):.2f}" if bounds else "- (skeleton stopped)"
                alphas = [x["alpha"] for x in runs if x["alpha"] is not None]
                alpha = f"{statistics.median(alphas):.2f}" if alphas else ("- (stopped)" if dim == 2 else "-")
                per_cell = runs[0]["events"] / (cells * runs[0]["slabs"])
                print(f"| {dim}D | {cells:,} | {step} | {per_cell:.2f} | {med['kinetic']:.2f} | "
                      f"{med['static']:.2f} | **{med['ratio']:.2f}** | {bound} | {alpha} |", flush=True)


if __name__ == "__main__":
    main()
