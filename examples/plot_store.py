#!/usr/bin/python3
"""Plot the barcodes and Betti curves of a medusa store as PNG files.

usage: plot_store.py run.h5 [--diagrams run.diagrams.csv] [--medusa path/to/medusa] [-o prefix]

The store (docs/FORMAT.md) gives the run's frame times, cell types and radius; the persistence pairs
are not stored in it, so they come from the `<stem>.diagrams.csv` that `medusa run` writes next to the
store, or, when that file is missing, from `medusa barcode --format csv` (give --medusa if `medusa` is
not on the PATH). Writes, as `medusa run` draws its SVGs, one panel per cell type and filtration
direction (rows) and homology degree (columns), each with its own time axis:
<prefix>.barcodes.png (the finite classes as bars sorted by birth; the classes that never die counted in
the titles), <prefix>.diagram.png (the same as persistence diagrams: points (birth, death) above the
diagonal), and <prefix>.betti.png (Betti curves of the forward and reverse filtrations, docs/MATH.md
§7.8: beta_k(s) = #{(b, d): b <= s < d}, reverse diagrams on the -t axis plotted back on t; one panel
per type and degree). The prefix defaults to the store's name without .h5.
"""
import argparse
import csv
import math
import os
import shutil
import subprocess
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (the backend must be chosen first)
from matplotlib.collections import LineCollection  # noqa: E402
import numpy as np  # noqa: E402

COLOURS = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd"]


def text(value):
    return value.decode("utf-8") if isinstance(value, bytes) else str(value)


def read_store(path):
    """Run facts from the store's root attributes and /input (docs/FORMAT.md)."""
    with h5py.File(path, "r") as f:
        if text(f.attrs.get("format", b"")) != "medusa-store" or int(f.attrs.get("complete", 0)) != 1:
            raise SystemExit(f"plot_store.py: {path} is not a complete medusa store")
        frame_times = f["input/frame_times"][:]
        types = f["input/cell_type"][:]
        names = [text(n) for n in f["input"].attrs.get("type_names", [])]
        return {
            "t0": float(frame_times[0]),
            "t_end": float(frame_times[-1]),
            "frames": len(frame_times),
            "radius": text(f.attrs.get("radius_text", b"")) or str(float(f.attrs["radius"])),
            "type_counts": {int(t): int(np.sum(types == t)) for t in np.unique(types)},
            "type_names": names,
            "run_id": text(f.attrs.get("run_id", b"")),
        }


def read_pairs(store, diagrams, medusa, run_id=""):
    """Rows of the diagrams CSV (birth,death,dimension,type,direction,type_name) as dicts with float times.

    The CSV's first line `# medusa run <id>` must name the store's run id (docs/FORMAT.md): a CSV from
    another run is refused (exit 5), as medusa refuses a store error."""
    if diagrams is None:
        stem = store[:-3] if store.endswith(".h5") else store
        if os.path.exists(stem + ".diagrams.csv"):
            diagrams = stem + ".diagrams.csv"
    if diagrams is not None:
        with open(diagrams, newline="") as f:
            content = f.read()
        first = content.split("\n", 1)[0]
        stamped = first[len("# medusa run "):] if first.startswith("# medusa run ") else ""
        if run_id and stamped != run_id:
            sys.stderr.write(f"plot_store.py: {diagrams} comes from another run than {store} "
                             f"(run id {stamped or 'none'}, the store's is {run_id})\n")
            sys.exit(5)
    else:
        program = medusa or shutil.which("medusa")
        if program is None:
            raise SystemExit("plot_store.py: no <stem>.diagrams.csv next to the store and no medusa program (--medusa)")
        result = subprocess.run([program, "barcode", store, "--format", "csv"], capture_output=True, text=True)
        if result.returncode != 0:
            raise SystemExit(f"plot_store.py: medusa barcode failed: {result.stderr.strip()}")
        content = result.stdout
    rows = []
    lines = [line for line in content.splitlines() if not line.startswith("#")]
    for r in csv.DictReader(lines):
        rows.append({"birth": float(r["birth"]), "death": float(r["death"]), "dim": int(r["dimension"]),
                     "type": r["type"], "direction": r["direction"]})
    return rows


def type_title(label, info):
    if label == "all":
        return "all cells"
    t = int(label)
    name = info["type_names"][t] if t < len(info["type_names"]) and info["type_names"][t] else f"type {t}"
    return f"{name} (type {t}, {info['type_counts'].get(t, 0)} cells)"


