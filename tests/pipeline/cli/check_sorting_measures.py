"""`medusa curves --frames-only` against GUDHI's exact static alpha complex of every frame.

usage: check_sorting_measures.py <medusa> <workdir> <store.h5> | <input> [run options...]
(run with /usr/bin/python3; an input other than a store is first run through `medusa run`)

For each frame k the positions are read from the store's /input (docs/FORMAT.md), the alpha complex of
the cells of the state reported at the frame is built by gudhi.AlphaComplex(precision='exact') on the integer grid coordinates and
pruned at (rho * grid_scale)^2 (GUDHI filtrations are squared radii). From it, independently of medusa:
the simplex counts and Betti numbers over Z/2 of K and of every type's full subcomplex (curves.csv),
and the sorting measures (sorting.csv): edges, heterotypic edges, same-type neighbour fractions,
clusters (union-find), largest and mean cluster size. Counts must be equal, fractions within 1e-12.
The contacts `medusa report` gives under each type's headline are those of the first and last frames,
and a verdict in which no type gathers names the cells outside each type's largest cluster at the last
frame as GUDHI's components do.
"""
import csv
import os
import re
import subprocess
import sys
from fractions import Fraction

import gudhi
import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from report_sweep_data import page_data  # noqa: E402

if not __debug__:
    sys.exit("these checks are assert statements: run without -O and without PYTHONOPTIMIZE")


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def components(vertices, edges):
    parent = {v: v for v in vertices}

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    for a, b in edges:
        ra, rb = find(a), find(b)
        if ra != rb:
            parent[ra] = rb
    sizes = {}
    for v in vertices:
        r = find(v)
        sizes[r] = sizes.get(r, 0) + 1
    return list(sizes.values())


def outside_largest(vertices, edges):
    """The vertices outside the largest component, or None when two components share the largest size."""
    parent = {v: v for v in vertices}

    def find(x):
        while parent[x] != x:
            x = parent[x]
        return x

    for a, b in edges:
        parent[find(a)] = find(b)
    members = {}
    for v in vertices:
        members.setdefault(find(v), []).append(v)
    sizes = sorted((len(m) for m in members.values()), reverse=True)
    if len(sizes) > 1 and sizes[0] == sizes[1]:
        return None
    largest = max(members.values(), key=len) if members else []
    return [v for v in vertices if v not in set(largest)]


def betti(simplices, dimension):
    st = gudhi.SimplexTree()
    for s in simplices:
        st.insert(list(s), 0.0)
    if st.num_vertices() == 0:
        return [0, 0, 0]
    st.compute_persistence(homology_coeff_field=2, persistence_dim_max=True)
    b = list(st.betti_numbers()) + [0, 0, 0]
    return b[:3]


