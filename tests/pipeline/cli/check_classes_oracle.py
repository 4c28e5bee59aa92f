"""Independent check of the class representatives stored by `medusa run` (run with /usr/bin/python3).

usage: check_classes_oracle.py <store>

Reads the store with h5py alone (docs/FORMAT.md) and, for every diagram with a `classes` subgroup and
every represented class of degree k (docs/MATH.md §7.9), requires:
* the cycle is a Z/2 cycle (its boundary from the stored facets is zero; every 0-chain is one),
* its cells belong to the diagram's (sub-)medusa and enter no later than the birth cell, which is in it,
* a finite class's cycle is not a boundary of the (k+1)-cells entered before the death cell, and is one
  once the death cell has entered; an essential class's cycle is never a boundary: a brute-force
  Z/2 rank test (Python integers as bit columns, its own elimination in filtration order),
* the cluster of an H0 class is the component of its birth vertex among the vertices and edges
  entered before the death cell (the whole filtration for an essential class).
Exit 1 names the first failure; a store without any represented class fails (it tests nothing).
"""
import sys
from collections import defaultdict

import h5py
import numpy as np

if not __debug__:
    sys.exit("these checks are assert statements: run without -O and without PYTHONOPTIMIZE")


def main():
    store = sys.argv[1]
    with h5py.File(store, "r") as f:
        c = f["cells"]
        ids = c["id"][:]
        off, verts = c["vertex_offset"][:], c["vertices"][:]
        foff, facets = c["facet_offset"][:], c["facets"][:]
        bb, br = c["birth_batch"][:], c["birth_rank"][:]
        db, dr = c["death_batch"][:], c["death_rank"][:]
        types = f["input"]["cell_type"][:]
        row_of = np.empty(len(ids), dtype=np.int64)
        row_of[ids] = np.arange(len(ids))
        tested = 0
        p = f["persistence"]
        for name in p.attrs["diagram_order"].decode().split(","):
            g = p[name]
            if "classes" not in g:
                continue
            forward = g.attrs["direction"].decode() == "forward"
            cell_type = int(g.attrs["type"])
            k = g["classes"]
            assert int(k.attrs["format_version"]) == 1
            rows = k["row"][:]
            coff, cyc = k["cycle_offset"][:], k["cycle"][:]
            loff, clu = k["cluster_offset"][:], k["cluster"][:]
            dims, ess = g["dimension"][:], g["essential"][:]
            bcell, dcell = g["birth_cell"][:], g["death_cell"][:]

            def tup(r):
                return tuple(int(x) for x in verts[off[r]:off[r + 1]])

            members = [r for r in range(len(ids))
                       if cell_type < 0 or all(types[v] == cell_type for v in verts[off[r]:off[r + 1]])]
            if forward:
                key = lambda r: (int(bb[r]), int(br[r]), int(off[r + 1] - off[r]), tup(r))
            else:
                key = lambda r: (-int(db[r]), -int(dr[r]), int(off[r + 1] - off[r]), tup(r))
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
            for i, row in enumerate(rows):
                cells = [row_of[x] for x in cyc[coff[i]:coff[i + 1]]]
                b = row_of[bcell[row]]
                kdim = int(dims[row])
                where = f"{name} row {row} (degree {kdim})"
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
                death = None if ess[row] else index[row_of[dcell[row]]]
                by_dim[kdim].append((death, z, where))
                if kdim == 0:
                    cluster = {int(row_of[x]) for x in clu[loff[i]:loff[i + 1]]}
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
                tested += 1
            # Rank test: eliminate the boundaries of (k+1)-cells in filtration order; just before a class's
            # death cell enters its cycle must not reduce to zero, and right after it must.
            for kdim, classes in by_dim.items():
                pivots = {}

                def reduce(col):
                    while col:
                        low = col.bit_length() - 1
                        if low not in pivots:
                            return col
                        col ^= pivots[low]
                    return 0
                dying = defaultdict(list)
                for death, z, where in classes:
                    dying[death].append((z, where))
                for j, r in enumerate(members):
                    for z, where in dying.get(j, []):
                        assert reduce(z) != 0, f"{where}: a boundary before its death cell"
                    if dim_of(r) == kdim + 1:
                        col = reduce(boundary_bits(r))
                        if col:
                            pivots[col.bit_length() - 1] = col
                    for z, where in dying.get(j, []):
                        assert reduce(z) == 0, f"{where}: not a boundary once its death cell has entered"
                for z, where in dying.get(None, []):
                    assert reduce(z) != 0, f"{where}: an essential cycle that is a boundary"
            print(f"{name}: {len(rows)} classes checked")
    assert tested > 0, "no represented class: nothing tested"
    print(f"all {tested} representatives pass")


if __name__ == "__main__":
    main()
