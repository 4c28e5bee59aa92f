"""End-to-end checks on three full 21-frame CompuCell3D runs (run with /usr/bin/python3): what the
persistence of the type-1 (Condensing) sub-medusa says about cell sorting.

usage: check_sorting_signals.py merges <medusa> <workdir>    claim (a): type-1 clusters merge, earlier when sorting
       check_sorting_signals.py seeds <medusa> <workdir>     claim (b): two sorting seeds are closer than sorting/control
The stores sorting_3d.h5, sorting_3d_seed2.h5 and nosorting_3d.h5 (radius 3) are in <workdir>.
Values measured when the test was written (radius 3, forward filtration of the type-1 sub-medusa, H0):
  run               H0 classes alive at MCS 0 -> at MCS 2000   median death (MCS)
  sorting_3d        7 -> 1                                     41.0
  sorting_3d_seed2  5 -> 1                                     47.3
  nosorting_3d      7 -> 2                                     96.9
"""
import csv
import io
import math
import statistics
import subprocess
import sys

if not __debug__:
    sys.exit("these checks are assert statements: run without -O and without PYTHONOPTIMIZE")

SORTING = ["sorting_3d", "sorting_3d_seed2"]
CONTROL = "nosorting_3d"


def run(args, cwd):
    print("$", " ".join(args))
    result = subprocess.run(args, cwd=cwd, capture_output=True, text=True)
    print(result.stdout[-3000:])
    print(result.stderr, file=sys.stderr)
    assert result.returncode == 0, f"exit code {result.returncode}"
    return result.stdout


def type1_h0_forward(medusa, work, name):
    """(birth, death) of the H0 pairs of the forward filtration of the type-1 sub-medusa (MCS)."""
    text = run([medusa, "barcode", f"{name}.h5", "--format", "csv", "--type", "1", "--filtration", "forward",
                "--dim", "0"], work)
    rows = list(csv.DictReader(io.StringIO(text)))
    assert rows, f"{name}: no type-1 H0 pairs"
    assert all(r["type"] == "1" and r["direction"] == "forward" and r["dimension"] == "0" for r in rows)
    return [(float(r["birth"]), float(r["death"])) for r in rows]


def betti0(pairs, s):
    """Betti curve of a forward diagram (docs/MATH.md §7.8): classes with birth <= s < death."""
    return sum(1 for b, d in pairs if b <= s < d)


def check_merges(medusa, work):
    t0, t_end = 0.0, 2000.0
    summary = {}
    for name in SORTING + [CONTROL]:
        pairs = type1_h0_forward(medusa, work, name)
        deaths = [d for _, d in pairs if math.isfinite(d)]
        assert deaths, f"{name}: no finite H0 class (no merge at all)"
        summary[name] = (betti0(pairs, t0), betti0(pairs, t_end), statistics.median(deaths))
        print(f"{name}: {summary[name][0]} type-1 H0 classes at MCS {t0:g}, {summary[name][1]} at MCS "
              f"{t_end:g}, median death MCS {summary[name][2]:.1f}")
    # (a1) Sorting means the Condensing cells aggregate: in the forward filtration of the type-1
    # sub-medusa (docs/MATH.md §7.2, §7.4) the type-1 clusters present at the start have merged by the end,
    # leaving fewer H0 classes (a single one in both sorting runs). The control also merges some (the
    # filtration accumulates all contacts over time), so this alone does not distinguish sorting.
    for name in SORTING:
        start, end, _ = summary[name]
        assert end < start, f"{name}: {end} type-1 H0 classes at the end, {start} at the start"
    # (a2) What distinguishes sorting is timing: with J(C,C) < J(N,C) the Condensing clusters touch
    # sooner, so the median death time of the type-1 H0 classes is earlier in both sorting runs than in
    # the no-preference control.
    for name in SORTING:
        assert summary[name][2] < summary[CONTROL][2], (
            f"median type-1 merge time {summary[name][2]} in {name} is not before {summary[CONTROL][2]} in {CONTROL}")


def read_matrix(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    names = rows[0][1:]
    return {(a, b): float(v) for a, row in zip(names, rows[1:]) for b, v in zip(names, row[1:])}


def check_seeds(medusa, work):
    stores = [f"{name}.h5" for name in SORTING + [CONTROL]]
    s1, s2 = SORTING
    for metric in ("bottleneck", "wasserstein:1"):
        # (b) Two seeds of the same sorting parameters are closer to each other than a sorting run is to
        # the control: type-1 H0 diagrams of the forward filtration on the normalised time axis (docs/MATH.md
        # §7.7), finite parts (the control keeps two type-1 classes to the end, the sorting runs one, so
        # with the essential classes counted the sorting/control distances are inf: checked below).
        prefix = f"seeds_{metric.replace(':', '')}"
        run([medusa, "compare", *stores, "--type", "1", "--dim", "0", "--filtration", "forward", "--metric", metric,
             "--ignore-essential", "-o", prefix], work)
        d = read_matrix(f"{work}/{prefix}.distances.csv")
        print(f"{metric}: d({s1},{s2}) = {d[s1, s2]:.4g}, d({s1},{CONTROL}) = {d[s1, CONTROL]:.4g}, "
              f"d({s2},{CONTROL}) = {d[s2, CONTROL]:.4g}")
        assert d[s1, s2] < d[s1, CONTROL], metric
        assert d[s1, s2] < d[s2, CONTROL], metric

        prefix = f"seeds_{metric.replace(':', '')}_essential"
        run([medusa, "compare", *stores, "--type", "1", "--dim", "0", "--filtration", "forward", "--metric", metric,
             "--essential", "-o", prefix], work)
        d = read_matrix(f"{work}/{prefix}.distances.csv")
        assert math.isfinite(d[s1, s2]) and math.isinf(d[s1, CONTROL]) and math.isinf(d[s2, CONTROL]), d


def main():
    what, medusa, work = sys.argv[1:4]
    {"merges": check_merges, "seeds": check_seeds}[what](medusa, work)
    print("ok")


if __name__ == "__main__":
    main()
