"""Independent oracle for `medusa diagrams` on a real store (run with /usr/bin/python3).

usage: check_diagrams_oracle.py <medusa> <store> [<run input> <radius>]
       (with a run input, `medusa run` first writes the store from it)

Reads the store with h5py alone, builds the forward and reverse filtrations of the whole medusa and of
each cell type's sub-medusa from docs/FORMAT.md and docs/MATH.md §7.2-§7.4 (keys by batch and rank, facets
from the stored facet ids), reduces their boundary matrices over Z/2 with the standard algorithm
(Python integers as bit columns: nothing shared with PHAT or libpersistence), and requires the
diagrams `medusa diagrams` prints to equal them exactly: every pair of positive length, as doubles,
and every essential class. Zero-length pairs (birth and death in one batch, 7.5) are not printed by
default and are left out here too. Exit 1 names the first difference.
"""
import subprocess
import sys
from collections import Counter

import h5py
import numpy as np

if not __debug__:
    sys.exit("these checks are assert statements: run without -O and without PYTHONOPTIMIZE")


def read_cells(path):
    with h5py.File(path, "r") as f:
        assert int(f.attrs["complete"]) == 1
        c = f["cells"]
        cells = {name: c[name][:] for name in
                 ("id", "birth_batch", "birth_rank", "birth_time", "death_batch", "death_rank", "death_time",
                  "vertex_offset", "vertices", "facet_offset", "facets")}
        types = f["input"]["cell_type"][:]
    return cells, types


def diagram(cells, types, direction, cell_type):
    """Multiset of (birth, death, dim) of positive length, inf/-inf for essential classes."""
    off, verts = cells["vertex_offset"], cells["vertices"]
    foff, facets = cells["facet_offset"], cells["facets"]
    n = len(cells["id"])
    row_of_id = np.empty(n, dtype=np.int64)
    row_of_id[cells["id"]] = np.arange(n)
    rows = []
    for r in range(n):
        v = verts[off[r]:off[r + 1]]
        if cell_type is None or all(types[x] == cell_type for x in v):
            rows.append(r)
    if direction == "forward":
        key = lambda r: (int(cells["birth_batch"][r]), int(cells["birth_rank"][r]), int(off[r + 1] - off[r]),
                         tuple(int(x) for x in verts[off[r]:off[r + 1]]))
        value, batch, sign = cells["birth_time"], cells["birth_batch"], 1.0
    else:
        key = lambda r: (-int(cells["death_batch"][r]), -int(cells["death_rank"][r]), int(off[r + 1] - off[r]),
                         tuple(int(x) for x in verts[off[r]:off[r + 1]]))
        value, batch, sign = cells["death_time"], cells["death_batch"], -1.0
    rows.sort(key=key)
    index = {r: i for i, r in enumerate(rows)}
    low_owner = {}  # low row -> reduced column index
    columns = []
    paired = set()
    pairs = Counter()
    for j, r in enumerate(rows):
        col = 0
        for fid in facets[foff[r]:foff[r + 1]]:
            i = index[row_of_id[fid]]  # a facet of a cell of the sub-medusa is in it (7.4)
            assert i < j, "a facet follows its coface in the filtration"
            col ^= 1 << i
        while col:
            low = col.bit_length() - 1
            if low not in low_owner:
                break
            col ^= columns[low_owner[low]]
        columns.append(col)
        if col:
            low = col.bit_length() - 1
            low_owner[low] = j
            paired.update((low, j))
            b, d = rows[low], r
            if batch[b] != batch[d]:
                pairs[(float(value[b]), float(value[d]), int(off[b + 1] - off[b]) - 1)] += 1
    for j, r in enumerate(rows):
        if j not in paired:
            pairs[(float(value[r]), sign * float("inf"), int(off[r + 1] - off[r]) - 1)] += 1
    return pairs, len(rows)


def printed_diagrams(medusa, store):
    out = subprocess.run([medusa, "diagrams", store], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    result, current = {}, None
    for line in out.stdout.splitlines():
        if line.startswith("# type "):
            # "# type 1 (Condensing), forward, ...": the id, then the direction
            head = line[len("# type "):].split(",")
            current = (head[0].split()[0], head[1].strip())
            result[current] = Counter()
        elif line.strip():
            b, d, dim = line.split()
            result[current][(float(b), float(d), int(dim))] += 1
    return result


def main():
    medusa, store = sys.argv[1], sys.argv[2]
    if len(sys.argv) > 3:
        made = subprocess.run([medusa, "run", "--force", sys.argv[3], "--radius", sys.argv[4], "--quiet", "-o", store],
                              capture_output=True, text=True)
        assert made.returncode == 0, made.stderr
    cells, types = read_cells(store)
    printed = printed_diagrams(medusa, store)
    assert len(printed) == 6, sorted(printed)
    for (type_name, direction), got in sorted(printed.items()):
        cell_type = None if type_name == "all" else int(type_name)
        expected, size = diagram(cells, types, direction, cell_type)
        print(f"type {type_name}, {direction}: {size} cells, {sum(expected.values())} pairs "
              f"of positive length or essential; medusa printed {sum(got.values())}")
        assert size > 0 and sum(expected.values()) > 0, "an empty filtration tests nothing"
        missing, extra = expected - got, got - expected
        assert not missing and not extra, (f"type {type_name}, {direction}: missing {list(missing.items())[:5]}, "
                                           f"extra {list(extra.items())[:5]}")
    print("all six diagrams equal the oracle's")


if __name__ == "__main__":
    main()
