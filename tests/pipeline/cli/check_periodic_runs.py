#!/usr/bin/python3
"""`medusa run` on periodic CompuCell3D runs (docs/MATH.md §8), end to end.

  check_periodic_runs.py hand MEDUSA WORKDIR
      hand-built planar runs periodic in x whose diagrams are derived on paper: a ring of cells that
      closes only across the seam, two cells that meet across the seam, a touching pair that crosses
      the seam mid-slab, and the ring translated along x (the same medusa).
  check_periodic_runs.py real MEDUSA WORKDIR RUN RADIUS
      a real periodic run: the Betti numbers of K_t at every frame equal those of GUDHI's exact alpha
      complex of the 3 x 3 tiled cell centres (CC3D's own cells.csv.gz) taken modulo the period, and the
      run translated along x and y gives the same medusa.
"""
import csv
import gzip
import io
import os
import shutil
import subprocess
import sys
from decimal import Decimal

import h5py


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def xml(dims, periodic):
    x, y, z = dims
    bounds = "".join("    <Boundary_%s>Periodic</Boundary_%s>\n" % (a, a) for a in periodic)
    return ('<CompuCell3D>\n  <Potts>\n    <Dimensions x="%s" y="%s" z="%s"/>\n%s  </Potts>\n'
            '</CompuCell3D>\n' % (x, y, z, bounds))


def make_run(folder, rows, dims=(10, 10, 1), periodic="x"):
    shutil.rmtree(folder, ignore_errors=True)
    lines = ["mcs,cell_id,type_id,xCOM,yCOM,zCOM"]
    lines += ["%d,%d,1,%s,%s,0" % (mcs, cell, x, y) for mcs, cell, x, y in rows]
    write(os.path.join(folder, "cells.csv"), "\n".join(lines) + "\n")
    write(os.path.join(folder, "Simulation", "run.xml"), xml(dims, periodic))
    return folder


def run(medusa, folder, out, radius, *extra):
    p = subprocess.run([medusa, "run", folder, "--radius", radius, "-o", out, "-q", *extra],
                       capture_output=True, text=True)
    assert p.returncode == 0, "medusa run %s: exit %d: %s" % (folder, p.returncode, p.stderr)
    with open(out[:-3] + ".diagrams.csv") as f:
        text = "".join(line for line in f if not line.startswith("#"))  # "# medusa run <id>"
    rows = list(csv.DictReader(io.StringIO(text)))
    return text, rows


def pairs(rows, dim, kind="all", direction="forward"):
    return sorted((r["birth"], r["death"]) for r in rows
                  if r["dimension"] == str(dim) and r["type"] == kind and r["direction"] == direction)


