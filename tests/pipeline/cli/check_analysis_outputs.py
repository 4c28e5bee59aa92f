"""Checks of `medusa compare`, `medusa curves` and `medusa at` on small stores (run with /usr/bin/python3).

usage: check_analysis_outputs.py compare <medusa> <workdir> <store>...
       check_analysis_outputs.py curves <medusa> <workdir> <store> <cells.csv.gz>
       check_analysis_outputs.py at <medusa> <workdir> <store> <cells.csv.gz>
       check_analysis_outputs.py barcode <medusa> <workdir> <store>
Every check prints what it compares; an AssertionError (exit 1) names the first mismatch.
"""
import csv
import gzip
import math
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ElementTree
from collections import Counter
from itertools import combinations

if not __debug__:
    sys.exit("these checks are assert statements: run without -O and without PYTHONOPTIMIZE")


def run(args, cwd, expect=0):
    print("$", " ".join(args))
    result = subprocess.run(args, cwd=cwd, capture_output=True, text=True)
    print(result.stdout)
    print(result.stderr, file=sys.stderr)
    assert result.returncode == expect, f"exit code {result.returncode}, expected {expect}"
    return result


def read_input_frames(path):
    """{mcs: {cell_id: (type, x, y, z)}} from a CC3D cells.csv.gz (the test's independent reader)."""
    frames = {}
    with gzip.open(path, "rt") as f:
        for row in csv.DictReader(f):
            frames.setdefault(int(row["mcs"]), {})[int(row["cell_id"])] = (
                int(row["type_id"]), float(row["xCOM"]), float(row["yCOM"]), float(row["zCOM"]))
    return frames


