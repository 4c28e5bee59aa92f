"""`medusa classes --sort seen`, the order of the report's tables, recomputed from its own JSON (run
with /usr/bin/python3).

usage: check_classes_seen.py <medusa> <workdir> <run input>

Runs the input, then lists the forward classes of every type and degree sorted by lifetime and by time
seen. Requires: the same classes either way; the seen order non-increasing in the time seen worked out
from each class's fields (a filled class: death - birth; a never-filled one: `ring.broke_at` - birth if
its ring broke open, t_end - birth if whole at the end, -inf if never whole; a cluster that never joins:
t_end - birth), ties by lifetime; each class's `seen` field that time (null for -inf), and the table's
`seen` column the same, row by row ("never whole" for null); and, so that the check is not empty, a ring that broke open ranked
below a filled class that outlived it in the tissue, though above it by lifetime.
"""
import json
import math
import os
import subprocess
import sys

import h5py

if not __debug__:
    sys.exit("these checks are assert statements: run without -O and without PYTHONOPTIMIZE")

medusa, work, data = sys.argv[1:4]
os.makedirs(work, exist_ok=True)


def call(*args):
    result = subprocess.run([medusa, *args], cwd=work, capture_output=True, text=True)
    assert result.returncode == 0, f"{args}: {result.stderr}"
    return result.stdout


call("run", "--force", data, "-o", "seen.h5", "-q")
with h5py.File(os.path.join(work, "seen.h5"), "r") as f:
    t_end = float(f["input"]["frame_times"][-1])
    types = sorted(set(int(t) for t in f["input"]["cell_type"][:]))


def seen(c):
    if not c["essential"]:
        return c["lifetime"]
    ring = c.get("ring")
    if c["dimension"] == 0 or ring is None or ring["state"] == "whole at the end":
        return t_end - c["birth"]
    if ring["state"] == "broke":
        return ring["broke_at"] - c["birth"]
    assert ring["state"] == "never whole", ring
    return -math.inf


def lifetime(c):
    return math.inf if c["essential"] else c["lifetime"]


checked, overtaken = 0, 0
for label in ["all"] + [str(t) for t in types]:
    for dim in (0, 1, 2):
        args = ["classes", "seen.h5", "--type", label, "--dim", str(dim), "--format", "json"]
        by_seen = json.loads(call(*args, "--sort", "seen"))["classes"]
        by_life = json.loads(call(*args, "--sort", "lifetime"))["classes"]
        assert sorted(c["id"] for c in by_seen) == sorted(c["id"] for c in by_life), (label, dim)
        for c in by_seen:
            expected = seen(c)
            assert (c["seen"] is None) if expected == -math.inf else math.isclose(c["seen"], expected, rel_tol=1e-12, abs_tol=1e-9), (label, dim, c["id"], c["seen"], expected)
        table = call("classes", "seen.h5", "--type", label, "--dim", str(dim), "--sort", "seen").splitlines()
        column = table[0].split("\t").index("seen")
        rows = [line.split("\t") for line in table[1:]]
        assert [int(r[0]) for r in rows] == [c["id"] for c in by_seen], (label, dim)
        for r, c in zip(rows, by_seen):
            shown = "never whole" if c["seen"] is None else "%.6g" % c["seen"]
            assert r[column] == shown, (label, dim, c["id"], r[column], shown)
        keys = [(seen(c), lifetime(c)) for c in by_seen]
        assert keys == sorted(keys, reverse=True), (label, dim, keys[:10])
        checked += len(keys)
        rank = {c["id"]: i for i, c in enumerate(by_life)}
        for i, c in enumerate(by_seen):
            if c["essential"] and (c.get("ring") or {}).get("state") == "broke":
                overtaken += sum(1 for d in by_seen[:i] if not d["essential"] and rank[d["id"]] > rank[c["id"]])
assert checked > 0, "no class listed"

# `medusa at --class` on a loop never whole at one time and on one whole from its birth until it broke open: it says how many of
# the representative's contacts are not in the complex at that time, counted here from `medusa at --time`.
import re
loops = json.loads(call("classes", "seen.h5", "--type", "1", "--dim", "1", "--format", "json", "--sort", "seen"))["classes"]
said = {}
whole_at_birth = next(c for c in loops if c.get("ring") and c["ring"]["state"] == "broke" and c["ring"]["broke_at"] > c["birth"])
never_whole = [c for c in loops if c["seen"] is None]
# The first and the ten with the most contacts (some of them made again later between the same cells).
for c in [whole_at_birth] + never_whole[:1] + sorted(never_whole, key=lambda c: -len(c["simplices"]))[:10]:
    out = call("at", "seen.h5", "--type", "1", "--class", str(c["id"]), "-o", "class.vtk")
    call("at", "seen.h5", "--type", "1", "--time", repr(c["birth"]), "-o", "at.csv")
    with open(os.path.join(work, "at.csv")) as f:
        next(f)
        present = {tuple(sorted(int(v) for v in line.strip().split(",")[1:] if v)) for line in f}
    missing = sum(1 for s in c["simplices"] if len(s) >= 2 and tuple(sorted(s)) not in present)
    m = re.search(r"; (\d+) of them (?:is|are) not in the complex at MCS", out)
    assert (int(m.group(1)) if m else 0) == missing, (c["id"], out, missing)
    said[c["id"]] = missing
assert said[whole_at_birth["id"]] == 0 and all(said[c["id"]] > 0 for c in never_whole[:1]), said
print(f"medusa at --class: contacts not in the complex at the class's birth, as counted here: {said}")
assert overtaken > 0, "no broken ring ranked below a filled class it outranks by lifetime: nothing was checked"
print(f"{checked} classes in the order of their time seen; {overtaken} broken rings below filled classes that "
      f"outlived them in the tissue")
