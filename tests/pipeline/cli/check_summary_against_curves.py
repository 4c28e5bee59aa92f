"""The summary of `medusa run` against `medusa curves --frames-only` (run with /usr/bin/python3).

usage: check_summary_against_curves.py <medusa> <workdir> <run input> <radius or auto> <name>

Runs `medusa run` on the input into <workdir>/<name>.h5, then `medusa curves --frames-only`, and requires
for the whole tissue and every cell type: the summary's clusters at the first and last frame equal b0
of the curves' rows at those frames; its loops and cavities still open at the end (plus those the
summary says bound in space-time) equal b1 and b2 at the last frame; and, unless cells left the complex
at the first frame, the loops and cavities present at the first frame equal b1 and b2 there (when cells
left, the count the summary gives beside them for the complex just after it does). Fails if it
compares nothing.
"""
import csv
import re
import subprocess
import sys

if not __debug__:
    sys.exit("these checks are assert statements: run without -O and without PYTHONOPTIMIZE")

medusa, work, data, radius, name = sys.argv[1:6]


def run(args):
    result = subprocess.run(args, cwd=work, capture_output=True, text=True)
    assert result.returncode == 0, f"{' '.join(args)} failed ({result.returncode}): {result.stderr}"
    return result.stdout


summary = run([medusa, "run", "--force", data, "-o", name + ".h5", "--radius", radius, "--quiet", "--threads", "1"])
print(summary)
run([medusa, "curves", name + ".h5", "--frames-only", "-o", name])
with open(f"{work}/{name}.curves.csv") as f:
    rows = list(csv.DictReader(f))
times = sorted({float(r["time"]) for r in rows})
first, last = times[0], times[-1]
curve = {(r["type"], float(r["time"])): r for r in rows}
planar = "dimension 2" in summary.splitlines()[0]
left_at_first = "only left the complex at that instant" in summary

groups = re.split(r"\n(?=all cells:|type \d+)", summary)
compared = 0
for group in groups[1:]:
    header = group.splitlines()[0]
    label = "all" if header.startswith("all cells") else re.match(r"type (\d+)", header).group(1)
    c = re.search(r"clusters: (\d+) at MCS \S+, (\d+) at MCS", group)
    assert c, f"no cluster line for {label}"
    b_first, b_last = curve[(label, first)], curve[(label, last)]
    assert int(c.group(1)) == int(b_first["b0"]), f"{label}: clusters at first frame {c.group(1)} vs b0 {b_first['b0']}"
    assert int(c.group(2)) == int(b_last["b0"]), f"{label}: clusters at end {c.group(2)} vs b0 {b_last['b0']}"
    compared += 2
    for k, word in ((1, "loops"), (2, "cavities")):
        if k == 2 and planar:
            continue
        lines = group.splitlines()
        start = next(i for i, line in enumerate(lines) if line.startswith(f"  {word}: "))
        end = next((i for i in range(start + 1, len(lines)) if not lines[i].startswith("    ")), len(lines))
        part = "\n".join(lines[start:end])[len(f"  {word}: "):]
        present = int(re.match(r"(\d+) present", part).group(1))
        # Cells that leave at the first frame can make the classes present then differ from b_k just
        # after it; the summary then says b_k beside them.
        after = re.search(r"the complex just after MCS \S+, without the cells present at that frame only, has (\d+)",
                          part)
        assert after is None or left_at_first, f"{label}: {word} differ at the first frame, but no cell left there"
        at_first = int(after.group(1)) if after else present
        assert at_first == int(b_first[f"b{k}"]), f"{label}: {word} at first frame {at_first} vs b{k} {b_first[f'b{k}']}"
        compared += 1
        still = sum(int(n) for n in re.findall(r"\((\d+) still open", part))
        whole = re.search(r"the complex at MCS \S+ has (\d+)", part)
        at_end = int(whole.group(1)) if whole else still
        assert at_end == int(b_last[f"b{k}"]), f"{label}: {word} open at the end {at_end} vs b{k} {b_last[f'b{k}']}"
        compared += 1
assert compared > 0, "nothing compared"
print(f"{compared} numbers of the summary equal the curves")
