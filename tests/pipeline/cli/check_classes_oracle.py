"""Independent check of the class representatives stored by `medusa run` (run with /usr/bin/python3).

usage: check_classes_oracle.py [<medusa>] <store> | <medusa> <store> <run input> <radius>
       (with a run input, `medusa run` first writes the store from it)

Reads the store with h5py alone (docs/FORMAT.md) and, for every diagram with a `classes` subgroup and
every represented class of degree k (docs/MATH.md §7.11), requires:
* the cycle is a Z/2 cycle (its boundary from the stored facets is zero; every 0-chain is one),
* its cells belong to the diagram's (sub-)medusa and enter no later than the birth cell, which is in it,
* a finite class's cycle is not a boundary of the (k+1)-cells entered before the death cell, and is one
  once the death cell has entered; an essential class's cycle is never a boundary: a brute-force
  Z/2 rank test (Python integers as bit columns, its own elimination in filtration order),
* the cluster of an H0 class is the component of its birth vertex among the vertices and edges
  entered before the death cell (the whole filtration for an essential class).
With <medusa>, `medusa classes --format json` must list exactly the stored classes of the whole
medusa's forward diagram with the CC3D ids derived here, and the classes it computes on demand for the
reverse diagram must pass the same checks. Exit 1 names the first failure; a store without any represented class fails (it tests nothing).
"""
import json
import subprocess
import sys
from collections import defaultdict

import h5py
import numpy as np

if not __debug__:
    sys.exit("these checks are assert statements: run without -O and without PYTHONOPTIMIZE")


class Boundaries:
    """Z/2 columns (Python integers, bit j = filtration index j) added one by one and kept reduced: a
    column reduces to zero exactly when it is a sum of the columns added so far."""

    def __init__(self):
        self.pivots = {}

    def reduce(self, col):
        while col:
            low = col.bit_length() - 1
            if low not in self.pivots:
                return col
            col ^= self.pivots[low]
        return 0

    def add(self, col):
        col = self.reduce(col)
        if col:
            self.pivots[col.bit_length() - 1] = col


class Store:
    """The cells of a store, read with h5py alone (docs/FORMAT.md)."""

    def __init__(self, f):
        c = f["cells"]
        self.ids = c["id"][:]
        self.off, self.verts = c["vertex_offset"][:].astype(np.int64), c["vertices"][:]
        self.foff, self.facets = c["facet_offset"][:].astype(np.int64), c["facets"][:]
        self.bb, self.br = c["birth_batch"][:], c["birth_rank"][:]
        self.db, self.dr = c["death_batch"][:], c["death_rank"][:]
        self.types = f["input"]["cell_type"][:]
        self.cc3d = f["input"]["cell_id"][:]
        self.row_of = np.empty(len(self.ids), dtype=np.int64)
        self.row_of[self.ids] = np.arange(len(self.ids))

    def cc3d_ids(self, cell_id):
        r = self.row_of[cell_id]
        return sorted(int(self.cc3d[v]) for v in self.verts[self.off[r]:self.off[r + 1]])


def check_classes(s, name, forward, cell_type, entries):
    """entries: dicts with dim, essential, birth_cell, death_cell, cycle (cell ids), cluster (ids or None)."""
    off, verts, foff, facets, row_of = s.off, s.verts, s.foff, s.facets, s.row_of

    def tup(r):
        return tuple(int(x) for x in verts[off[r]:off[r + 1]])

    members = [r for r in range(len(s.ids))
               if cell_type < 0 or all(s.types[v] == cell_type for v in verts[off[r]:off[r + 1]])]
    if forward:
        key = lambda r: (int(s.bb[r]), int(s.br[r]), int(off[r + 1] - off[r]), tup(r))
    else:
        key = lambda r: (-int(s.db[r]), -int(s.dr[r]), int(off[r + 1] - off[r]), tup(r))
    members.sort(key=key)
    index = {r: j for j, r in enumerate(members)}
    dim_of = lambda r: int(off[r + 1] - off[r]) - 1

    def boundary_bits(r):
        col = 0
        for fid in facets[foff[r]:foff[r + 1]]:
            col ^= 1 << index[row_of[fid]]
        return col

    # The classes grouped by degree, each with the filtration index of its death (None: essential).
    by_dim = defaultdict(list)
    for e in entries:
        cells = [row_of[x] for x in e["cycle"]]
        b = row_of[e["birth_cell"]]
        kdim = e["dim"]
        where = f"{name} class {e['id']} (degree {kdim})"
        assert all(r in index for r in cells), f"{where}: a cell outside the diagram's medusa"
        assert b in cells, f"{where}: the birth cell is not in the cycle"
        assert all(index[r] <= index[b] for r in cells), f"{where}: a cell enters after the birth cell"
        assert all(dim_of(r) == kdim for r in cells), f"{where}: cells of another dimension"
        z = 0
        for r in cells:
            z ^= 1 << index[r]
        assert bin(z).count("1") == len(cells), f"{where}: a cell listed twice"
        if kdim > 0:
            bd = 0
            for r in cells:
                bd ^= boundary_bits(r)
            assert bd == 0, f"{where}: not a cycle"
        death = None if e["essential"] else index[row_of[e["death_cell"]]]
        by_dim[kdim].append((death, z, where))
        if kdim == 0 and e["cluster"] is not None:
            cluster = {int(row_of[x]) for x in e["cluster"]}
            # Component of b among the vertices and edges entered before the death (or at all).
            limit = len(members) if death is None else death
            parent = {}

            def find(x):
                while parent[x] != x:
                    parent[x] = parent[parent[x]]
                    x = parent[x]
                return x
            for j in range(limit):
                r = members[j]
                if dim_of(r) == 0:
                    parent[r] = r
                elif dim_of(r) == 1:
                    u, v = (row_of[x] for x in facets[foff[r]:foff[r + 1]])
                    parent[find(u)] = find(v)
            expected = {r for r in parent if find(r) == find(b)}
            assert cluster == expected, f"{where}: cluster {len(cluster)} cells, expected {len(expected)}"
    # Rank test: eliminate the boundaries of (k+1)-cells in filtration order; just before a class's
    # death cell enters its cycle must not reduce to zero, and right after it must.
    for kdim, classes in by_dim.items():
        boundaries = Boundaries()
        reduce = boundaries.reduce
        dying = defaultdict(list)
        for death, z, where in classes:
            dying[death].append((z, where))
        for j, r in enumerate(members):
            for z, where in dying.get(j, []):
                assert reduce(z) != 0, f"{where}: a boundary before its death cell"
            if dim_of(r) == kdim + 1:
                boundaries.add(boundary_bits(r))
            for z, where in dying.get(j, []):
                assert reduce(z) == 0, f"{where}: not a boundary once its death cell has entered"
        for z, where in dying.get(None, []):
            assert reduce(z) != 0, f"{where}: an essential cycle that is a boundary"
    return len(entries)