def groups(rows):
    """(type, direction) in the order of the CSV."""
    seen = []
    for r in rows:
        key = (r["type"], r["direction"])
        if key not in seen:
            seen.append(key)
    return seen


DEGREE_NAMES = ["H0 clusters", "H1 loops", "H2 cavities", "H3 4D bubbles"]


def degrees_of(rows):
    """Degrees with a class in some diagram; H3 only with a finite class (forward H3 classes are all
    essential, docs/MATH.md §7.6)."""
    shown = {r["dim"] for r in rows if r["dim"] < 3 or not math.isinf(r["death"])}
    return sorted(k for k in shown if k <= 3) or [0]


def panel_range(finite, info):
    """The whole run, or the range of the panel's classes when they lie within a third of it (the type-1
    clusters of a sorting run join within the first tens of MCS of thousands)."""
    t0, t_end = info["t0"], info["t_end"]
    if not finite:
        return t0, t_end
    lo = max(t0, min(min(b, d) for b, d in finite))
    hi = min(t_end, max(max(b, d) for b, d in finite))
    if hi - lo >= (t_end - t0) / 3:
        return t0, t_end
    step = 10 ** math.floor(math.log10(max(hi - lo, 1e-9) / 5))
    step = next(f * step for f in (1, 2, 5, 10) if f * step >= (hi - lo) / 5)
    return max(t0, math.floor(lo / step) * step), min(t_end, max(math.ceil(hi / step) * step, lo + step))


def counts_title(label, direction, k, finite, essential, info):
    if direction == "forward" and k == 0:
        words = ("joined", "never joined")
    elif direction == "forward" and k <= 2:
        words = ("filled", "never filled")
    else:
        words = ("finite", "essential")
    return (f"{type_title(label, info)}, {direction}, {DEGREE_NAMES[k]}\n"
            f"{len(finite)} {words[0]}, {essential} {words[1]}" + (" (counted, not drawn)" if essential else ""))


def panels(rows, info):
    """One panel per (type, direction) and degree: its finite (birth, death) pairs, sorted by birth, and
    its number of essential classes."""
    keys, degrees = groups(rows), degrees_of(rows)
    grid = []
    for label, direction in keys:
        line = []
        for k in degrees:
            mine = [r for r in rows if r["type"] == label and r["direction"] == direction and r["dim"] == k]
            finite = sorted(((r["birth"], r["death"]) for r in mine if not math.isinf(r["death"])),
                            key=lambda p: (min(p), max(p)))
            line.append((label, direction, k, finite, len(mine) - len(finite)))
        grid.append(line)
    return grid, degrees


def figure_of(grid, degrees, height):
    fig, axes = plt.subplots(len(grid), len(degrees), figsize=(4.2 * len(degrees), height * len(grid)),
                             squeeze=False)
    handles = [plt.Line2D([], [], color=COLOURS[k], linewidth=4, label=DEGREE_NAMES[k]) for k in degrees]
    fig.legend(handles=handles, loc="upper right", ncol=len(degrees), fontsize=8)
    return fig, axes


def plot_barcodes(rows, info, path):
    """Barcodes: one panel per diagram and degree with its own time axis; the finite classes as bars from
    birth to death, sorted by birth; the essential classes counted in the title."""
    grid, degrees = panels(rows, info)
    fig, axes = figure_of(grid, degrees, 2.6)
    for i, line in enumerate(grid):
        for j, (label, direction, k, finite, essential) in enumerate(line):
            ax = axes[i, j]
            if finite:
                segments = [[(min(b, d), y), (max(b, d), y)] for y, (b, d) in enumerate(finite)]
                width = max(0.3, min(3.0, 200.0 / len(finite)))
                ax.add_collection(LineCollection(segments, colors=COLOURS[k], linewidths=width))
                ax.set_ylim(len(finite), -1)
            else:
                ax.text(0.02, 0.9, "no finite class", transform=ax.transAxes, fontsize=8, color="#888")
            ax.set_xlim(*panel_range(finite, info))
            ax.set_yticks([])
            ax.set_xlabel("MCS", fontsize=8)
            ax.tick_params(labelsize=7)
            ax.set_title(counts_title(label, direction, k, finite, essential, info), fontsize=8, loc="left")
    fig.suptitle(f"barcodes, radius {info['radius']}: finite classes sorted by birth", fontsize=10, x=0.25)
    fig.tight_layout(rect=(0, 0, 1, 1 - 0.5 / fig.get_figheight()))
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_diagrams(rows, info, path):
    """Persistence diagrams: each finite class a point (birth, death), the diagonal dashed."""
    grid, degrees = panels(rows, info)
    fig, axes = figure_of(grid, degrees, 3.4)
    for i, line in enumerate(grid):
        for j, (label, direction, k, finite, essential) in enumerate(line):
            ax = axes[i, j]
            lo, hi = panel_range(finite, info)
            ax.plot([lo, hi], [lo, hi], linestyle="--", color="#888", linewidth=0.8)
            if finite:
                ax.scatter([b for b, d in finite], [d for b, d in finite], s=6, color=COLOURS[k], alpha=0.55,
                           clip_on=False)
            ax.set_xlim(lo, hi)
            ax.set_ylim(lo, hi)
            ax.set_aspect("equal")
            ax.set_xlabel("birth (MCS)", fontsize=8)
            ax.set_ylabel("death (MCS)", fontsize=8)
            ax.tick_params(labelsize=7)
            ax.set_title(counts_title(label, direction, k, finite, essential, info), fontsize=8, loc="left")
    fig.suptitle(f"persistence diagrams, radius {info['radius']}", fontsize=10, x=0.25)
    fig.tight_layout(rect=(0, 0, 1, 1 - 0.5 / fig.get_figheight()))
    fig.savefig(path, dpi=110)
    plt.close(fig)


