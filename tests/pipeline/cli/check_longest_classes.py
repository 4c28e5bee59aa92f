"""The longest-lived filled loop and cavity the summary of `medusa run` names, against `medusa classes`
(run with /usr/bin/python3).

usage: check_longest_classes.py <medusa> <workdir> <run input> <radius or auto> <name> <expected lines>

Runs `medusa run` on the input into <workdir>/<name>.h5 and requires, for every "longest-lived filled"
line of the summary: its class id, cells (the first ones, and how many more), birth and death are those
of the first finite class of `medusa classes <store> --type T --dim k --format json` (sorted by
lifetime, longest first); every type and degree whose classes include a finite one has such a line;
and the two commands the line prints run and succeed: the listing sorts by time seen and its first
filled row (death not inf) is the class, and `medusa at` writes its VTK file. Fails unless
it checks exactly <expected lines> lines.
"""
import json
import os
import re
import shlex
import subprocess
import sys

if not __debug__:
    sys.exit("these checks are assert statements: run without -O and without PYTHONOPTIMIZE")

medusa, work, data, radius, name, expected_lines = sys.argv[1:7]


def run(args):
    result = subprocess.run(args, cwd=work, capture_output=True, text=True)
    assert result.returncode == 0, f"{' '.join(args)} failed ({result.returncode}): {result.stderr}"
    return result.stdout


def mcs(t):
    return f"{t:.6g}"


summary = run([medusa, "run", "--force", data, "-o", name + ".h5", "--radius", radius, "--quiet", "--threads", "1"])
print(summary)
planar = "dimension 2" in summary.splitlines()[0]
line_re = re.compile(r"  longest-lived filled (loop|cavity): class (\d+), cells ([\d, ]+?)(?: and (\d+) more)?, "
                     r"formed at MCS (\S+), filled at MCS (\S+) \(`(medusa classes [^`]+)`, `(medusa at [^`]+)`\)$")
checked = 0
groups = re.split(r"\n(?=all cells:|type \d+)", summary)
for group in groups[1:]:
    header = group.splitlines()[0]
    label = "all" if header.startswith("all cells") else re.match(r"type (\d+)", header).group(1)
    named = {}
    for line in group.splitlines():
        if line.startswith("  longest-lived"):
            m = line_re.match(line)
            assert m, f"{label}: unexpected line {line!r}"
            named[1 if m.group(1) == "loop" else 2] = m
    for k in (1, 2):
        listed = json.loads(run([medusa, "classes", name + ".h5", "--type", label, "--dim", str(k), "--format", "json"]))
        finite = [c for c in listed["classes"] if not c["essential"]]
        if not finite or (planar and k == 2):
            assert k not in named, f"{label}: a longest-lived class of degree {k}, but none is finite"
            continue
        assert k in named, f"{label}: no longest-lived class of degree {k}, but {len(finite)} are finite"
        m, top = named[k], finite[0]
        assert int(m.group(2)) == top["id"], f"{label} H{k}: class {m.group(2)}, medusa classes {top['id']}"
        shown = [int(x) for x in m.group(3).split(", ")]
        more = int(m.group(4) or 0)
        assert shown == top["cells"][:len(shown)] and len(shown) + more == len(top["cells"]), \
            f"{label} H{k}: cells {shown} and {more} more, medusa classes {top['cells']}"
        assert (m.group(5), m.group(6)) == (mcs(top["birth"]), mcs(top["death"])), \
            f"{label} H{k}: MCS {m.group(5)} to {m.group(6)}, medusa classes {top['birth']} to {top['death']}"
        listing = run([medusa] + shlex.split(m.group(7))[1:])
        assert "--sort seen" in m.group(7), f"{label} H{k}: `{m.group(7)}` does not sort by time seen"
        rows = [r.split("\t") for r in listing.splitlines()[1:]]
        first_filled = next(i for i, r in enumerate(rows) if r[3] != "inf")
        assert int(rows[first_filled][0]) == top["id"], \
            f"{label} H{k}: the first filled row of `{m.group(7)}` is class {rows[first_filled][0]}, not {top['id']}"
        at = shlex.split(m.group(8))
        run([medusa] + at[1:])
        assert os.path.getsize(os.path.join(work, at[-1])) > 0, f"{label} H{k}: `{m.group(8)}` wrote nothing"
        checked += 1
        print(f"{label} H{k}: class {top['id']} with {len(top['cells'])} cells agrees with medusa classes; "
              f"row {first_filled + 1} of {len(rows)} of `{m.group(7)}`")
assert checked == int(expected_lines), f"checked {checked} lines, expected {expected_lines}"