def stored_entries(s, g):
    k = g["classes"]
    assert int(k.attrs["format_version"]) == 1
    rows = k["row"][:]
    coff, cyc = k["cycle_offset"][:].astype(np.int64), k["cycle"][:]
    loff, clu = k["cluster_offset"][:].astype(np.int64), k["cluster"][:]
    dims, ess = g["dimension"][:], g["essential"][:]
    bcell, dcell = g["birth_cell"][:], g["death_cell"][:]
    return [{"id": int(row), "dim": int(dims[row]), "essential": bool(ess[row]), "birth_cell": int(bcell[row]),
             "death_cell": int(dcell[row]), "cycle": [int(x) for x in cyc[coff[i]:coff[i + 1]]],
             "cluster": [int(x) for x in clu[loff[i]:loff[i + 1]]],
             "birth": float(g["birth"][row]), "death": float(g["death"][row])}
            for i, row in enumerate(rows)]


def listed_classes(medusa, store, *options):
    out = subprocess.run([medusa, "classes", store, "--format", "json", *options], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout)["classes"]


def main():
    medusa = sys.argv[1] if len(sys.argv) > 2 else None
    store = sys.argv[2] if medusa else sys.argv[1]
    if len(sys.argv) > 3:
        made = subprocess.run([medusa, "run", "--force", sys.argv[3], "--radius", sys.argv[4], "--quiet", "-o", store],
                              capture_output=True, text=True)
        assert made.returncode == 0, made.stderr
    tested = 0
    with h5py.File(store, "r") as f:
        s = Store(f)
        p = f["persistence"]
        for name in p.attrs["diagram_order"].decode().split(","):
            g = p[name]
            if "classes" not in g:
                continue
            entries = stored_entries(s, g)
            tested += check_classes(s, name, g.attrs["direction"].decode() == "forward", int(g.attrs["type"]),
                                    entries)
            print(f"{name}: {len(entries)} stored classes checked")
            if medusa is None or name != "forward_all":
                continue
            # `medusa classes` lists exactly the stored classes, with their cells' CC3D ids.
            listed = {c["id"]: c for c in listed_classes(medusa, store, "--sort", "birth")}
            assert sorted(listed) == sorted(e["id"] for e in entries), "medusa classes lists other classes"
            for e in entries:
                c = listed[e["id"]]
                assert c["dimension"] == e["dim"] and c["medusa_cycle"] == e["cycle"], e["id"]
                assert c["birth"] == e["birth"] and (c["death"] == "inf" if e["essential"] else c["death"] == e["death"])
                assert c["birth_cells"] == s.cc3d_ids(e["birth_cell"]), e["id"]
                assert c["simplices"] == [s.cc3d_ids(x) for x in e["cycle"]], e["id"]
                made_of = e["cluster"] if e["dim"] == 0 else e["cycle"]
                assert c["cells"] == sorted({i for x in made_of for i in s.cc3d_ids(x)}), e["id"]
            print(f"medusa classes lists the {len(entries)} stored classes of {name}")
        if medusa is not None:
            # Not stored: the reverse diagram of the whole medusa, computed on demand.
            listed = listed_classes(medusa, store, "--filtration", "reverse")
            entries = [{"id": c["id"], "dim": c["dimension"], "essential": c["essential"],
                        "birth_cell": c["medusa_birth_cell"], "death_cell": c["medusa_death_cell"],
                        "cycle": c["medusa_cycle"], "cluster": None} for c in listed]
            tested += check_classes(s, "reverse_all (on demand)", False, -1, entries)
            print(f"reverse_all: {len(entries)} classes computed on demand checked")
    assert tested > 0, "no represented class: nothing tested"
    print(f"all {tested} representatives pass")


if __name__ == "__main__":
    main()