def read_matrix(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    names = rows[0][1:]
    assert rows[0][0] == "run", rows[0]
    assert [r[0] for r in rows[1:]] == names, "row names differ from column names"
    values = [[float(v) for v in r[1:]] for r in rows[1:]]
    assert all(len(r) == len(names) for r in values), "matrix is not square"
    return names, values


def check_matrix(names, values, stores):
    n = len(stores)
    assert len(names) == n, (names, stores)
    assert names == [os.path.splitext(os.path.basename(s))[0] for s in stores], names
    for i in range(n):
        assert values[i][i] == 0, f"diagonal entry {i} is {values[i][i]}"
        for j in range(n):
            assert values[i][j] == values[j][i], f"entries ({i},{j}) and ({j},{i}) differ"
            assert values[i][j] >= 0 and not math.isnan(values[i][j])


def essential_counts(stdout):
    """Run name -> number of essential classes, from the per-run lines of `medusa compare`."""
    return {m.group(1): int(m.group(2))
            for m in re.finditer(r"^  (\S+): MCS .* finite points, (\d+) essential classes$", stdout, re.M)}


def check_compare(medusa, work, stores):
    prefix = os.path.join(work, "cmp_t1")
    # Type 1 (Condensing), H0, forward: the runs have different numbers of type-1 clusters at the end,
    # so with essential classes counted some distances are inf (docs/MATH.md §7.7) and equal counts are finite.
    result = run([medusa, "compare", *stores, "--type", "1", "--dim", "0", "--filtration", "forward", "--essential",
                  "-o", prefix], work)
    names, values = read_matrix(prefix + ".distances.csv")
    check_matrix(names, values, stores)
    counts = essential_counts(result.stdout)
    print("essential counts:", counts)
    assert sorted(counts) == sorted(names), counts
    assert len(set(counts.values())) > 1, "no two runs differ in essential counts: inf is not tested"
    for i, j in combinations(range(len(names)), 2):
        same = counts[names[i]] == counts[names[j]]
        print(f"{names[i]} / {names[j]}: {values[i][j]} (essential counts {'equal' if same else 'differ'})")
        assert math.isinf(values[i][j]) != same
    assert "average-linkage clustering:" in result.stdout
    assert len(re.findall(r"^  .* \+ .* at \S+$", result.stdout, re.M)) == len(names) - 1, "n-1 merges expected"
    for suffix in (".heatmap.svg", ".dendrogram.svg"):
        root = ElementTree.parse(prefix + suffix).getroot()
        assert root.tag.endswith("svg"), root.tag
        text = "".join(root.itertext())
        assert all(name in text for name in names), f"{suffix} does not name every run"

    # Finite parts only, W1: every distance finite, and the same matrix shape.
    prefix = os.path.join(work, "cmp_w1")
    run([medusa, "compare", *stores, "--type", "1", "--metric", "wasserstein:1", "--ignore-essential", "-o", prefix],
        work)
    names, values = read_matrix(prefix + ".distances.csv")
    check_matrix(names, values, stores)
    assert all(math.isfinite(v) for row in values for v in row), values
    # Comparing a run with itself: distance 0 everywhere.
    prefix = os.path.join(work, "cmp_self")
    run([medusa, "compare", stores[0], stores[0], "--type", "1", "-o", prefix], work)
    names, values = read_matrix(prefix + ".distances.csv")
    assert values == [[0.0, 0.0], [0.0, 0.0]], values
    assert names == [stores[0], stores[0]], names


def check_curves(medusa, work, store, cells):
    prefix = os.path.join(work, "curves")
    run([medusa, "curves", store, "-o", prefix], work)
    frames = read_input_frames(cells)
    first = frames[min(frames)]
    expected_f0 = {"all": len(first)}
    for t in set(v[0] for v in first.values()):
        expected_f0[str(t)] = sum(1 for v in first.values() if v[0] == t)
    with open(prefix + ".curves.csv", newline="") as f:
        reader = csv.DictReader(f)
        assert reader.fieldnames == ["time", "type", "f0", "f1", "f2", "f3", "euler", "b0", "b1", "b2"], reader.fieldnames
        rows = list(reader)
    assert rows, "no rows"
    first_rows = {}
    for r in rows:
        f = [int(r[f"f{k}"]) for k in range(4)]
        assert int(r["euler"]) == f[0] - f[1] + f[2] - f[3], r
        # Euler-Poincare (b3 = 0 for a subcomplex of R^3): the Betti numbers agree with the counts.
        assert int(r["euler"]) == int(r["b0"]) - int(r["b1"]) + int(r["b2"]), r
        first_rows.setdefault(r["type"], r)
    print("first rows:", first_rows)
    assert sorted(first_rows) == sorted(expected_f0), (sorted(first_rows), sorted(expected_f0))
    for label, r in first_rows.items():
        assert float(r["time"]) == min(frames), r
        assert int(r["f0"]) == expected_f0[label], (label, r["f0"], expected_f0[label])
    for label in first_rows:
        times = [float(r["time"]) for r in rows if r["type"] == label]
        assert times == sorted(times), f"type {label}: times not increasing"
        assert times[-1] == max(frames), f"type {label}: last sample at {times[-1]}"
    root = ElementTree.parse(prefix + ".curves.svg").getroot()
    assert root.tag.endswith("svg")

    # --frames-only: one row per frame and type, at the frame times; the last frame reports K(t_end-),
    # the last row of the full curves.
    run([medusa, "curves", store, "-o", prefix + "_frames", "--frames-only"], work)
    with open(prefix + "_frames.curves.csv", newline="") as f:
        frame_rows = list(csv.DictReader(f))
    for label in first_rows:
        mine = [r for r in frame_rows if r["type"] == label]
        assert [float(r["time"]) for r in mine] == [float(t) for t in sorted(frames)], (label, mine)
        assert mine[0] == first_rows[label], (mine[0], first_rows[label])
        last = [r for r in rows if r["type"] == label][-1]
        assert mine[-1] == last, (mine[-1], last)


def read_simplices(path):
    with open(path, newline="") as f:
        reader = csv.reader(f)
        assert next(reader) == ["dimension", "v0", "v1", "v2", "v3"]
        simplices = []
        for row in reader:
            assert len(row) == 5, row
            d = int(row[0])
            ids = [int(v) for v in row[1:] if v != ""]
            assert len(ids) == d + 1 and ids == sorted(ids), row
            assert all(v == "" for v in row[d + 2:]), row
            simplices.append(tuple(ids))
    return simplices


def read_vtk(path):
    """Sections of a legacy ASCII VTK unstructured grid, checking the counts of every header."""
    with open(path) as f:
        lines = f.read().split("\n")
    assert lines[0] == "# vtk DataFile Version 3.0", lines[0]
    assert lines[2] == "ASCII" and lines[3] == "DATASET UNSTRUCTURED_GRID", lines[2:4]
    i = 4
    m = re.fullmatch(r"POINTS (\d+) double", lines[i])
    assert m, lines[i]
    n_points = int(m.group(1))
    points = [tuple(float(x) for x in lines[i + 1 + k].split()) for k in range(n_points)]
    assert all(len(p) == 3 for p in points)
    i += 1 + n_points
    m = re.fullmatch(r"CELLS (\d+) (\d+)", lines[i])
    assert m, lines[i]
    n_cells, size = int(m.group(1)), int(m.group(2))
    cells = [[int(x) for x in lines[i + 1 + k].split()] for k in range(n_cells)]
    assert sum(len(c) for c in cells) == size, "CELLS size"
    assert all(c[0] == len(c) - 1 and all(0 <= v < n_points for v in c[1:]) for c in cells)
    i += 1 + n_cells
    assert lines[i] == f"CELL_TYPES {n_cells}", lines[i]
    types = [int(lines[i + 1 + k]) for k in range(n_cells)]
    i += 1 + n_cells
    assert lines[i] == f"CELL_DATA {n_cells}", lines[i]
    data = {}
    i += 1
    for name in ("cell_type", "dimension"):
        assert lines[i] == f"SCALARS {name} int 1" and lines[i + 1] == "LOOKUP_TABLE default", lines[i:i + 2]
        data[name] = [int(lines[i + 2 + k]) for k in range(n_cells)]
        i += 2 + n_cells
    assert lines[i] == f"POINT_DATA {n_points}", lines[i]
    i += 1
    point_data = {}
    for name, kind in (("cell_id", "long"), ("cell_type", "int")):
        assert lines[i] == f"SCALARS {name} {kind} 1" and lines[i + 1] == "LOOKUP_TABLE default", lines[i:i + 2]
        point_data[name] = [int(lines[i + 2 + k]) for k in range(n_points)]
        i += 2 + n_points
    assert all(line == "" for line in lines[i:]), "trailing content"
    return points, cells, types, data, point_data


def check_at(medusa, work, store, cells_csv):
    frames = read_input_frames(cells_csv)
    times = sorted(frames)
    # T = t_1: K(t_1+) lives on the slab [t_1, t_2], so its vertices are the cells present on both frames.
    t = times[1]
    csv_path = os.path.join(work, "at.csv")
    run([medusa, "at", store, "--time", str(t), "-o", csv_path], work)
    simplices = read_simplices(csv_path)
    present = set(frames[t]) & set(frames[times[2]])
    vertices = [s[0] for s in simplices if len(s) == 1]
    print(f"{len(vertices)} vertices in K({t}+), {len(present)} cells present on frames {t} and {times[2]}")
    assert Counter(vertices) == Counter(present)
    # Closure: every face of every simplex is listed.
    listed = set(simplices)
    assert len(listed) == len(simplices), "a simplex is listed twice"
    for s in simplices:
        for k in range(1, len(s)):
            for face in combinations(s, k):
                assert face in listed, f"face {face} of {s} is missing"
    dims = Counter(len(s) - 1 for s in simplices)
    print("simplices by dimension:", dict(dims))
    assert dims[1] > 0 and dims[2] > 0, "expected edges and triangles at radius 3"

    # --type 1 at the start: the type-1 subcomplex (docs/MATH.md §7.4) has every type-1 cell as a vertex and
    # only simplices whose vertices are all of type 1; it is the full subcomplex of K(t0+) on them.
    t0 = times[0]
    type1_path, all_path = os.path.join(work, "at_type1.csv"), os.path.join(work, "at_start.csv")
    run([medusa, "at", store, "--time", str(t0), "--type", "1", "-o", type1_path], work)
    run([medusa, "at", store, "--time", str(t0), "-o", all_path], work)
    type1 = read_simplices(type1_path)
    type_of = {cell_id: v[0] for cell_id, v in frames[t0].items() if cell_id in frames[times[1]]}
    expected = [s for s in read_simplices(all_path) if all(type_of[c] == 1 for c in s)]
    print(f"type-1 subcomplex at MCS {t0}: {len(type1)} simplices, {sum(1 for s in type1 if len(s) == 1)} vertices")
    assert sorted(type1) == sorted(expected)
    assert sum(1 for s in type1 if len(s) == 1) == sum(1 for t in type_of.values() if t == 1)

    # The same complex as VTK, half-way through the first slab: positions are the midpoints of the
    # input centres (linear interpolation), and the cell counts match the CSV of the same time.
    t_mid = (times[0] + times[1]) / 2
    vtk_path, mid_csv = os.path.join(work, "at.vtk"), os.path.join(work, "at_mid.csv")
    run([medusa, "at", store, "--time", str(t_mid), "-o", vtk_path], work)
    run([medusa, "at", store, "--time", str(t_mid), "-o", mid_csv], work)
    points, cells, types, data, point_data = read_vtk(vtk_path)
    mid = read_simplices(mid_csv)
    assert len(cells) == len(mid), (len(cells), len(mid))
    assert Counter(data["dimension"]) == Counter(len(s) - 1 for s in mid)
    vtk_type = {0: 1, 1: 3, 2: 5, 3: 10}
    for c, t_vtk, d, ct in zip(cells, types, data["dimension"], data["cell_type"]):
        assert d == len(c) - 2 and t_vtk == vtk_type[d], (c, t_vtk, d)
        vertex_types = {point_data["cell_type"][v] for v in c[1:]}
        assert ct == (vertex_types.pop() if len(vertex_types) == 1 else 0), (c, ct)
    ids = point_data["cell_id"]
    assert sorted(ids) == sorted(set(frames[times[0]]) & set(frames[times[1]]))
    for p, cell_id, cell_type in zip(points, ids, point_data["cell_type"]):
        a, b = frames[times[0]][cell_id], frames[times[1]][cell_id]
        assert cell_type == a[0]
        for k in range(3):
            expected = (a[k + 1] + b[k + 1]) / 2
            assert abs(p[k] - expected) <= 1e-7 * max(1.0, abs(expected)), (cell_id, p, expected)
    # Simplices of the VTK, as sorted cell-id tuples, are those of the CSV.
    assert sorted(tuple(sorted(ids[v] for v in c[1:])) for c in cells) == sorted(mid)


def check_barcode(medusa, work, store, max_bars=5):
    """`barcode --format svg --max-bars N` draws, per diagram and degree, the N longest bars of the
    CSV export (essential ones first): their count and their lengths on the time axis."""
    pairs = {}
    for row in csv.DictReader(run([medusa, "barcode", store, "--format", "csv"], work).stdout.splitlines()):
        pairs.setdefault((row["type"], row["direction"]), {}).setdefault(int(row["dimension"]), []).append(
            (float(row["birth"]), float(row["death"])))
    svg = run([medusa, "barcode", store, "--format", "svg", "--max-bars", str(max_bars)], work).stdout
    root = ElementTree.fromstring(svg)
    ns = "{http://www.w3.org/2000/svg}"
    axis = [float(re.fullmatch(r"MCS (\S+)", t.text).group(1)) for t in root.iter(ns + "text") if t.text.startswith("MCS")]
    t0, t_end = axis
    colours = {"#1f77b4": 0, "#d62728": 1, "#2ca02c": 2}

    def x_of(t):
        t = t_end if t == math.inf else t0 if t == -math.inf else t
        return 150 + 630 * (min(max(t, t0), t_end) - t0) / (t_end - t0)

    sections, truncated = [], 0
    for element in root:
        if element.tag == ns + "text" and element.text.startswith("type "):
            m = re.match(r"type (\S+), (forward|reverse) \((\d+) bars", element.text)
            sections.append(((m.group(1), m.group(2)), int(m.group(3)), {}))
            truncated += f"the {max_bars} longest of each degree shown" in element.text
        elif element.tag == ns + "line" and element.get("stroke") in colours:
            length = abs(float(element.get("x2")) - float(element.get("x1")))
            sections[-1][2].setdefault(colours[element.get("stroke")], []).append(round(length, 2))
    assert [s[0] for s in sections] == list(pairs), (list(pairs), [s[0] for s in sections])
    for key, total, drawn in sections:
        assert total == sum(len(v) for v in pairs[key].values()), key
        for dim, bars in pairs[key].items():
            longest = sorted(bars, key=lambda b: (not math.isinf(b[1]), -abs(b[1] - b[0])))[:max_bars]
            expected = sorted(round(abs(x_of(d) - x_of(b)), 2) for b, d in longest)
            assert sorted(drawn.get(dim, [])) == expected, (key, dim, sorted(drawn.get(dim, [])), expected)
        print(key, {d: len(v) for d, v in drawn.items()}, "drawn of", {d: len(v) for d, v in pairs[key].items()})
    assert truncated > 0, "no diagram was long enough to be cut: the check did not test the cap"


def main():
    what, medusa, work = sys.argv[1], sys.argv[2], sys.argv[3]
    os.makedirs(work, exist_ok=True)
    if what == "compare":
        check_compare(medusa, work, sys.argv[4:])
    elif what == "curves":
        check_curves(medusa, work, sys.argv[4], sys.argv[5])
    elif what == "at":
        check_at(medusa, work, sys.argv[4], sys.argv[5])
    elif what == "barcode":
        check_barcode(medusa, work, sys.argv[4])
    else:
        raise SystemExit(f"unknown check {what}")
    print("ok")


if __name__ == "__main__":
    main()
