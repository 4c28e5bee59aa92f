"""Shortened class representatives (docs/MATH.md §7.13) against the unshortened ones, by brute force.

usage: check_shortened_classes.py <medusa> <run input> <radius> <work folder>

Runs `medusa run` twice on the input, plainly and with --shorten-representatives, and requires:
* the shortened store's representatives pass every check of check_classes_oracle.py (a cycle with its
  birth cell last, in the prefix, not a boundary before the death, one after it; never for an
  essential class), and say they are shortened;
* `medusa classes --shorten` on the plain store lists exactly the shortened store's cycles, for the
  whole medusa's forward diagram (stored) and its reverse one (computed on demand);
* each shortened cycle z' is no longer than the unshortened z, and z + z' is a boundary of the
  (k+1)-cells entered before the death cell (anywhere, for an essential class): a Z/2 rank test of its
  own, with the boundaries eliminated in filtration order;
* some cycle is strictly shorter (otherwise nothing is tested).
"""
import json
import os
import subprocess
import sys

import h5py

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import check_classes_oracle as oracle  # noqa: E402

if not __debug__:
    sys.exit("these checks are assert statements: run without -O and without PYTHONOPTIMIZE")


def classes(medusa, store, *options):
    out = subprocess.run([medusa, "classes", store, "--format", "json", *options], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout)


def filtration(s, forward):
    off, verts = s.off, s.verts
    members = list(range(len(s.ids)))
    tup = lambda r: tuple(int(x) for x in verts[off[r]:off[r + 1]])
    if forward:
        key = lambda r: (int(s.bb[r]), int(s.br[r]), int(off[r + 1] - off[r]), tup(r))
    else:
        key = lambda r: (-int(s.db[r]), -int(s.dr[r]), int(off[r + 1] - off[r]), tup(r))
    members.sort(key=key)
    return members, {r: j for j, r in enumerate(members)}


def check_homologous(s, forward, pairs):
    """pairs: (dim, death cell or None, plain cycle, shortened cycle, label); z + z' must reduce to zero
    against the boundaries of the (k+1)-cells entered before the death (all of them if essential)."""
    members, index = filtration(s, forward)
    dim_of = lambda r: int(s.off[r + 1] - s.off[r]) - 1

    def bits(cycle):
        z = 0
        for x in cycle:
            z ^= 1 << index[s.row_of[x]]
        return z
    for kdim in {p[0] for p in pairs}:
        boundaries = oracle.Boundaries()
        waiting = {}
        for dim, death, plain, short, label in pairs:
            if dim == kdim:
                limit = len(members) if death is None else index[s.row_of[death]]
                waiting.setdefault(limit, []).append((bits(plain) ^ bits(short), label))
        for j, r in enumerate(members + [None]):
            for z, label in waiting.get(j, []):
                assert boundaries.reduce(z) == 0, f"{label}: shortened cycle not homologous to the unshortened one"
            if r is not None and dim_of(r) == kdim + 1:
                col = 0
                for fid in s.facets[s.foff[r]:s.foff[r + 1]]:
                    col ^= 1 << index[s.row_of[fid]]
                boundaries.add(col)


def main():
    medusa, run_input, radius, work = sys.argv[1:5]
    os.makedirs(work, exist_ok=True)
    plain_store, short_store = os.path.join(work, "plain.h5"), os.path.join(work, "shortened.h5")
    for store, extra in ((plain_store, []), (short_store, ["--shorten-representatives"])):
        made = subprocess.run([medusa, "run", "--force", run_input, "--radius", radius, "--quiet", "-o", store, *extra],
                              capture_output=True, text=True)
        assert made.returncode == 0, made.stderr
    with h5py.File(short_store, "r") as f:
        s = oracle.Store(f)
        p = f["persistence"]
        checked = 0
        for name in p.attrs["diagram_order"].decode().split(","):
            g = p[name]
            if "classes" in g:
                assert int(g["classes"].attrs["shortened"]) == 1, f"{name}: not marked shortened"
                checked += oracle.check_classes(s, name, g.attrs["direction"].decode() == "forward",
                                                int(g.attrs["type"]), oracle.stored_entries(s, g))
        assert checked > 0, "no stored class"
        print(f"{checked} stored shortened representatives pass the oracle's checks")
    with h5py.File(plain_store, "r") as f:
        assert int(f["persistence/forward_all/classes"].attrs["shortened"]) == 0
        s = oracle.Store(f)
    shorter = 0
    for direction in ("forward", "reverse"):
        plain = classes(medusa, plain_store, "--filtration", direction)
        short = classes(medusa, plain_store, "--filtration", direction, "--shorten")
        stored = classes(medusa, short_store, "--filtration", direction)
        assert not plain["shortened"] and short["shortened"], direction
        by_id = {c["id"]: c for c in short["classes"]}
        assert sorted(by_id) == sorted(c["id"] for c in plain["classes"]), direction
        if direction == "forward":
            assert stored["shortened"]
            assert [c["medusa_cycle"] for c in stored["classes"]] == [c["medusa_cycle"] for c in short["classes"]]
        else:
            # On demand, reverse: the oracle's checks on the shortened cycles.
            entries = [{"id": c["id"], "dim": c["dimension"], "essential": c["essential"],
                        "birth_cell": c["medusa_birth_cell"], "death_cell": c["medusa_death_cell"],
                        "cycle": c["medusa_cycle"], "cluster": None} for c in short["classes"]]
            oracle.check_classes(s, "reverse_all (shortened on demand)", False, -1, entries)
        pairs = []
        for c in plain["classes"]:
            z, z2 = c["medusa_cycle"], by_id[c["id"]]["medusa_cycle"]
            label = f"{direction} class {c['id']} (degree {c['dimension']})"
            assert len(z2) <= len(z), f"{label}: longer after shortening"
            assert z2[-1] == c["medusa_birth_cell"], f"{label}: the birth cell is not last"
            shorter += len(z2) < len(z)
            if c["dimension"] > 0:
                pairs.append((c["dimension"], None if c["essential"] else c["medusa_death_cell"], z, z2, label))
        check_homologous(s, direction == "forward", pairs)
        before = sum(len(c["medusa_cycle"]) for c in plain["classes"] if c["dimension"] > 0)
        after = sum(len(by_id[c["id"]]["medusa_cycle"]) for c in plain["classes"] if c["dimension"] > 0)
        print(f"{direction}: {len(pairs)} loops and shells, {before} cells before shortening, {after} after")
    assert shorter > 0, "no representative got shorter: nothing tested"
    print(f"{shorter} representatives strictly shorter, all homologous to the unshortened ones")


if __name__ == "__main__":
    main()
