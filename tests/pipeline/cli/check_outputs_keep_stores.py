"""No command writes a report, plot or table over an HDF5 file: the store a run computed is never
replaced by a derived output (README, "Exit codes of `medusa`").

usage: check_outputs_keep_stores.py <medusa> <small run csv> <workdir>

Each command whose output names an HDF5 file (a store, a copy of it under another name, one behind a
512-byte user block) exits 2 with one line naming it, leaves every file as it was and creates none;
`curves`, whose second output is the HDF5 file, leaves none of its four outputs behind.
Run with /usr/bin/python3.
"""
import hashlib
import os
import shutil
import sys

from cli_checks import run_logged as run

if not __debug__:
    sys.exit("these checks are assert statements: run without -O and without PYTHONOPTIMIZE")


def state(folder):
    out = {}
    for name in sorted(os.listdir(folder)):
        with open(os.path.join(folder, name), "rb") as f:
            out[name] = hashlib.sha256(f.read()).hexdigest()
    return out


def main(medusa, csv, work):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    assert run([medusa, "run", csv, "-o", "s.h5"], work).returncode == 0
    store = os.path.join(work, "s.h5")
    for copy in ["copy.h5", "copy.html", "copy.vtk", "p.curves.svg", "q.type1.h0.distances.csv"]:
        shutil.copyfile(store, os.path.join(work, copy))
    with open(os.path.join(work, "block.svg"), "wb") as out, open(store, "rb") as f:
        out.write(b"\0" * 512 + f.read())  # a user block of 512 bytes: the superblock at byte 512
    cases = [
        (["report", "s.h5", "-o", "s.h5"], "s.h5"),
        (["report", "s.h5", "-o", "copy.html"], "copy.html"),
        (["barcode", "s.h5", "--format", "svg", "-o", "copy.h5"], "copy.h5"),
        (["barcode", "s.h5", "--format", "svg", "-o", "block.svg"], "block.svg"),
        (["classes", "s.h5", "-o", "copy.h5"], "copy.h5"),
        (["at", "s.h5", "--time", "0", "-o", "copy.vtk"], "copy.vtk"),
        (["curves", "s.h5", "-o", "p"], "p.curves.svg"),
        (["compare", "s.h5", "s.h5", "-o", "q"], "q.type1.h0.distances.csv"),
    ]
    before = state(work)
    for args, name in cases:
        result = run([medusa] + args, work)
        lines = result.stderr.strip().splitlines()
        assert result.returncode == 2, f"{args}: exit {result.returncode}, expected 2"
        assert lines and lines[-1] == f"medusa: output {name} is an HDF5 file (a medusa store?); it is not replaced: choose another name", result.stderr
        assert state(work) == before, f"{args} changed or created files"
    # The same commands write as usual elsewhere.
    assert run([medusa, "report", "s.h5", "-o", "r.html"], work).returncode == 0
    assert run([medusa, "barcode", "s.h5", "--format", "svg", "-o", "b.svg"], work).returncode == 0
    print(f"{len(cases)} refusals, the store and its copies unchanged")


if __name__ == "__main__":
    main(*sys.argv[1:])