def hand(medusa, work):
    # Ring (L = 10 along x, radius 1.1): cells at x = 1, 3, 5, 7 (y alternating 0, 0.4) and E moving
    # from x = 8 to 9 over MCS 0..100. The ring closes across the seam when E meets the copy of the
    # cell at x = 1, i.e. 11 - x_E = 2 rho = 2.2: x_E = 8.8, MCS 80. No three cells are pairwise within
    # 2.2, so K is a graph; the cycle 1-3-5-7-E-1 winds once around the torus: one H1 class, born at
    # MCS 80, never filled. Read as open the seam edge never exists.
    ring = [(0, 1, "1", "0"), (0, 2, "3", "0.4"), (0, 3, "5", "0"), (0, 4, "7", "0.4"), (0, 5, "8", "0"),
            (100, 1, "1", "0"), (100, 2, "3", "0.4"), (100, 3, "5", "0"), (100, 4, "7", "0.4"),
            (100, 5, "9", "0")]
    folder = make_run(os.path.join(work, "ring"), ring)
    text, rows = run(medusa, folder, os.path.join(work, "ring.h5"), "1.1")
    assert pairs(rows, 1) == [("80", "inf")], pairs(rows, 1)
    assert pairs(rows, 0) == [("0", "inf")], pairs(rows, 0)
    _, open_rows = run(medusa, folder, os.path.join(work, "ring_open.h5"), "1.1", "--periodic-as-open")
    assert pairs(open_rows, 1) == [], pairs(open_rows, 1)
    with h5py.File(os.path.join(work, "ring.h5"), "r") as f:
        assert f.attrs["periodic_axes"].decode() == "x", f.attrs["periodic_axes"]
        lengths = [int(f.attrs["periodic_length_" + a]) for a in "xyz"]
        assert lengths == [10000000, 0, 0], lengths
    print("ok: ring closing across the seam: one H1 class born at MCS 80")
    # Its representative winds once along x (docs/MATH.md §8.8): the summary and `medusa classes` say so.
    p = subprocess.run([medusa, "run", folder, "--radius", "1.1", "-o", os.path.join(work, "ring_words.h5")],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    assert "1 of 1 loop of all cells wraps around the domain along x (not a hole in the tissue" in p.stdout, p.stdout
    p = subprocess.run([medusa, "classes", os.path.join(work, "ring.h5"), "--dim", "1", "--format", "csv"],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    classes = list(csv.DictReader(io.StringIO(p.stdout)))
    assert [r["wraps"] for r in classes] == ["x"], p.stdout
    print("ok: its loop wraps around the domain along x, in the summary and in medusa classes")
    p = subprocess.run([medusa, "info", os.path.join(work, "ring.h5")], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    assert "\ndomain: periodic along x (period 10 lattice units;" in p.stdout, p.stdout
    p = subprocess.run([medusa, "info", os.path.join(work, "ring_open.h5")], capture_output=True, text=True)
    assert "\ndomain: open (no periodic boundary)\n" in p.stdout, p.stdout
    print("ok: medusa info names the periodic axes and the period, and an open run as open")
    # `medusa at` draws the seam edge whole (docs/FORMAT.md): at MCS 100 cell 1 (x = 1) and cell 5
    # (x = 9) are 2 apart across the seam; the edge is drawn from cell 1, in the lattice, to a copy of
    # cell 5 beyond the seam at x = -1, an extra point marked beyond_seam. Every drawn edge is then
    # shorter than 2 rho = 2.2, and the four lattice edges are drawn between the cells themselves.
    vtk = os.path.join(work, "ring_at.vtk")
    p = subprocess.run([medusa, "at", os.path.join(work, "ring.h5"), "--time", "100", "-o", vtk],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    points, cells, data = read_vtk(vtk)
    ids, beyond = data["cell_id"], data["beyond_seam"]
    assert sorted(zip(ids, beyond, (round(x[0], 9) for x in points))) == [
        (1, 0, 1.0), (2, 0, 3.0), (3, 0, 5.0), (4, 0, 7.0), (5, 0, 9.0), (5, 1, -1.0)], (ids, beyond, points)
    edges = sorted(tuple(sorted((ids[a], ids[b]))) + (round(points[a][0], 9), round(points[b][0], 9))
                   for a, b in (c for c in cells if len(c) == 2))
    assert [e[:2] for e in edges] == [(1, 2), (1, 5), (2, 3), (3, 4), (4, 5)], edges
    for a, b in (c for c in cells if len(c) == 2):
        assert sum((points[a][i] - points[b][i]) ** 2 for i in range(3)) < 2.2 ** 2, (ids[a], ids[b])
    print("ok: medusa at draws the edge across the seam whole, to a copy of the cell beyond it")
    # medusa sweep runs on the torus too: at radius 1.1 the ring is closed at MCS 100 (b1 = 1, which
    # the run read as open never has); a radius with 4 x radius >= L is refused before any output.
    out = os.path.join(work, "ring_sweep")
    p = subprocess.run([medusa, "sweep", folder, "--radius", "1.1", "-o", out, "-q"], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    with open(out + ".crocker.csv") as f:
        crocker = [r for r in csv.DictReader(line for line in f if not line.startswith("#"))]
    assert [(r["time"], r["b1"]) for r in crocker if r["type"] == "all"] == [("0", "0"), ("100", "1")], crocker
    out = os.path.join(work, "ring_sweep_large")
    p = subprocess.run([medusa, "sweep", folder, "--radii", "1.1:2.6:1.4", "-o", out], capture_output=True, text=True)
    assert p.returncode == 4 and "radius 2.5 is too large" in p.stderr and p.stderr.count("\n") == 1, p.stderr
    assert not any(n.startswith("ring_sweep_large") for n in os.listdir(work)), os.listdir(work)
    print("ok: medusa sweep on the torus: the ring closes; a radius too large for the period is refused")

    # The same ring translated by 3 along x and wrapped: other cells are now the originals near the
    # seam, and the ring closes across another pair. The torus is the same: the same medusa.
    shifted = [(m, c, str((Decimal(x) + Decimal("3")) % 10), y) for m, c, x, y in ring]
    folder = make_run(os.path.join(work, "ring_shifted"), shifted)
    shifted_text, _ = run(medusa, folder, os.path.join(work, "ring_shifted.h5"), "1.1")
    same_medusa(os.path.join(work, "ring.h5"), os.path.join(work, "ring_shifted.h5"), text, shifted_text)
    print("ok: the ring translated along x gives the same medusa and diagrams")

    # Two cells meeting across the seam (radius 1): A at x = 0.5, B from x = 7 to 9 over MCS 0..100
    # (x_B = 7 + t / 50), their distance across the seam 10.5 - x_B reaches 2 at MCS 75: the edge
    # enters then, and A's and B's clusters merge (an H0 pair born 0, dead 75). C and D stay apart.
    meet = [(0, 1, "0.5", "5"), (0, 2, "7", "5"), (0, 3, "4", "1"), (0, 4, "4", "9"),
            (100, 1, "0.5", "5"), (100, 2, "9", "5"), (100, 3, "4", "1"), (100, 4, "4", "9")]
    folder = make_run(os.path.join(work, "meet"), meet)
    _, rows = run(medusa, folder, os.path.join(work, "meet.h5"), "1")
    assert pairs(rows, 0) == [("0", "75"), ("0", "inf"), ("0", "inf"), ("0", "inf")], pairs(rows, 0)
    print("ok: two cells meeting across the seam: their edge enters at MCS 75")

    # A touching pair (0.8 apart, radius 1) crossing the seam mid-slab: A 8.6 -> 9.6 -> 0.6,
    # B 9.4 -> 0.4 -> 1.4. Its edge stays in K the whole run: no event at all on the torus.
    cross = [(0, 1, "8.6", "5"), (0, 2, "9.4", "5"), (0, 3, "4", "1"), (0, 4, "4", "8"),
             (100, 1, "9.6", "5"), (100, 2, "0.4", "5"), (100, 3, "4", "1"), (100, 4, "4", "8"),
             (200, 1, "0.6", "5"), (200, 2, "1.4", "5"), (200, 3, "4", "1"), (200, 4, "4", "8")]
    folder = make_run(os.path.join(work, "cross"), cross)
    _, rows = run(medusa, folder, os.path.join(work, "cross.h5"), "1")
    with h5py.File(os.path.join(work, "cross.h5"), "r") as f:
        assert int(f.attrs["batch_count"]) == 1, int(f.attrs["batch_count"])  # batch 0 (t_0) alone
        assert int(f.attrs["cell_count"]) == 5, int(f.attrs["cell_count"])  # 4 vertices and the edge
    assert pairs(rows, 0) == [("0", "inf")] * 3, pairs(rows, 0)
    print("ok: a touching pair crossing the seam mid-slab: no event")

    # A cell born next to the seam (radius 1.05): A at x = 0.5 and B at 8.5 touch across the seam
    # (2 apart); N appears at MCS 100 at (9.5, 5.3), between them across the seam, where the edge AB
    # leaves K (N lies in its diametral disc, and the triangle ABN has circumradius (1 + 0.09) / 0.6 >
    # 1.05): the join ABN (docs/MATH.md §6.3) fills the loop A-N-B. The same cells translated by 3 lie
    # away from the seam; read as open they must give the same medusa as the periodic run.
    birth = [(m, c, x, y) for m in (0, 100, 200) for c, x, y in ((1, "0.5", "5"), (2, "8.5", "5"),
                                                                 (3, "4", "1"), (4, "4", "9"))]
    birth += [(m, 5, "9.5", "5.3") for m in (100, 200)]
    folder = make_run(os.path.join(work, "birth"), birth)
    text, rows = run(medusa, folder, os.path.join(work, "birth.h5"), "1.05")
    assert pairs(rows, 1) == [], pairs(rows, 1)
    away = [(m, c, str((Decimal(x) + 3) % 10), y) for m, c, x, y in birth]
    folder = make_run(os.path.join(work, "birth_away"), away)
    away_text, _ = run(medusa, folder, os.path.join(work, "birth_away.h5"), "1.05", "--periodic-as-open")
    same_medusa(os.path.join(work, "birth.h5"), os.path.join(work, "birth_away.h5"), text, away_text)
    with h5py.File(os.path.join(work, "birth.h5"), "r") as f:
        assert 2 in list(f["cells/kind"][:]), "no join cell"
    print("ok: a cell born across the seam: the same medusa as the open run away from the seam")

    # `medusa at` shows the positions wrapped into the lattice: at MCS 200 the pair is at x = 0.6 and
    # 1.4 (unwrapped 10.6 and 11.4).
    vtk = os.path.join(work, "cross_at.vtk")
    p = subprocess.run([medusa, "at", os.path.join(work, "cross.h5"), "--time", "200", "-o", vtk],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    lines = open(vtk).read().split("\n")
    start = next(i for i, line in enumerate(lines) if line.startswith("POINTS"))
    count = int(lines[start].split()[1])
    xs = sorted(round(float(lines[start + 1 + i].split()[0]), 9) for i in range(count))
    assert xs == [0.6, 1.4, 4.0, 4.0], xs
    print("ok: medusa at writes positions wrapped into the periodic lattice")


def read_vtk(path):
    """A legacy VTK file of `medusa at`: points, cells (point index lists), point data by name."""
    lines = open(path).read().split("\n")
    start = next(i for i, line in enumerate(lines) if line.startswith("POINTS"))
    count = int(lines[start].split()[1])
    points = [[float(v) for v in lines[start + 1 + i].split()] for i in range(count)]
    cstart = next(i for i, line in enumerate(lines) if line.startswith("CELLS"))
    cells = [[int(v) for v in lines[cstart + 1 + i].split()[1:]] for i in range(int(lines[cstart].split()[1]))]
    pstart = next(i for i, line in enumerate(lines) if line.startswith("POINT_DATA"))
    data, i = {}, pstart + 1
    while i < len(lines) and lines[i].startswith("SCALARS"):
        data[lines[i].split()[1]] = [int(v) for v in lines[i + 2:i + 2 + count]]
        i += 2 + count
    return points, cells, data


def cells_of(path):
    """Every medusa cell as (vertex tuple, kind, birth (batch, rank), death (batch, rank)): the exact
    content of a store; times are double approximations and are left out."""
    with h5py.File(path, "r") as f:
        c = f["cells"]
        off, verts = c["vertex_offset"][:], c["vertices"][:]
        columns = [c[name][:] for name in ("kind", "birth_batch", "birth_rank", "death_batch", "death_rank")]
        return sorted((tuple(int(v) for v in verts[off[i]:off[i + 1]]),) + tuple(int(col[i]) for col in columns)
                      for i in range(len(off) - 1))


def same_medusa(a, b, text_a, text_b):
    """Two stores hold the same cells with the same virtual times, and their diagrams the same pairs,
    byte for byte: event times are exact algebraic numbers, reported as a function of the time alone
    (docs/MATH.md §3.12), so a translated run reports the same doubles."""
    assert cells_of(a) == cells_of(b), "the medusa cells differ"
    rows_a = list(csv.DictReader(io.StringIO(text_a)))
    rows_b = list(csv.DictReader(io.StringIO(text_b)))
    assert len(rows_a) == len(rows_b), (len(rows_a), len(rows_b))
    for x, y in zip(rows_a, rows_b):
        for key in ("dimension", "type", "direction", "birth", "death"):
            assert x[key] == y[key], (x, y)


def betti(simplices, n):
    import gudhi
    st = gudhi.SimplexTree()
    for v in range(n):
        st.insert([v])
    for s in simplices:
        st.insert(list(s))
    st.compute_persistence(homology_coeff_field=2, persistence_dim_max=True)
    b = st.betti_numbers()
    return (b + [0, 0, 0])[:3]


def torus_complex(points, lengths, rho2):
    """The alpha complex at rho of the points on the torus (periodic x, y): GUDHI's exact alpha complex
    of the 3 x 3 tiled points, its simplices with R^2 <= rho^2 whose vertex of smallest index lies in
    the central tile, named by the indices of the points they are copies of."""
    import gudhi
    n = len(points)
    tiles = [(0, 0)] + [(i, j) for i in (-1, 0, 1) for j in (-1, 0, 1) if (i, j) != (0, 0)]
    tiled = [[x + i * lengths[0], y + j * lengths[1], z] for (i, j) in tiles for (x, y, z) in points]
    st = gudhi.AlphaComplex(points=tiled, precision="exact").create_simplex_tree()
    out = set()
    for s, value in st.get_filtration():
        if value > rho2:
            continue
        smallest = min(s, key=lambda v: v % n)
        if smallest >= n:
            continue
        image = tuple(sorted(v % n for v in s))
        assert len(set(image)) == len(image), "a simplex with two copies of one cell"
        out.add(image)
    return out


def real(medusa, work, folder, radius, source="csv"):
    text, _ = run(medusa, folder, os.path.join(work, "real.h5"), radius, "--source", source)
    p = subprocess.run([medusa, "curves", os.path.join(work, "real.h5"), "--frames-only", "-o",
                        os.path.join(work, "real")], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    curves = list(csv.DictReader(open(os.path.join(work, "real.curves.csv"))))
    L = (Decimal(50), Decimal(50))
    frames = {}
    with gzip.open(os.path.join(folder, "cells.csv.gz"), "rt") as f:
        for r in csv.DictReader(f):
            frames.setdefault(int(r["mcs"]), []).append(r)
    rho2 = float(Decimal(radius) ** 2)
    checked = 0
    # The VTK route reads the periodic voxel means of the snapshots (docs/MATH.md §8.1), which agree
    # with CC3D's centres in the CSV to the 10^-6 grid: the same Betti numbers, at the snapshots' MCS.
    measured_times = {float(c["time"]) for c in curves}
    for mcs in sorted(frames):
        if source == "vtk" and float(mcs) not in measured_times:
            continue
        rows = sorted(frames[mcs], key=lambda r: int(r["cell_id"]))
        points = [[float(Decimal(r["xCOM"]) % L[0]), float(Decimal(r["yCOM"]) % L[1]), float(r["zCOM"])]
                  for r in rows]
        types = [int(r["type_id"]) for r in rows]
        complex_ = torus_complex(points, (50.0, 50.0), rho2)
        got = {c["type"]: c for c in curves if float(c["time"]) == mcs}
        for kind in ["all"] + sorted({str(t) for t in types}):
            keep = [v for v in range(len(points)) if kind == "all" or types[v] == int(kind)]
            index = {v: i for i, v in enumerate(keep)}
            sub = [tuple(index[v] for v in s) for s in complex_ if all(v in index for v in s)]
            expected = betti(sub, len(keep))
            measured = [int(got[kind]["b0"]), int(got[kind]["b1"]), int(got[kind]["b2"])]
            assert measured == expected, "MCS %d type %s: medusa %s, GUDHI on the torus %s" % (
                mcs, kind, measured, expected)
            checked += 1
        print("ok: MCS %d: Betti numbers %s" % (mcs, [int(got["all"]["b%d" % d]) for d in range(3)]))
    assert checked > 0
    if source == "vtk":
        return

    # The run translated by (17, 4) lattice sites and wrapped: the same medusa.
    shifted = os.path.join(work, "shifted_run")
    shutil.rmtree(shifted, ignore_errors=True)
    shutil.copytree(os.path.join(folder, "Simulation"), os.path.join(shifted, "Simulation"))
    with gzip.open(os.path.join(folder, "cells.csv.gz"), "rt") as f:
        reader = csv.DictReader(f)
        rows = list(reader)
        fields = reader.fieldnames
    with open(os.path.join(shifted, "cells.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields, lineterminator="\n")
        w.writeheader()
        for r in rows:
            r["xCOM"] = str((Decimal(r["xCOM"]) + Decimal("17")) % L[0])
            r["yCOM"] = str((Decimal(r["yCOM"]) + Decimal("4")) % L[1])
            w.writerow(r)
    shifted_text, _ = run(medusa, shifted, os.path.join(work, "shifted.h5"), radius)
    same_medusa(os.path.join(work, "real.h5"), os.path.join(work, "shifted.h5"), text, shifted_text)
    print("ok: the run translated by (17, 4) gives the same medusa and diagrams")


def main():
    mode, medusa, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    if mode == "hand":
        hand(medusa, work)
    else:
        real(medusa, work, sys.argv[4], sys.argv[5], *sys.argv[6:7])


if __name__ == "__main__":
    main()
