#!/usr/bin/python3
"""The radius sweep `medusa report` computes from the store of a periodic run is the one on the torus
(docs/MATH.md §8): every Betti number at every frame, radius and type equals that of `medusa sweep` on
the CC3D run at the same radii. Radii with 4 x radius not below the shortest period (docs/MATH.md §8.3),
which `medusa sweep` refuses (exit 4), are left out of the report's sweep with one note on the page
naming them, and the rest of the report is written. The page's summary says, as `medusa run`'s does,
how many loops wrap around the domain.

  real: the first 3 frames of the bundled periodic run (50 x 50 x 40, periodic in x and y), store at
        radius 3, --sweep-radii 3, 3.5 and 13 (4 x 13 >= 50).
  hand: a planar run periodic in x with period 10, store at radius 2: the default radii are 1 to 3 in
        steps of 0.25; 2.5 (4 x 2.5 = 10, the boundary), 2.75 and 3 are left out. Then radii that are all
        too large: no sweep for the run, and the page says why.

Usage: check_report_sweep_periodic.py <medusa> <periodic CC3D run folder> <workdir>"""
import os
import shutil
import subprocess
import sys
from decimal import Decimal

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cli_checks import cut_run  # noqa: E402
from report_sweep_data import page_data, page_sweep, sweep_csv  # noqa: E402

medusa, run, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
os.chdir(work)
failures = []


def call(*args, code=0):
    result = subprocess.run([medusa, *args], capture_output=True, text=True)
    if result.returncode != code:
        sys.exit(f"medusa {' '.join(args)}: exit {result.returncode}, expected {code}\n{result.stderr}")
    return result


def check_equal(label, data, oracle, radii):
    """The page's one computed sweep has exactly `radii` and the values of medusa sweep's CSV."""
    if len(data["sweeps"]) != 1 or not data["sweeps"][0]["origin"].startswith("computed at report time"):
        failures.append(f"{label}: expected one sweep computed at report time, got "
                        f"{[w['origin'] for w in data['sweeps']]}")
        return
    sweep = data["sweeps"][0]
    if [Decimal(r) for r in sweep["radii"]] != [Decimal(r) for r in radii]:
        failures.append(f"{label}: swept radii {sweep['radii']}, expected {radii}")
    got, want = page_sweep(sweep), sweep_csv(oracle)
    if not want:
        failures.append(f"{label}: medusa sweep wrote no rows")
    if got != want:
        diff = sorted(k for k in set(got) | set(want) if got.get(k) != want.get(k))[:5]
        failures.append(f"{label}: report sweep differs from medusa sweep at {len(diff)}+ points, e.g. "
                        f"{[(k, got.get(k), want.get(k)) for k in diff]}")
    print(f"{label}: {len(got)} (radius, frame, type) points equal to medusa sweep's at radii {sweep['radii']}")


def check_note(label, data, left_out, period):
    """One note, naming the radii left out, the period and docs/MATH.md §8.3."""
    notes = [n for n in data["scale"]["notes"] if "left out" in n]
    if len(notes) != 1:
        failures.append(f"{label}: expected one note on radii left out, got {data['scale']['notes']}")
        return
    for word in [left_out, f"4 x radius below the shortest period, {period}", "§8.3"]:
        if word not in notes[0]:
            failures.append(f"{label}: the note does not say '{word}': {notes[0]}")
    print(f"{label}: note: {notes[0]}")


# 1. The real run, cut to its first 3 frames (CC3D's own centres) beside its CC3DML.
folder = "periodic_3frames"
cut_run(run, folder, 3)
summary = call("run", folder, "--radius", "3", "-o", "real.h5").stdout
result = call("report", "real.h5", "-o", "real.html", "--sweep-radii", "3:3.5:0.5", "--sweep-radii", "13:13:1")
call("sweep", folder, "--radii", "3:3.5:0.5", "-o", "real_oracle", "--quiet")
refused = call("sweep", folder, "--radius", "13", "-o", "real_refused", "--quiet", code=4)
data = page_data("real.html")
check_equal("real run", data, "real_oracle.crocker.csv", ["3", "3.5"])
check_note("real run", data, "radius 13 is left out", "50")
if "radius 13" not in result.stderr:
    failures.append(f"real run: no warning on stderr naming radius 13: {result.stderr}")
if data["scale"]["computed_radii"] != ["3", "3.5", "13"]:
    failures.append(f"real run: computed radii {data['scale']['computed_radii']}, expected 3, 3.5 and 13")
print(f"real run: medusa sweep --radius 13 refused: {refused.stderr.strip()}")
# The page says the run is periodic, with the periods of its CC3DML (50 x 50 lattice units along x, y).
domain = data["runs"][0]["facts"]["domain"]
if domain != "periodic along x, y (period 50 x 50 lattice units)":
    failures.append(f"real run: the page's domain is {domain!r}")
# The page's summary says, as `medusa run` does, how many loops wrap around the domain.
wrapping = [line for line in summary.splitlines() if line.startswith("periodic domain (x,y): ")]
if len(wrapping) != 1 or wrapping[0] not in data["runs"][0]["summary"].splitlines():
    failures.append(f"real run: the page's summary lacks medusa run's line on wrapping loops {wrapping}")

# 2. Hand-built: a ring of 5 cells of two types along x (period 10), the last one moving towards the
# seam, so that contacts across it appear at the larger radii.
os.makedirs("ring/Simulation")
with open("ring/Simulation/run.xml", "w") as f:
    f.write('<CompuCell3D>\n  <Potts>\n    <Dimensions x="10" y="10" z="1"/>\n'
            '    <Boundary_x>Periodic</Boundary_x>\n  </Potts>\n</CompuCell3D>\n')
cells = [(1, 1, "1", "0"), (2, 2, "3", "0.4"), (3, 1, "5", "0"), (4, 2, "7", "0.4")]
rows = ["mcs,cell_id,type_id,xCOM,yCOM,zCOM"]
for mcs, x in [(0, "8"), (100, "9")]:
    rows += [f"{mcs},{c},{t},{cx},{cy},0" for c, t, cx, cy in cells] + [f"{mcs},5,1,{x},0,0"]
with open("ring/cells.csv", "w") as f:
    f.write("\n".join(rows) + "\n")
call("run", "ring", "--radius", "2", "-o", "ring.h5", "--quiet")
call("report", "ring.h5", "-o", "ring.html", "-q")
kept = ["1", "1.25", "1.5", "1.75", "2", "2.25"]
call("sweep", "ring", *sum((["--radius", r] for r in kept), []), "-o", "ring_oracle", "--quiet")
for r in ["2.5", "2.75", "3"]:
    call("sweep", "ring", "--radius", r, "-o", "ring_refused", "--quiet", code=4)
data = page_data("ring.html")
check_equal("hand-built run, default radii", data, "ring_oracle.crocker.csv", kept)
check_note("hand-built run, default radii", data, "radii 2.5 to 3 are left out", "10")

# 3. Every radius too large: no sweep of the run, and the page says why instead of a CROCKER plot.
call("report", "ring.h5", "-o", "none.html", "--sweep-radii", "2.5:3:0.5", "-q")
data = page_data("none.html")
text = open("none.html").read()
if data["sweeps"] or 'id="crocker"' in text:
    failures.append("radii all too large: a sweep is shown")
check_note("radii all too large", data, "no radius sweep is computed for it, its radii 2.5 and 3 are left out", "10")
# The note (shown on the page by its script, checked above) says why; the static paragraph points to it.
if "No radius sweep is shown (the note above says why)" not in text:
    failures.append("radii all too large: the page does not point to the note saying why no sweep was computed")

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
