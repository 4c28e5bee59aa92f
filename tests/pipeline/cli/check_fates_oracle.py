"""The summary's split of never-filled loops and cavities against a brute-force Z/2 computation
(run with /usr/bin/python3).

usage: check_fates_oracle.py <medusa> <workdir> <run input> <radius or auto> <name> [threads]

Runs `medusa run` on the input (on `threads` threads, 1 by default) into <workdir>/<name>.h5 and reads the store with h5py alone
(docs/FORMAT.md). For the whole medusa and each cell type's sub-medusa M, and k = 1, 2 (k = 1 only for a
planar run), it computes with its own Z/2 elimination (Python integers as bit columns) the subspaces
A = image of H_k(L_first) and B = image of H_k(L_end) in H_k(M), where L_first holds the cells born at
or before the batch that reaches the first frame and L_end those dying at the final batch, as
dim(Z_k(L) + B_k(M)) - dim B_k(M), and dim(A + B) likewise; then requires the summary's "never
filled" line to say: dim A of those at the first frame, of them dim(A ∩ B) still open and the rest
broke open; dim H_k(M) - dim A formed later, of them dim(A + B) - dim A still open and dim H_k(M) -
dim(A + B) broke open (docs/MATH.md §7.12). Where some are still open, the command the summary names
for them must list, as the rows born at t_end with death -inf, dim B classes whose representatives
lie in L_end (rings and shells of cells at the end) and are independent in H_k(M): a basis of B.
Fails if it compares nothing.
"""
import json
import re
import shlex
import subprocess
import sys

import h5py
import numpy as np

if not __debug__:
    sys.exit("these checks are assert statements: run without -O and without PYTHONOPTIMIZE")

medusa, work, data, radius, name = sys.argv[1:6]
threads = sys.argv[6] if len(sys.argv) > 6 else "1"
result = subprocess.run([medusa, "run", "--force", data, "-o", name + ".h5", "--radius", radius, "--quiet",
                         "--threads", threads], cwd=work, capture_output=True, text=True)
assert result.returncode == 0, f"medusa run failed ({result.returncode}): {result.stderr}"
summary = result.stdout
planar = "dimension 2" in summary.splitlines()[0]

with h5py.File(f"{work}/{name}.h5", "r") as f:
    c = f["cells"]
    ids = c["id"][:]
    off, verts = c["vertex_offset"][:].astype(np.int64), c["vertices"][:]
    foff, facets = c["facet_offset"][:].astype(np.int64), c["facets"][:]
    bb, db = c["birth_batch"][:], c["death_batch"][:]
    types = f["input"]["cell_type"][:]
    ev = f["events"]
    frames = len(f["input"]["frame_times"][:])
    slab, at_frame, index = ev["batch_slab"][:], ev["batch_at_frame"][:], ev["batch_index"][:]
    end_batch = int(max(db))
    t_end = float(f["input"]["frame_times"][-1])
row_of = np.empty(len(ids), dtype=np.int64)
row_of[ids] = np.arange(len(ids))
# The batch that reaches the first frame: the last frame batch of slab 0 (docs/FORMAT.md, /events);
# a one-frame run reaches it at the end.
first = [int(b) for b, s, a in zip(index, slab, at_frame) if s == 0 and a]
first_batch = max(first) if first and frames != 1 else end_batch
dim_of = (off[1:] - off[:-1]) - 1


def rank_and_reducer():
    """An incremental Z/2 basis keyed by highest bit: add(v) returns True if v was independent."""
    pivots = {}

    def add(v):
        while v:
            top = v.bit_length() - 1
            if top not in pivots:
                pivots[top] = v
                return True
            v ^= pivots[top]
        return False
    return add, pivots


def boundary(r, index_of):
    col = 0
    for fid in facets[foff[r]:foff[r + 1]]:
        col ^= 1 << index_of[row_of[fid]]
    return col


def cycles(rows, index_k, index_km1, k):
    """A basis of Z_k of the k-cells `rows` (their facets among index_km1): kernel by elimination."""
    pivots = {}  # highest bit -> (boundary, combination)
    basis = []
    for r in rows:
        b = boundary(r, index_km1) if k > 0 else 0
        comb = 1 << index_k[r]
        while b:
            top = b.bit_length() - 1
            if top not in pivots:
                pivots[top] = (b, comb)
                break
            pb, pc = pivots[top]
            b ^= pb
            comb ^= pc
        if not b:
            basis.append(comb)
    return basis


