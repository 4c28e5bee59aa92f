#!/usr/bin/python3
"""Plot the barcodes and Betti curves of a medusa store as PNG files.

usage: plot_store.py run.h5 [--diagrams run.diagrams.csv] [--medusa path/to/medusa] [-o prefix]

The store (docs/FORMAT.md) gives the run's frame times, cell types and radius; the persistence pairs
are not stored in it, so they come from the `<stem>.diagrams.csv` that `medusa run` writes next to the
store, or, when that file is missing, from `medusa barcode --format csv` (give --medusa if `medusa` is
not on the PATH). Writes <prefix>.barcodes.png (one panel per cell type and filtration direction, bars
coloured by homology degree) and <prefix>.betti.png (Betti curves of the forward and reverse
filtrations, docs/MATH.md §7.8: beta_k(s) = #{(b, d): b <= s < d}, reverse diagrams on the -t axis plotted
back on t). The prefix defaults to the store's name without .h5.
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
    """Rows of the diagrams CSV (birth,death,dimension,type,direction) as dicts with float times.

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


def plot_barcodes(rows, info, path):
    keys = groups(rows)
    fig, axes = plt.subplots(len(keys), 1, figsize=(9, 0.6 + 2.4 * len(keys)), squeeze=False)
    for ax, (label, direction) in zip(axes[:, 0], keys):
        bars = sorted((r for r in rows if r["type"] == label and r["direction"] == direction),
                      key=lambda r: (r["dim"], min(r["birth"], r["death"])))
        width = max(0.3, min(2.0, 150.0 / max(len(bars), 1)))
        for y, r in enumerate(bars):
            # Essential classes run to the end of the axis in the direction of the filtration.
            end = r["death"]
            if math.isinf(end):
                end = info["t_end"] if end > 0 else info["t0"]
            ax.plot([r["birth"], end], [y, y], color=COLOURS[min(r["dim"], 3)], linewidth=width,
                    solid_capstyle="butt")
            if math.isinf(r["death"]):
                ax.plot([end], [y], marker=">" if r["death"] > 0 else "<", color=COLOURS[min(r["dim"], 3)],
                        markersize=4)
        ax.set_xlim(info["t0"], info["t_end"])
        ax.set_ylim(-1, max(len(bars), 1))
        ax.set_yticks([])
        ax.set_title(f"{type_title(label, info)}, {direction} filtration ({len(bars)} bars)", fontsize=9)
    axes[-1, 0].set_xlabel("MCS")
    handles = [plt.Line2D([], [], color=COLOURS[k], label=f"H{k}") for k in range(3)]
    fig.legend(handles=handles, loc="upper right", ncol=3, fontsize=8)
    fig.suptitle(f"barcodes, radius {info['radius']}", fontsize=10, x=0.3)
    fig.tight_layout(rect=(0, 0, 1, 1 - 0.4 / fig.get_figheight()))
    fig.savefig(path, dpi=120)
    plt.close(fig)


def betti_curve(rows, k, direction, times):
    """beta_k on the time axis: forward b <= s < d; reverse on -t, i.e. d < s <= b in t (docs/MATH.md §7.3, §7.8)."""
    pairs = [(r["birth"], r["death"]) for r in rows if r["dim"] == k]
    if direction == "forward":
        return [sum(1 for b, d in pairs if b <= s < d) for s in times]
    return [sum(1 for b, d in pairs if d < s <= b) for s in times]


def plot_betti(rows, info, path):
    keys = groups(rows)
    labels = sorted({k[0] for k in keys}, key=lambda x: (x != "all", x))
    directions = ["forward", "reverse"]
    times = np.linspace(info["t0"], info["t_end"], 400)
    fig, axes = plt.subplots(len(labels), 2, figsize=(10, 2.6 * len(labels)), squeeze=False)
    for i, label in enumerate(labels):
        for j, direction in enumerate(directions):
            ax = axes[i, j]
            mine = [r for r in rows if r["type"] == label and r["direction"] == direction]
            for k in range(3):
                ax.step(times, betti_curve(mine, k, direction, times), where="post", color=COLOURS[k], label=f"beta_{k}")
            ax.set_xlim(info["t0"], info["t_end"])
            ax.set_title(f"{type_title(label, info)}, {direction}", fontsize=9)
            if i == len(labels) - 1:
                ax.set_xlabel("MCS")
    axes[0, 0].legend(fontsize=8)
    fig.suptitle("Betti curves of the time filtrations (forward: rank H_k(M_<=s); reverse: rank H_k(M_>=s))",
                 fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 1 - 0.4 / fig.get_figheight()))
    fig.savefig(path, dpi=120)
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
    for suffix, plot in ((".barcodes.png", plot_barcodes), (".betti.png", plot_betti)):
        tmp = f"{prefix}{suffix}.tmp-{os.getpid()}.png"
        plot(rows, info, tmp)
        os.replace(tmp, prefix + suffix)
        print(f"wrote {prefix}{suffix}")


if __name__ == "__main__":
    sys.exit(main())
