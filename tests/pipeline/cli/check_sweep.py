#!/usr/bin/python3
"""`medusa sweep` against separate runs: for each radius, the CROCKER rows (radius,time,type,b0,b1,b2)
equal the rows of `medusa run --radius R` followed by `medusa curves --frames-only` at every frame and
type; a radius at which no two cells ever meet is warned about.

Usage: check_sweep.py <medusa> <run folder> <workdir>"""
import csv
import io
import os
import shutil
import subprocess
import sys

medusa, run, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
os.chdir(work)


def call(*args):
    result = subprocess.run([medusa, *args], capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"{' '.join(args)}: exit {result.returncode}\n{result.stderr}")
    return result


def number(text):
    return float(text)


# Two radii from a range (exact decimal steps), and one of them given again alone: swept once.
sweep = call("sweep", run, "--radii", "2.5:3:0.5", "--radius", "3.0", "-o", "sw", "--threads", "2")
rows = list(csv.DictReader(open("sw.crocker.csv")))
radii = sorted({r["radius"] for r in rows}, key=float)
assert radii == ["2.5", "3"], radii
summary = open("sw.sweep.txt").read().splitlines()
assert sum(line.startswith("radius ") for line in summary) == 2, summary
assert os.path.getsize("sw.crocker.svg") > 0

checked = summaries = 0
for radius in radii:
    call("run", run, "--radius", radius, "-o", f"r{radius}.h5", "--quiet")
    call("curves", f"r{radius}.h5", "--frames-only", "-o", f"r{radius}")
    expected = {(number(r["time"]), r["type"]): (r["b0"], r["b1"], r["b2"])
                for r in csv.DictReader(open(f"r{radius}.curves.csv"))}
    got = {(number(r["time"]), r["type"]): (r["b0"], r["b1"], r["b2"]) for r in rows if r["radius"] == radius}
    assert expected, f"no curves rows at radius {radius}"
    assert set(got) == set(expected), (radius, sorted(set(got) ^ set(expected))[:5])
    for key, value in expected.items():
        assert got[key] == value, f"radius {radius}, MCS {key[0]}, type {key[1]}: sweep {got[key]}, run+curves {value}"
        checked += 1
    # The summary line of this radius counts what the forward diagrams of the stored run hold: H0
    # classes born at the first frame and essential ones, H1 and H2 classes and the finite ones.
    line = next(l for l in summary if l.startswith(f"radius {radius}:"))
    pairs = list(csv.DictReader(io.StringIO(call("barcode", f"r{radius}.h5", "--format", "csv", "--filtration",
                                                 "forward").stdout)))
    t0 = min(number(r["time"]) for r in rows)
    for label, words in [("all", "all cells"), ("1", "type 1"), ("2", "type 2")]:
        mine = [p for p in pairs if p["type"] == label]
        essential = lambda p: p["death"] == "inf"
        start = sum(1 for p in mine if p["dimension"] == "0" and number(p["birth"]) == t0)
        end = sum(1 for p in mine if p["dimension"] == "0" and essential(p))
        loops = [p for p in mine if p["dimension"] == "1"]
        cavities = [p for p in mine if p["dimension"] == "2"]
        want = (f"{words} {start} -> {end} cluster{'' if end == 1 else 's'}, {len(loops)} "
                f"loop{'' if len(loops) == 1 else 's'} ({sum(not essential(p) for p in loops)} filled), "
                f"{len(cavities)} {'cavity' if len(cavities) == 1 else 'cavities'} "
                f"({sum(not essential(p) for p in cavities)} filled)")
        assert want in line, f"radius {radius}: expected '{want}' in '{line}'"
        summaries += 1
    print(line)
print(f"{checked} (time, type) Betti triples and {summaries} summaries equal at {len(radii)} radii")
assert checked > 0 and summaries > 0

# No edge at any time: every cell stays alone, and the sweep says so.
lonely = call("sweep", run, "--radius", "0.5", "-o", "lonely", "--threads", "1")
assert "radius 0.5: no two cells are ever within the radius" in lonely.stderr, lonely.stderr
assert "warning: radius 0.5" in open("lonely.sweep.txt").read()
print("a radius without edges is warned about")