compared, pointers = 0, 0
groups = re.split(r"\n(?=all cells:|type \d+)", summary)
for group in groups[1:]:
    header = group.splitlines()[0]
    cell_type = -1 if header.startswith("all cells") else int(re.match(r"type (\d+)", header).group(1))
    member = [r for r in range(len(ids))
              if cell_type < 0 or all(types[v] == cell_type for v in verts[off[r]:off[r + 1]])]
    for k, word in ((1, "loops"), (2, "cavities")):
        if k == 2 and planar:
            continue
        cells_k = [r for r in member if dim_of[r] == k]
        cells_km1 = [r for r in member if dim_of[r] == k - 1]
        cells_kp1 = [r for r in member if dim_of[r] == k + 1]
        index_k = {r: j for j, r in enumerate(cells_k)}
        index_km1 = {r: j for j, r in enumerate(cells_km1)}
        add, _ = rank_and_reducer()
        boundaries = sum(1 for r in cells_kp1 if add(boundary(r, index_k)))
        z_m = len(cycles(cells_k, index_k, index_km1, k))
        h_m = z_m - boundaries
        z_first = cycles([r for r in cells_k if bb[r] <= first_batch], index_k, index_km1, k)
        z_end = cycles([r for r in cells_k if db[r] >= end_batch], index_k, index_km1, k)
        dim_a = sum(1 for z in z_first if add(z))
        dim_a_plus_b = dim_a + sum(1 for z in z_end if add(z))
        add2, _ = rank_and_reducer()
        for r in cells_kp1:
            add2(boundary(r, index_k))
        dim_b = sum(1 for z in z_end if add2(z))
        dim_ab = dim_a + dim_b - dim_a_plus_b
        lines = group.splitlines()
        start = next(i for i, line in enumerate(lines) if line.startswith(f"  {word}: "))
        never = next((line for line in lines[start + 1:start + 4] if line.startswith("    never filled: ")), None)
        label = f"{name} {header.rstrip(':')} {word}"
        if never is None:
            assert h_m == 0, f"{label}: no never-filled line, but H_{k}(M) has dimension {h_m}"
            compared += 1
            continue
        m = re.match(r"    never filled: (\d+) of those at MCS \S+(?: \((\d+) still open(?: at MCS \S+)?, (\d+) broke "
                     r"open\))?, (\d+) formed later(?: \((\d+) still open(?: at MCS \S+)?, (\d+) broke open\))?$", never)
        assert m, f"{label}: unexpected line {never!r}"
        got = [int(x) if x is not None else 0 for x in m.groups()]
        expected = [dim_a, dim_ab, dim_a - dim_ab, h_m - dim_a, dim_a_plus_b - dim_a, h_m - dim_a_plus_b]
        assert got == expected, f"{label}: summary {got}, brute force {expected} (dim A {dim_a}, dim B {dim_b})"
        print(f"{label}: {got} agrees (dim A {dim_a}, dim B {dim_b}, dim A+B {dim_a_plus_b}, H {h_m})")
        compared += 1
        if dim_b > 0:
            pointer = lines[lines.index(never) + 1]
            m = re.match(r"    the (\d+) still open, each with the cells around it at MCS \S+: `medusa (.*)`, the rows "
                         r"born at \S+ with death -inf$", pointer)
            assert m and int(m.group(1)) == dim_b, f"{label}: no pointer to the {dim_b} still open: {pointer!r}"
            listed = subprocess.run([medusa, *shlex.split(m.group(2)), "--format", "json"], cwd=work,
                                    capture_output=True, text=True)
            assert listed.returncode == 0, f"{label}: {m.group(2)}: {listed.stderr}"
            open_now = [c for c in json.loads(listed.stdout)["classes"] if c["essential"] and c["birth"] == t_end]
            assert len(open_now) == dim_b, f"{label}: {len(open_now)} rows born at the end, dim B {dim_b}"
            add3, _ = rank_and_reducer()
            for r in cells_kp1:
                add3(boundary(r, index_k))
            for c in open_now:
                rows = [int(row_of[x]) for x in c["medusa_cycle"]]
                assert all(r in index_k and db[r] >= end_batch for r in rows), \
                    f"{label}: class {c['id']} has a cell not in the end complex"
                cycle = 0
                for r in rows:
                    cycle ^= 1 << index_k[r]
                assert add3(cycle), f"{label}: class {c['id']} depends on the others"
            print(f"{label}: the {dim_b} still open are listed as cycles of the end complex, a basis of B")
            pointers += 1
assert compared > 0, "nothing compared"
print(f"{pointers} lists of the classes still open at the end checked")
print(f"{compared} never-filled splits of the summary equal the brute-force ones")
