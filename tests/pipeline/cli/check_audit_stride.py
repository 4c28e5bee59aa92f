"""`medusa run --audit --audit-stride N` (run with /usr/bin/python3).

usage: check_audit_stride.py <medusa> <planar cells.csv.gz> <3D cells.csv.gz> <work dir>

On the cells with ids 1 to 40 of the first 3 frames of each run (a planar and a 3D one, small enough
to audit after every batch in seconds), at radius 3:
* the audit does not change results: the stores written without --audit, with --audit and with
  --audit --audit-stride 3 hold the same datasets and attributes (store_digest.py, which leaves out
  the run id and the command line);
* the engine audits once at the start, once at every frame that starts a slab (F - 1 of F frames)
  and after every N-th batch of events (KineticOptions::audit_stride, counted over the whole run):
  F + floor(E / N) audits for E batches of events. --audit (N = 1) gives E, and --audit-stride 3
  must then give F + floor(E / 3), fewer; the count is in --timings ("audit") and on stderr;
* --audit-stride 3 alone audits as --audit --audit-stride 3 (it implies --audit).
Exit 1 names the first difference.
"""
import gzip
import json
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from store_digest import digest_lines  # noqa: E402

if not __debug__:
    sys.exit("these checks are assert statements: run without -O and without PYTHONOPTIMIZE")


def restrict(source, target, frames, last_id):
    """The rows of `source` on its first `frames` frames for cells 1 .. last_id."""
    with gzip.open(source, "rt") as f:
        lines = f.read().splitlines()
    kept = sorted({int(line.split(",")[0]) for line in lines[1:]})[:frames]
    rows = [line for line in lines[1:] if int(line.split(",")[0]) in kept and int(line.split(",")[1]) <= last_id]
    with open(target, "w") as f:
        f.write("\n".join([lines[0]] + rows) + "\n")


def run(binary, work, name, cells, *options):
    """(store digest lines, the --timings "audit" record, frames, stderr) of one `medusa run`."""
    store, timings = os.path.join(work, name + ".h5"), os.path.join(work, name + ".json")
    out = subprocess.run([binary, "run", "--force", cells, "-o", store, "--radius", "3", "--timings", timings,
                          *options], capture_output=True, text=True)
    assert out.returncode == 0, f"{name}: exit {out.returncode}: {out.stderr}"
    with open(timings) as f:
        record = json.load(f)
    return digest_lines(store), record["audit"], record["frames"], out.stderr


def audits_on_stderr(stderr):
    m = re.search(r"^medusa: audit: (\d+) audits? of the kinetic structure passed", stderr, re.M)
    assert m, f"no audit line on stderr: {stderr}"
    return int(m.group(1))


def check(binary, work, name, source):
    cells = os.path.join(work, name + ".csv")
    restrict(source, cells, 3, 40)
    plain, off, frames, _ = run(binary, work, name + "_plain", cells)
    every, audit1, _, stderr1 = run(binary, work, name + "_audit", cells, "--audit")
    strided, audit3, _, stderr3 = run(binary, work, name + "_stride3", cells, "--audit", "--audit-stride", "3")
    assert frames == 3, (name, frames)
    assert plain == every, f"{name}: --audit changed the store"
    assert plain == strided, f"{name}: --audit --audit-stride 3 changed the store"
    assert off == {"on": False, "stride": 0, "audits": 0, "compared_with_cgal": 0}, (name, off)
    assert audit1["on"] and audit1["stride"] == 1 and audit3["on"] and audit3["stride"] == 3, (audit1, audit3)
    event_batches = audit1["audits"] - frames
    assert event_batches >= 30, f"{name}: only {event_batches} batches of events: too few to tell strides apart"
    expected = frames + event_batches // 3
    assert audit3["audits"] == expected, f"{name}: {audit3['audits']} audits with stride 3, expected {expected}"
    assert audit3["audits"] < audit1["audits"]
    assert audits_on_stderr(stderr1) == audit1["audits"] and audits_on_stderr(stderr3) == audit3["audits"], name
    print(f"{name}: {frames} frames, {event_batches} batches of events: {audit1['audits']} audits with --audit, "
          f"{audit3['audits']} with --audit-stride 3 ({frames} + {event_batches} // 3); stores equal")
    return cells, audit3


def main():
    binary, planar, spatial, work = sys.argv[1:5]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    cells, audit3 = check(binary, work, "planar", planar)
    check(binary, work, "spatial", spatial)
    _, implied, _, _ = run(binary, work, "planar_implied", cells, "--audit-stride", "3")
    assert implied == audit3, f"--audit-stride 3 alone: {implied}, with --audit: {audit3}"
    print(f"--audit-stride 3 alone: {implied['audits']} audits, as with --audit")


main()
