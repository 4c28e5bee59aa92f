"""Cross-checks the golden files of tests/data/cli/golden against each other and against GUDHI, so
that a regenerated golden file that is internally inconsistent or disagrees with the oracle fails even
before its diff is read (tests/data/cli/golden/README.txt lists what each check covers).

usage: verify_golden.py <golden dir> <medusa binary> <work dir with the three golden stores>
"""
import csv
import json
import math
import os
import re
import subprocess
import sys

import gudhi

golden, medusa, work = sys.argv[1:4]
checks = 0


def text(name):
    with open(os.path.join(golden, name)) as f:
        return f.read()


def check(condition, message):
    global checks
    checks += 1
    if not condition:
        sys.exit("golden files disagree: " + message)


def number(s):
    return float(s)  # float('inf'), float('-inf') and %.17g text all read back exactly


type_names = {"all": ""}  # type id -> the name its block headers give (small.csv names its types)


def blocks(name):
    """`medusa diagrams` output: {(type, direction): (announced count, [(birth, death, dim)])}."""
    result, key = {}, None
    for line in text(name).splitlines():
        m = re.match(r"# type (\w+)(?: \(([^)]*)\))?, (forward|reverse), (\d+) pairs \(birth death dim\)$", line)
        if m:
            key = (m.group(1), m.group(3))
            result[key] = (int(m.group(4)), [])
            named = m.group(2) or ""
            check(type_names.setdefault(key[0], named) == named, f"{name}: type {key[0]} named twice")
        else:
            b, d, k = line.split()
            result[key][1].append((number(b), number(d), int(k)))
    for key, (count, pairs) in result.items():
        check(count == len(pairs), f"{name}: block {key} announces {count} pairs, has {len(pairs)}")
    return result


every = blocks("diagrams_all.txt")
check(sorted(every) == sorted((t, d) for t in ("all", "1", "2") for d in ("forward", "reverse")),
      "diagrams_all.txt: not the six diagrams (all, 1, 2) x (forward, reverse)")
check(type_names == {"all": "", "1": "Condensing", "2": "NonCondensing"},
      f"diagrams_all.txt: the headers do not name small.csv's types: {type_names}")

# barcode_all.pers as GUDHI reads it: per dimension, the multiset of (birth, death) of diagrams_all.
pers = os.path.join(golden, "barcode_all.pers")
for k in range(4):
    ours = sorted((b, d) for _, pairs in every.values() for (b, d, dim) in pairs if dim == k)
    theirs = sorted(map(tuple, gudhi.read_persistence_intervals_in_dimension(persistence_file=pers,
                                                                             only_this_dim=k).tolist()))
    check(ours == theirs, f"barcode_all.pers read by GUDHI differs from diagrams_all.txt in dimension {k}")

# barcode_all.csv: the same pairs, labelled with their diagram, in the order of diagrams_all.txt.
with open(os.path.join(golden, "barcode_all.csv")) as f:
    rows = list(csv.DictReader(f))
# run_small.diagrams.csv (what `medusa run` wrote beside small.h5): its run id line, then barcode_all.csv.
with open(os.path.join(golden, "run_small.diagrams.csv")) as f, open(os.path.join(golden, "barcode_all.csv")) as g:
    check(f.read() == "# medusa run <RUN_ID>\n" + g.read(), "run_small.diagrams.csv is not barcode_all.csv under its run id")
expected = [(t, d, p) for (t, d), (_, pairs) in every.items() for p in pairs]
got = [(r["type"], r["direction"], (number(r["birth"]), number(r["death"]), int(r["dimension"]))) for r in rows]
check(got == expected, "barcode_all.csv differs from diagrams_all.txt")
check(all(r["type_name"] == type_names[r["type"]] for r in rows), "barcode_all.csv: a type_name is not its type's")

# barcode_type2.json: the type-2 diagrams.
listed = json.loads(text("barcode_type2.json"))["diagrams"]
check([(x["type"], x["type_name"], x["direction"]) for x in listed] ==
      [("2", "NonCondensing", "forward"), ("2", "NonCondensing", "reverse")],
      "barcode_type2.json: not the two type-2 diagrams, named")
for x in listed:
    pairs = [(number(p["birth"]), number(p["death"]), p["dimension"]) for p in x["pairs"]]
    check(pairs == every[("2", x["direction"])][1], f"barcode_type2.json {x['direction']} differs")

# Filtered `diagrams` outputs are the matching lines of diagrams_all.txt.
def selected(types, directions, dim=None):
    return {(t, d): [p for p in every[(t, d)][1] if dim is None or p[2] == dim]
            for t in types for d in directions}


def pairs_of(name):
    return {key: pairs for key, (_, pairs) in blocks(name).items()}


check(pairs_of("diagrams_forward_h0.txt") == selected(("all", "1", "2"), ("forward",), 0),
      "diagrams_forward_h0.txt")
check(pairs_of("diagrams_reverse_h2.txt") == selected(("all", "1", "2"), ("reverse",), 2),
      "diagrams_reverse_h2.txt")
check(pairs_of("diagrams_type2.txt") == selected(("2",), ("forward", "reverse")), "diagrams_type2.txt")

# With zero-length pairs, H0 of type 1 has one pair per type-1 cell (each vertex is born once), and
# dropping the pairs with birth == death leaves the pairs of diagrams_all.txt.
info = text("info.txt")
type1_cells = int(re.search(r"cell types: 1 \(Condensing\): (\d+);", info).group(1))
zero = pairs_of("diagrams_type1_h0_zero_length.txt")
for direction in ("forward", "reverse"):
    pairs = zero[("1", direction)]
    check(len(pairs) == type1_cells, f"type 1 H0 {direction} with zero-length pairs: one pair per cell")
    check([p for p in pairs if p[0] != p[1]] == selected(("1",), (direction,), 0)[("1", direction)],
          f"type 1 H0 {direction} without its zero-length pairs")