def expected_at_frame(f, k):
    inp = f["input"]
    scale = int(f.attrs["grid_scale"])
    dimension = int(f.attrs["dimension"])
    radius = f.attrs["radius_text"]
    radius = radius.decode() if isinstance(radius, bytes) else str(radius)
    rho2 = float((Fraction(radius) * scale) ** 2)
    first = [int(x) for x in inp["first_frame"][:]]
    offset = [int(x) for x in inp["position_offset"][:]]
    types = inp["cell_type"][:]
    ids = inp["cell_id"][:]
    positions = inp["positions"][:]
    last_frame = len(inp["frame_times"]) - 1
    present, points = [], []
    for v in range(len(first)):
        last = first[v] + offset[v + 1] - offset[v] - 1
        # The state reported at frame k < K is K(t_k+): cells deleted at t_k (last frame k) are gone,
        # cells inserted at t_k are there; at the last frame it is K(t_K-), the cells of slab K-1
        # (docs/MATH.md §0, §2.4); a run of one frame has only its cells at t_0.
        if last_frame == 0:
            here = first[v] == 0
        elif k < last_frame:
            here = first[v] <= k < last
        else:
            here = first[v] < k <= last
        if here:
            present.append(v)
            p = positions[offset[v] + k - first[v]]
            points.append([float(x) for x in p[:dimension]])
    st = gudhi.AlphaComplex(points=points, precision="exact").create_simplex_tree()
    st.prune_above_filtration(rho2)
    simplices = [tuple(present[i] for i in s) for s, _ in st.get_simplices()]
    kinds = sorted(set(int(types[v]) for v in present))
    out = {}
    for label in ["all"] + [str(t) for t in kinds]:
        def mine(v):
            return label == "all" or int(types[v]) == int(label)

        verts = [v for v in present if mine(v)]
        edges = [s for s in simplices if len(s) == 2]
        touching = [e for e in edges if mine(e[0]) or mine(e[1])]
        hetero = [e for e in touching if types[e[0]] != types[e[1]]]
        neighbours = {v: [] for v in verts}
        for a, b in edges:
            if a in neighbours:
                neighbours[a].append(b)
            if b in neighbours:
                neighbours[b].append(a)
        fractions = [sum(1 for w in ns if types[w] == types[v]) / len(ns) for v, ns in neighbours.items() if ns]
        own = [s for s in simplices if all(mine(v) for v in s)]
        sizes = components(verts, [e for e in own if len(e) == 2])
        apart = outside_largest(verts, [e for e in own if len(e) == 2])
        f_counts = [sum(1 for s in own if len(s) == d + 1) for d in range(4)]
        out[label] = {
            "cells": len(verts), "edges": len(touching), "heterotypic_edges": len(hetero),
            "heterotypic_fraction": len(hetero) / len(touching) if touching else None,
            "cells_with_neighbours": len(fractions),
            "same_type_fraction": sum(fractions) / len(fractions) if fractions else None,
            "clusters": len(sizes), "largest_cluster": max(sizes) if sizes else 0,
            "mean_cluster_size": len(verts) / len(sizes) if sizes else None,
            "f": f_counts, "betti": betti(own, dimension),
            "apart": None if apart is None else sorted(set(int(ids[v]) for v in apart)),
        }
    return out


def main():
    medusa, work, store = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    if not store.endswith(".h5"):
        name = os.path.basename(store.rstrip("/")).split(".")[0] + "_oracle.h5"
        result = subprocess.run([medusa, "run", "--force", store, "-o", name, "--quiet"] + sys.argv[4:], cwd=work)
        assert result.returncode == 0, f"medusa run exit code {result.returncode}"
        store = name
    prefix = os.path.join(work, os.path.splitext(os.path.basename(store))[0] + ".oracle")
    result = subprocess.run([medusa, "curves", store, "-o", prefix, "--frames-only"], cwd=work,
                            capture_output=True, text=True)
    print(result.stdout, result.stderr)
    assert result.returncode == 0, result.returncode
    sorting = read_rows(prefix + ".sorting.csv")
    curves = read_rows(prefix + ".curves.csv")
    with h5py.File(store if os.path.isabs(store) else os.path.join(work, store), "r") as f:
        times = [float(t) for t in f["input"]["frame_times"][:]]
        compared = 0
        for k, t in enumerate(times):
            expected = expected_at_frame(f, k)
            if k == 0:
                oracle_first = expected
            oracle_last = expected
            for label, e in expected.items():
                srow = [r for r in sorting if r["type"] == label and float(r["time"]) == t]
                crow = [r for r in curves if r["type"] == label and float(r["time"]) == t]
                assert len(srow) == 1 and len(crow) == 1, (k, label, len(srow), len(crow))
                s, c = srow[0], crow[0]
                for key in ["cells", "edges", "heterotypic_edges", "cells_with_neighbours", "clusters",
                            "largest_cluster"]:
                    assert int(s[key]) == e[key], (k, label, key, s[key], e[key])
                for key in ["heterotypic_fraction", "same_type_fraction", "mean_cluster_size"]:
                    if e[key] is None:
                        assert s[key] == "", (k, label, key, s[key])
                    else:
                        assert abs(float(s[key]) - e[key]) <= 1e-12, (k, label, key, s[key], e[key])
                assert [int(c[f"f{d}"]) for d in range(4)] == e["f"], (k, label, c, e["f"])
                assert [int(c[f"b{d}"]) for d in range(3)] == e["betti"], (k, label, c, e["betti"])
                compared += 1
            print(f"frame {k} (MCS {t:g}):", {l: (e["heterotypic_fraction"], e["clusters"], e["betti"])
                                              for l, e in expected.items()})
    assert compared >= 3, f"only {compared} frame rows compared"
    print(f"{compared} frame rows equal to GUDHI's exact alpha complexes")
    check_report(medusa, work, store, prefix, oracle_first, oracle_last)


