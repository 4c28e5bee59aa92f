"""`medusa at --class` and `medusa at --times` against `medusa classes` and `medusa at -o x.csv`
(run with /usr/bin/python3).

usage: check_at_classes.py <medusa> <store> <work dir>

* --class ID (an H1 class of the whole medusa, an H0 class of type 1): the legacy VTK holds K(T) at the class's
  birth time T (the simplices of `medusa at --time T -o x.csv`) plus the representative's simplices,
  and exactly the representative's simplices (for H0 its cluster's cells, not the older cluster's vertex
  of its 0-cycle) carry in_class = 1 and
  class_id = ID, as `medusa classes --format json` lists them;
* --times A:B:STEP -o folder: one .vtu per time whose simplices are those of `medusa at --time t`,
  and series.pvd listing them with their times.
Exit 1 names the first difference.
"""
import csv
import json
import os
import sys
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cli_checks import cli  # noqa: E402

if not __debug__:
    sys.exit("these checks are assert statements: run without -O and without PYTHONOPTIMIZE")


def csv_simplices(binary, store, t, work, *options):
    path = os.path.join(work, "k.csv")
    cli(binary, "at", store, "--time", repr(t), "-o", path, *options)
    with open(path) as f:
        return {tuple(int(x) for x in r[1:] if x) for r in list(csv.reader(f))[1:]}


def legacy_vtk(path):
    """(simplices as sorted CC3D tuples, cell data by name, point cell ids, point data by name)."""
    lines = open(path).read().split("\n")
    i = lines.index("ASCII") + 2
    n_points = int(lines[i].split()[1])
    i += 1 + n_points
    n_cells = int(lines[i].split()[1])
    cells = [[int(x) for x in lines[i + 1 + k].split()[1:]] for k in range(n_cells)]
    data, point_data, current, k = {}, {}, None, i + 1 + n_cells
    while k < len(lines):
        words = lines[k].split()
        if words and words[0] == "CELL_DATA":
            current = data
        elif words and words[0] == "POINT_DATA":
            current = point_data
        elif words and words[0] == "SCALARS":
            size = n_cells if current is data else n_points
            current[words[1]] = [int(x) for x in lines[k + 2:k + 2 + size]]
            k += 1 + size
        k += 1
    ids = point_data["cell_id"]
    simplices = [tuple(sorted(ids[p] for p in c)) for c in cells]
    return simplices, data, ids, point_data


def check_class(binary, store, work, cls, *options):
    target = os.path.join(work, f"class_{cls['id']}.vtk")
    cli(binary, "at", store, "--class", str(cls["id"]), "-o", target, *options)
    t = cls["birth"]  # the default time
    simplices, data, ids, point_data = legacy_vtk(target)
    context = csv_simplices(binary, store, t, work, *options)
    # For H0 the class's cells are its cluster's, as `medusa classes` lists them: the 0-cycle's other
    # vertex belongs to the older cluster it joins (docs/MATH.md §7.11) and is not drawn as the class.
    cluster = {(c,) for c in cls["cells"]} if cls["dimension"] == 0 else set()
    representative = cluster if cls["dimension"] == 0 else {tuple(s) for s in cls["simplices"]}
    assert set(simplices) == context | representative, f"class {cls['id']}: the export is not K(T) and the class"
    marked = {s for s, c in zip(simplices, data["class_id"]) if c == cls["id"]}
    assert marked == representative, f"class {cls['id']}: marked cells differ"
    if cls["dimension"] == 0:
        older = {tuple(s) for s in cls["simplices"] if tuple(s) not in cluster}
        assert older, f"class {cls['id']}: the 0-cycle has no vertex outside the cluster (nothing tested)"
    assert all((c >= 0) == bool(i) for c, i in zip(data["class_id"], data["in_class"]))
    marked_points = {ids[p] for p, c in enumerate(point_data["class_id"]) if c == cls["id"]}
    assert marked_points == set(cls["cells"]) | {i for s in representative for i in s}, f"class {cls['id']}: points"
    print(f"class {cls['id']} (degree {cls['dimension']}): {len(marked)} marked simplices in K({t}) "
          f"of {len(simplices)}")


def check_series(binary, store, work):
    folder = os.path.join(work, "series")
    cli(binary, "at", store, "--times", "0:200:100", "-o", folder)
    root = ET.parse(os.path.join(folder, "series.pvd")).getroot()
    sets = root.find("Collection").findall("DataSet")
    assert [(d.get("timestep"), d.get("file")) for d in sets] == [
        ("0", "at_00000.vtu"), ("100", "at_00001.vtu"), ("200", "at_00002.vtu")], [d.attrib for d in sets]
    for d in sets:
        piece = ET.parse(os.path.join(folder, d.get("file"))).getroot().find("UnstructuredGrid/Piece")
        arrays = {a.get("Name"): [int(x) for x in a.text.split()]
                  for a in piece.iter("DataArray") if a.get("Name")}
        ids, conn, offsets = arrays["cell_id"], arrays["connectivity"], arrays["offsets"]
        assert len(ids) == int(piece.get("NumberOfPoints")) and len(offsets) == int(piece.get("NumberOfCells"))
        starts = [0] + offsets[:-1]
        simplices = {tuple(sorted(ids[p] for p in conn[a:b])) for a, b in zip(starts, offsets)}
        expected = csv_simplices(binary, store, float(d.get("timestep")), work)
        assert simplices == expected, f"{d.get('file')}: simplices differ from medusa at"
        assert len(arrays["types"]) == len(offsets)
    print(f"series: {len(sets)} .vtu files and series.pvd")


def main():
    binary, store, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    def classes(*options):
        return json.loads(cli(binary, "classes", store, "--format", "json", "--sort", "death", *options))["classes"]
    h1 = [c for c in classes() if c["dimension"] == 1 and not c["essential"] and len(c["simplices"]) > 3]
    h0 = [c for c in classes("--type", "1") if c["dimension"] == 0 and not c["essential"] and len(c["cells"]) > 1]
    assert h1 and h0, "no class to draw"
    check_class(binary, store, work, h1[0])
    check_class(binary, store, work, h0[0], "--type", "1")
    check_series(binary, store, work)


if __name__ == "__main__":
    main()