# The run summary and `info` count the same cells; the summary's feature counts are diagrams_all's.
summary = text("run_small.txt")
dims = [int(x) for x in re.search(r"medusa cells: dim 0: (\d+), dim 1: (\d+), dim 2: (\d+), dim 3: (\d+), "
                                  r"dim 4: (\d+)", summary).groups()]
check(dims == [int(re.search(rf"  dimension {k}: (\d+)\n", info).group(1)) for k in range(5)],
      "cells per dimension: run_small.txt against info.txt")
check(sum(dims) == int(re.search(r"medusa cells: (\d+)\n", info).group(1)), "info.txt: total cells")
for label, t in (("all cells", "all"), ("type 1 (Condensing)", "1"), ("type 2 (NonCondensing)", "2")):
    part = summary.split(label + ":\n")[1]
    forward = every[(t, "forward")][1]
    for k, word in ((1, "loops"), (2, "cavities")):
        present, formed = (int(x) for x in re.search(rf"  {word}: (\d+) present at MCS 0, (\d+) formed", part).groups())
        filled = [int(x) for x in re.search(rf"  {word}: .*\n    filled by cells: (\d+) of those at MCS 0, (\d+) formed",
                                            part).groups()] if present + formed else [0, 0]
        finite = [(b, d) for b, d, kk in forward if kk == k and b != d and d != math.inf]
        check(present + formed == sum(1 for b, d, kk in forward if kk == k and b != d), f"{word} of {t}")
        check(filled == [sum(1 for b, d in finite if b == 0), sum(1 for b, d in finite if b != 0)],
              f"filled {word} of {t}: born at MCS 0 and later")

# curves_frames.csv: Euler characteristic from the f-vector and from the Betti numbers (docs/MATH.md §7.5);
# the two types partition the vertices; MCS 100 agrees with `medusa at --time 100`.
with open(os.path.join(golden, "curves_frames.csv")) as f:
    curves = list(csv.DictReader(f))
check(len(curves) == 9, "curves_frames.csv: 3 frames x (all, 1, 2)")
row = {}
for r in curves:
    f_ = [int(r[f"f{k}"]) for k in range(4)]
    b_ = [int(r[f"b{k}"]) for k in range(3)]
    check(f_[0] - f_[1] + f_[2] - f_[3] == int(r["euler"]) == b_[0] - b_[1] + b_[2], f"Euler at {r}")
    row[(r["time"], r["type"])] = f_
for time in ("0", "100", "200"):
    check(row[(time, "all")][0] == row[(time, "1")][0] + row[(time, "2")][0], f"vertices at {time}")
at = [int(x) for x in re.search(r"K\(t\+\) at MCS 100: (\d+) vertices, (\d+) edges, (\d+) triangles, "
                                r"(\d+) tetrahedra", text("at_100.txt")).groups()]
check(at == row[("100", "all")], "at_100.txt against curves_frames.csv at MCS 100")
with open(os.path.join(golden, "at_100.csv")) as f:
    simplices = list(csv.DictReader(f))
check([sum(1 for s in simplices if s["dimension"] == str(k)) for k in range(4)] == at,
      "at_100.csv rows per dimension against at_100.txt")

# at_type1_50.5.vtk: as many points as type-1 cells, as many VTK cells as the simplices counted.
vtk = text("at_type1_50.5.vtk")
counts = [int(x) for x in re.search(r"(\d+) vertices, (\d+) edges, (\d+) triangles, (\d+) tetrahedra",
                                    text("at_type1_50.5.txt")).groups()]
check(int(re.search(r"\nPOINTS (\d+) double\n", vtk).group(1)) == counts[0] == type1_cells, "VTK points")
check(int(re.search(r"\nCELLS (\d+) ", vtk).group(1)) == sum(counts), "VTK cells")

# compare_type1_h1: GUDHI's bottleneck distance between the finite type-1 H1 forward points of the
# three stores on the normalised time axis t -> (t - t0) / (t_end - t0) (docs/MATH.md §7.7).
names = ["small", "nosorting_3d_3frames", "sorting_3d_seed2_3frames"]
finite = []
for name in names:
    out = subprocess.run([medusa, "barcode", name + ".h5", "--format", "csv", "--type", "1", "--dim", "1",
                          "--filtration", "forward"], cwd=work, check=True, capture_output=True, text=True)
    points = [(number(r["birth"]), number(r["death"])) for r in csv.DictReader(out.stdout.splitlines())]
    t0, t_end = map(number, re.search(rf"\n  {name}: MCS (\S+) to (\S+),", text("compare_type1_h1.txt")).groups())
    finite.append([((b - t0) / (t_end - t0), (d - t0) / (t_end - t0)) for b, d in points if math.isfinite(d)])
with open(os.path.join(golden, "compare_type1_h1.distances.csv")) as f:
    matrix = list(csv.reader(f))
check(matrix[0] == ["run"] + names, "compare_type1_h1.distances.csv header")
for i in range(3):
    check(matrix[i + 1][0] == names[i], "compare_type1_h1.distances.csv row names")
    for j in range(3):
        value = number(matrix[i + 1][j + 1])
        check(value == number(matrix[j + 1][i + 1]), "compare_type1_h1.distances.csv is symmetric")
        oracle = gudhi.bottleneck_distance(finite[i], finite[j], 0)
        # Exact: GUDHI's value (e = 0) is a coordinate difference, or half of one, of the same
        # normalised doubles, which are computed here as medusa computes them.
        check(value == oracle, f"bottleneck {names[i]}-{names[j]}: golden {value!r}, GUDHI {oracle!r}")
print(f"{checks} checks passed")