def betti_curve(rows, k, direction, times):
    """beta_k on the time axis: forward b <= s < d; reverse on -t, i.e. d < s <= b in t (docs/MATH.md §7.3, §7.8)."""
    pairs = [(r["birth"], r["death"]) for r in rows if r["dim"] == k]
    if direction == "forward":
        return [sum(1 for b, d in pairs if b <= s < d) for s in times]
    return [sum(1 for b, d in pairs if d < s <= b) for s in times]


def plot_betti(rows, info, path):
    """Betti curves of the time filtrations, one panel per type and degree, each with its own range."""
    keys = groups(rows)
    labels = sorted({k[0] for k in keys}, key=lambda x: (x != "all", x))
    degrees = [k for k in degrees_of(rows) if k <= 2]
    times = np.linspace(info["t0"], info["t_end"], 400)
    fig, axes = plt.subplots(len(labels), len(degrees), figsize=(4.2 * len(degrees), 2.5 * len(labels)),
                             squeeze=False)
    for i, label in enumerate(labels):
        for j, k in enumerate(degrees):
            ax = axes[i, j]
            for direction, style in (("forward", "-"), ("reverse", "--")):
                mine = [r for r in rows if r["type"] == label and r["direction"] == direction]
                ax.step(times, betti_curve(mine, k, direction, times), where="post", color=COLOURS[k],
                        linestyle=style, label=direction)
            ax.set_xlim(info["t0"], info["t_end"])
            ax.set_ylim(bottom=0)
            ax.tick_params(labelsize=7)
            ax.set_title(f"{type_title(label, info)}, beta_{k} ({DEGREE_NAMES[k]})", fontsize=8, loc="left")
            if i == len(labels) - 1:
                ax.set_xlabel("MCS", fontsize=8)
    axes[0, 0].legend(fontsize=7)
    fig.suptitle("Betti curves of the time filtrations (forward: rank H_k(M_<=s); reverse: rank H_k(M_>=s))",
                 fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 1 - 0.4 / fig.get_figheight()))
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("store")
    parser.add_argument("--diagrams", help="diagrams CSV (default: <stem>.diagrams.csv, else medusa barcode)")
    parser.add_argument("--medusa", help="the medusa program (default: medusa on the PATH)")
    parser.add_argument("-o", "--output", help="output prefix (default: the store name without .h5)")
    args = parser.parse_args()
    info = read_store(args.store)
    rows = read_pairs(args.store, args.diagrams, args.medusa, info["run_id"])
    if not rows:
        raise SystemExit("plot_store.py: the diagrams are empty")
    prefix = args.output or (args.store[:-3] if args.store.endswith(".h5") else args.store)
    for suffix, plot in ((".barcodes.png", plot_barcodes), (".diagram.png", plot_diagrams),
                         (".betti.png", plot_betti)):
        tmp = f"{prefix}{suffix}.tmp-{os.getpid()}.png"
        plot(rows, info, tmp)
        os.replace(tmp, prefix + suffix)
        print(f"wrote {prefix}{suffix}")


if __name__ == "__main__":
    sys.exit(main())
