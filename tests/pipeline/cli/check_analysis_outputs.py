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
            for m in re.finditer(r"^  (\S+): MCS \S+ to \S+, radius \S+, \d+ finite, (\d+) essential$", stdout, re.M)}


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
    assert "runs grouped by distance, closest first (average linkage):" in result.stdout
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
    # The type by its name, in any case, as `medusa info` lists it: the same matrix as by its id.
    by_name = os.path.join(work, "cmp_w1_named")
    result = run([medusa, "compare", *stores, "--type", "condensing", "--metric", "wasserstein:1",
                  "--ignore-essential", "-o", by_name], work)
    assert read_matrix(by_name + ".distances.csv") == (names, values)
    assert "type condensing" in result.stdout, result.stdout
    # Comparing a run with itself: distance 0 everywhere.
    prefix = os.path.join(work, "cmp_self")
    itself = run([medusa, "compare", stores[0], stores[0], "--type", "1", "-o", prefix], work)
    assert f"warning: {stores[0]} is given twice: its distance to itself is 0" in itself.stderr, itself.stderr
    names, values = read_matrix(prefix + ".distances.csv")
    assert values == [[0.0, 0.0], [0.0, 0.0]], values
    assert names == [stores[0], stores[0]], names

    # Two runs, every type and degree: one distance per comparison, largest first, each that of its
    # distances.csv, and where the verdicts are.
    prefix = os.path.join(work, "cmp_pair")
    pair = run([medusa, "compare", stores[0], stores[1], "-o", prefix], work)
    lines = re.findall(r"^  (type \S+ \w+ \(H(\d)\)): (\S+)$", pair.stdout, re.M)
    assert "the distance between the two runs, largest first" in pair.stdout, pair.stdout
    assert "grouped:" not in pair.stdout and ", ratio " not in pair.stdout, pair.stdout
    assert len(lines) >= 4, lines
    shown = [float(d) for _, _, d in lines]
    assert shown == sorted(shown, reverse=True), shown
    for words, dim, d in lines:
        label = words.split()[1]
        _, matrix = read_matrix(f"{prefix}.type{label}.h{dim}.distances.csv")
        assert abs(matrix[0][1] - float(d)) <= 1e-5 * max(1.0, abs(matrix[0][1])), (words, d, matrix)
    assert f"whether and when each run sorts: medusa report {stores[0]} {stores[1]}" in pair.stdout