def check_report(medusa, work, store, prefix, first, last):
    """The report's contacts and largest clusters under each type's headline: the same first and last
    frames, to its three decimals."""
    page = prefix + ".report.html"
    result = subprocess.run([medusa, "report", store, "-o", page, "--no-sweep", "-q"], cwd=work)
    assert result.returncode == 0, result.returncode
    checked = 0
    for h in page_data(page)["runs"][0]["headlines"]:
        m = re.match(r"heterotypic contacts (\S+) → (\S+), same-type neighbours (\S+) → (\S+), "
                     r"largest cluster (\d+) of (\d+) → (\d+) of (\d+) cells \(MCS ", h["contacts"])
        assert m, h["contacts"]
        sizes = [int(x) for x in m.groups()[4:]]
        f, l = first[h["label"]], last[h["label"]]
        assert sizes == [f["largest_cluster"], f["cells"], l["largest_cluster"], l["cells"]], (h["contacts"], f, l)
        shown = [float(x) for x in m.groups()[:4]]
        wanted = [first[h["label"]]["heterotypic_fraction"], last[h["label"]]["heterotypic_fraction"],
                  first[h["label"]]["same_type_fraction"], last[h["label"]]["same_type_fraction"]]
        for a, b in zip(shown, wanted):
            assert b is not None and abs(a - b) <= 0.0005 + 1e-12, (h["label"], h["contacts"], wanted)
        checked += 1
    assert checked >= 2, f"only {checked} headlines checked"
    print(f"the report's contacts of {checked} headlines equal GUDHI's at the first and last frames")
    check_verdict_apart(page_data(page)["runs"][0], last)


def check_verdict_apart(run, last):
    """A verdict in which no type gathers says, for each type in several clusters at the last frame, how
    many cells its largest cluster holds and names the cells outside it (up to five): GUDHI's."""
    verdict = run["verdict"]
    if not verdict.startswith("has no type in one cluster"):
        print("the run sorts or cannot tell: no cells apart in its verdict")
        return
    named = 0
    for label, e in last.items():
        if label == "all" or e["clusters"] <= 1:
            continue
        m = re.search(rf"type {label}(?: \([^)]*\))? (?:goes from|has) [^;]*?\(the largest holds (\d+) of its (\d+) "
                      rf"cells(?:; cells? ([\d, and]+) (?:is|are) outside it(?:, (each alone|in one other cluster|"
                      rf"in (\d+) other clusters))?)?\)", verdict)
        assert m, (label, verdict)
        assert [int(m.group(1)), int(m.group(2))] == [e["largest_cluster"], e["cells"]], (label, verdict, e)
        wanted = e["apart"]
        if wanted is not None and len(wanted) <= 5:
            assert m.group(3) is not None, (label, verdict, wanted)
            assert [int(x) for x in re.findall(r"\d+", m.group(3))] == wanted, (label, verdict, wanted)
            # The clusters they are in: GUDHI's components less the largest.
            others = e["clusters"] - 1
            said = {None: 1, "each alone": len(wanted), "in one other cluster": 1}.get(m.group(4))
            assert (int(m.group(5)) if m.group(5) else said) == others, (label, verdict, others)
            named += 1
        else:
            assert m.group(3) is None, (label, verdict, wanted)
    print(f"the verdict's largest clusters equal GUDHI's; {named} types' cells apart named as GUDHI finds them")


if __name__ == "__main__":
    main()
