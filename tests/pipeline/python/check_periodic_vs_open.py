"""The real periodic run on the torus against the same run read as open (run with /usr/bin/python3).

usage: check_periodic_vs_open.py <medusa> <periodic CC3D run folder> <radius> <work dir>
       (PYTHONPATH must hold <build dir>/python)

`medusa run` writes the run on the torus and with --periodic-as-open (the unwrapped trajectories of
docs/MATH.md §8.2 as an open run). At every frame, K(t+) of the two (store.K_at) may differ only at
simplices with a vertex o near which the two geometries differ: a cell p within 2 rho of o on the
torus (minimum image) whose unwrapped offset from o is not that minimum image. Away from such
vertices both complexes see the same cells at the same offsets, and a simplex's membership depends
only on the cells within 2 rho of one of its vertices (docs/MATH.md §8.4, the lemma), so it is the
same. The two must differ somewhere (cells meet across the seams of this run). Exact decimals.
Exit 1 names the first difference.
"""
import csv
import gzip
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
from decimal import Decimal

import medusa

if not __debug__:
    sys.exit("these checks are assert statements: run without -O and without PYTHONOPTIMIZE")


def periods(folder):
    sim = os.path.join(folder, "Simulation")
    for name in sorted(os.listdir(sim)):
        if name.endswith(".xml"):
            potts = ET.parse(os.path.join(sim, name)).getroot().find("Potts")
            dims = potts.find("Dimensions")
            out = []
            for a in "xyz":
                b = potts.find("Boundary_" + a)
                out.append(Decimal(dims.get(a)) if b is not None and b.text.strip() == "Periodic" else None)
            return out
    raise AssertionError("no CC3DML in " + sim)


def image(d, L):
    """The minimum image of d in [-L/2, L/2) (docs/MATH.md §8.1)."""
    if L is None:
        return d
    m = d % L  # Decimal's % keeps the sign of d
    if m < 0:
        m += L
    return m - L if m >= L / 2 else m


def main():
    binary, folder, radius, work = sys.argv[1:5]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    L = periods(folder)
    assert any(L), "the run has no periodic axis"
    stores = {}
    for name, extra in (("torus", []), ("open", ["--periodic-as-open"])):
        out = os.path.join(work, name + ".h5")
        p = subprocess.run([binary, "run", folder, "--radius", radius, "-o", out, "-q", *extra],
                           capture_output=True, text=True)
        assert p.returncode == 0, p.stderr
        stores[name] = medusa.open(out)

    frames = {}
    with gzip.open(os.path.join(folder, "cells.csv.gz"), "rt") as f:
        for r in csv.DictReader(f):
            frames.setdefault(int(r["mcs"]), {})[int(r["cell_id"])] = [Decimal(r[k]) for k in ("xCOM", "yCOM", "zCOM")]
    # Unwrapped positions (docs/MATH.md §8.2): each step is the minimum image of the wrapped step.
    unwrapped, previous = {}, {}
    for mcs in sorted(frames):
        unwrapped[mcs] = {}
        for cell, x in frames[mcs].items():
            if cell in previous:
                prev_wrapped, prev_unwrapped = previous[cell]
                u = [pu + image(xi - pw, La) for xi, pw, pu, La in zip(x, prev_wrapped, prev_unwrapped, L)]
            else:
                u = list(x)
            unwrapped[mcs][cell] = u
            previous[cell] = (x, u)

    reach2 = (2 * Decimal(radius)) ** 2
    differing_total = 0
    for mcs in sorted(frames):
        torus = {tuple(s) for s in stores["torus"].K_at(mcs)}
        open_ = {tuple(s) for s in stores["open"].K_at(mcs)}
        differing = torus ^ open_
        if not differing:
            continue
        pos, unw = frames[mcs], unwrapped[mcs]
        seam_cells = set()
        for o in pos:
            for p in pos:
                if p == o:
                    continue
                m = [image(a - b, La) for a, b, La in zip(pos[p], pos[o], L)]
                if sum(c * c for c in m) <= reach2 and m != [a - b for a, b in zip(unw[p], unw[o])]:
                    seam_cells.add(o)
                    break
        for s in sorted(differing):
            assert any(v in seam_cells for v in s), (
                "MCS %d: simplex %s is %s but no cell of it meets another across a seam" %
                (mcs, list(s), "only on the torus" if s in torus else "only in the open run"))
        differing_total += len(differing)
        print("ok: MCS %d: %d simplices differ, all at %d cells meeting others across a seam" %
              (mcs, len(differing), len(seam_cells)))
    assert differing_total > 0, "the torus and the open run never differ: no contact across a seam was seen"


if __name__ == "__main__":
    main()