def check_compare_warnings(medusa, work, cells_csv):
    # The same run with its two type ids swapped (names kept with their cells), and once more at another
    # radius: by name the swapped run is the same run (distance 0); by id, a warning names the clash.
    with gzip.open(cells_csv, "rt") as f:
        rows = list(csv.reader(f))
    col = rows[0].index("type_id")
    swap_csv = os.path.join(work, "swapped_types.csv")
    with open(swap_csv, "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(rows[0])
        for r in rows[1:]:
            r[col] = {"1": "2", "2": "1"}[r[col]]
            out.writerow(r)
    stores = {}
    for name, source, radius in (("original", cells_csv, "3"), ("swapped", swap_csv, "3"), ("wider", cells_csv, "5")):
        stores[name] = os.path.join(work, name + ".h5")
        run([medusa, "run", "-q", "--force", source, "-o", stores[name], "--radius", radius], work)
    by_name = run([medusa, "compare", stores["original"], stores["swapped"], "--type", "Condensing", "-o",
                   os.path.join(work, "by_name")], work)
    assert read_matrix(os.path.join(work, "by_name.distances.csv"))[1] == [[0.0, 0.0], [0.0, 0.0]]
    assert "different names" not in by_name.stderr, by_name.stderr
    by_id = run([medusa, "compare", stores["original"], stores["swapped"], "--type", "1", "-o",
                 os.path.join(work, "by_id")], work)
    assert read_matrix(os.path.join(work, "by_id.distances.csv"))[1][0][1] > 0
    assert ("type 1 has different names in the runs (original Condensing, swapped NonCondensing): types are "
            "matched by id; --type NAME matches them by name") in by_id.stderr, by_id.stderr
    assert "radii" not in by_id.stderr, by_id.stderr
    every = run([medusa, "compare", stores["original"], stores["swapped"], stores["wider"], "-o",
                 os.path.join(work, "every")], work)
    assert "  swapped: MCS 0 to 200, radius 3\n    type 1 (NonCondensing):" in every.stdout, every.stdout
    assert "  wider: MCS 0 to 200, radius 5\n" in every.stdout, every.stdout
    assert "radii more than 5% apart (original 3, swapped 3, wider 5)" in every.stderr, every.stderr
    # A name one run lacks is refused before anything is printed.
    wrong = run([medusa, "compare", stores["original"], stores["swapped"], "--type", "Light"], work, expect=3)
    assert wrong.stdout == "" and "no cell type is named 'Light' in" in wrong.stderr, wrong.stderr


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
        assert reader.fieldnames == ["time", "type", "f0", "f1", "f2", "f3", "euler", "b0", "b1", "b2",
                                     "type_name"], reader.fieldnames
        rows = list(reader)
    assert rows, "no rows"
    # Each type's name as the input CSV gives it, on every row of the type (none for all cells).
    with gzip.open(cells, "rt") as f:
        names = {row["type_id"]: row["type_name"] for row in csv.DictReader(f)}
    names["all"] = ""
    assert len(names) > 2 and all(names[k] for k in names if k != "all"), names
    for path in (prefix + ".curves.csv", prefix + ".sorting.csv"):
        with open(path, newline="") as f:
            named = list(csv.DictReader(f))
        assert named and all(r["type_name"] == names[r["type"]] for r in named), (path, names)
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
    # The SVG: one plot per curve (b0-b2, f0-f3) of each type, each with the range of its own column.
    root = ElementTree.parse(prefix + ".curves.svg").getroot()
    curves = [g for g in root.iter("{http://www.w3.org/2000/svg}g") if g.get("class") == "curve"]
    labels = list(dict.fromkeys(r["type"] for r in rows))
    expected = [(label, column) for label in labels for column in ("b0", "b1", "b2", "f0", "f1", "f2", "f3")]
    assert [g.get("data-name") for g in curves] == [c for _, c in expected], [g.get("data-name") for g in curves]
    for g, (label, column) in zip(curves, expected):
        top = max(int(r[column]) for r in rows if r["type"] == label)
        assert float(g.get("data-max")) == top, (label, column, g.get("data-max"), top)

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
    # The type by its name gives the same subcomplex; "all" is no type of `medusa at`.
    named_path = os.path.join(work, "at_condensing.csv")
    run([medusa, "at", store, "--time", str(t0), "--type", "Condensing", "-o", named_path], work)
    assert read_simplices(named_path) == type1
    refused = run([medusa, "at", store, "--time", str(t0), "--type", "all", "-o", named_path], work, expect=2)
    assert "leave out --type" in refused.stderr, refused.stderr
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


def panels_of(root):
    """The panels of a barcode or diagram SVG: (type, direction, degree) -> (attributes, [(birth, death)])."""
    ns = "{http://www.w3.org/2000/svg}"
    panels = {}
    for g in root.iter(ns + "g"):
        if g.get("class") != "panel":
            continue
        key = (g.get("data-type"), g.get("data-direction"), int(g.get("data-degree")))
        marks = [(float(e.get("data-birth")), float(e.get("data-death")))
                 for e in g if e.get("class") in ("bar", "point")]
        assert key not in panels, f"panel {key} twice"
        panels[key] = (g.attrib, marks, g)
    return panels


def check_barcode(medusa, work, store, max_bars=5):
    """`barcode --format svg --max-bars N` draws one panel per diagram and degree H0-H2 with its own time
    axis: the N longest finite bars of the CSV export, sorted by birth, and counts the essential classes
    in the title; `--format diagram-svg` draws every finite pair as a point, with the diagonal, or with
    --max-points N, a panel of more than N classes as bins counting each class once."""
    pairs = {}
    for row in csv.DictReader(run([medusa, "barcode", store, "--format", "csv"], work).stdout.splitlines()):
        pairs.setdefault((row["type"], row["direction"], int(row["dimension"])), []).append(
            (float(row["birth"]), float(row["death"])))
    ns = "{http://www.w3.org/2000/svg}"
    for style, cap in (("svg", []), ("diagram-svg", ["--max-points", "0"]), ("density", ["--max-points", "5"])):
        shape = "diagram-svg" if style == "density" else style
        svg = run([medusa, "barcode", store, "--format", shape, "--max-bars", str(max_bars)] + cap, work).stdout
        root = ElementTree.fromstring(svg)
        legend = [t.text for t in root.iter(ns + "text")]
        for word in ("H0 clusters", "H1 loops", "H2 cavities"):
            assert word in legend, f"{style}: legend without {word}"
        panels = panels_of(root)
        diagrams = {(t, d) for t, d, k in pairs}
        assert {(t, d) for t, d, k in panels} == diagrams, (sorted(panels), sorted(diagrams))
        truncated = binned = 0
        for (t, d, k), (attributes, marks, g) in panels.items():
            all_pairs = pairs.get((t, d, k), [])
            finite = [(b, e) for b, e in all_pairs if not math.isinf(e)]
            essential = len(all_pairs) - len(finite)
            assert int(attributes["data-finite"]) == len(finite), (style, t, d, k)
            assert int(attributes["data-essential"]) == essential, (style, t, d, k)
            title = " ".join(e.text for e in g if e.tag == ns + "text" and e.text)
            assert f"{essential} " in title, (style, t, d, k, title)
            lo, hi = float(attributes["data-t0"]), float(attributes["data-t1"])
            for b, e in marks:
                assert lo - 1e-9 <= min(b, e) and max(b, e) <= hi + 1e-9, (style, t, d, k, b, e, lo, hi)
            if style == "svg":
                expected = sorted(finite, key=lambda p: -abs(p[1] - p[0]))[:max_bars]
                assert sorted(abs(e - b) for b, e in marks) == sorted(abs(e - b) for b, e in expected), (t, d, k)
                starts = [min(b, e) for b, e in marks]
                assert starts == sorted(starts), f"{t} {d} H{k}: bars not sorted by birth"
                truncated += len(finite) > max_bars
            elif style == "density" and len(finite) > 5:
                # Each class counted once, in the bin of its (birth, death): bin floor((x - t0) / (t1 - t0)
                # * bins), the right end in the last (svg_plot.h).
                assert not marks, (t, d, k, "points drawn in a density panel")
                density = g.find(ns + "g")
                assert density is not None and density.get("class") == "density", (t, d, k)
                bins = int(density.get("data-bins"))
                drawn = {(int(e.get("data-bx")), int(e.get("data-by"))): int(e.get("data-count")) for e in density}
                assert len(drawn) == len(list(density)) and all(n > 0 for n in drawn.values()), (t, d, k)
                def bin_of(x):
                    return min(bins - 1, int((min(max(x, lo), hi) - lo) / (hi - lo) * bins))
                expected = {}
                for b, e in finite:
                    key = (bin_of(b), bin_of(e))
                    expected[key] = expected.get(key, 0) + 1
                assert drawn == expected, (t, d, k)
                assert "shaded by count" in title, (t, d, k, title)
                binned += 1
                marks = [None] * len(drawn)
            else:
                assert sorted(marks) == sorted(finite), (t, d, k)
                assert any(e.get("class") == "diagonal" for e in g), f"{t} {d} H{k}: no diagonal"
            print(style, t, d, f"H{k}:", len(marks), "drawn of", len(finite), "finite,", essential, "essential")
        if style == "svg":
            assert truncated > 0, "no panel was long enough to be cut: the check did not test the cap"
        if style == "density":
            assert binned > 0, "no panel was drawn as a density: the check did not test --max-points"


def main():
    what, medusa, work = sys.argv[1], sys.argv[2], sys.argv[3]
    os.makedirs(work, exist_ok=True)
    if what == "compare":
        check_compare(medusa, work, sys.argv[4:])
    elif what == "compare_warnings":
        check_compare_warnings(medusa, work, sys.argv[4])
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
