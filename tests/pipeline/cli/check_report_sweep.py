#!/usr/bin/python3
"""The radius sweep `medusa report` computes from a store equals `medusa sweep` on the CC3D run at the
same radii (every Betti number at every frame, radius and type); its default radii follow the
documented rule (r/2 to 3r/2 in steps of r/8, rounded half up to 0.01, r the store's radius, derived
here in exact decimals); --no-sweep computes none; a run of more event times than --max-sweep-events gets
no default sweep but a note on the page and on stderr saying why and how to get one, while radii given
with --sweep-radii are computed whatever its size, and --max-sweep-events 0 lifts the limit; a sweep
file beside the store is read instead.

Usage: check_report_sweep.py <medusa> <CC3D run folder> <workdir>"""
import os
import re
import shutil
import subprocess
import sys
from decimal import ROUND_HALF_UP, Decimal

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from report_sweep_data import page_data, page_sweep, sweep_csv  # noqa: E402

medusa, run, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
os.chdir(work)
failures = []


def call(*args):
    result = subprocess.run([medusa, *args], capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"medusa {' '.join(args)}: exit {result.returncode}\n{result.stderr}")
    return result


RADIUS = "3"
call("run", run, "--radius", RADIUS, "-o", "run.h5", "--quiet")

# 1. Given radii: the report's values equal medusa sweep's.
call("report", "run.h5", "-o", "given.html", "--sweep-radii", "2.5:3.5:0.5", "-q")
call("sweep", run, "--radii", "2.5:3.5:0.5", "-o", "oracle", "--quiet")
data = page_data("given.html")
if len(data["sweeps"]) != 1 or not data["sweeps"][0]["origin"].startswith("computed at report time"):
    failures.append(f"given radii: expected one sweep computed at report time, got {[w['origin'] for w in data['sweeps']]}")
else:
    got, want = page_sweep(data["sweeps"][0]), sweep_csv("oracle.crocker.csv")
    if not want:
        failures.append("medusa sweep wrote no rows")
    if got != want:
        diff = sorted(k for k in set(got) | set(want) if got.get(k) != want.get(k))[:5]
        failures.append(f"report sweep differs from medusa sweep at {len(diff)}+ points, e.g. "
                        f"{[(k, got.get(k), want.get(k)) for k in diff]}")
    print(f"given radii: {len(got)} (radius, frame, type) points compared with medusa sweep")

# 2. Default radii: the documented rule.
call("report", "run.h5", "-o", "default.html", "-q")
r = Decimal(RADIUS)
expected = [(r * k / 8).quantize(Decimal("0.01"), rounding=ROUND_HALF_UP) for k in range(4, 13)]
data = page_data("default.html")
radii = [Decimal(x) for x in data["sweeps"][0]["radii"]] if data["sweeps"] else []
if radii != expected:
    failures.append(f"default radii {radii}, expected {expected}")
call("sweep", run, *sum((["--radius", str(x)] for x in expected), []), "-o", "oracle_default", "--quiet")
if data["sweeps"] and page_sweep(data["sweeps"][0]) != sweep_csv("oracle_default.crocker.csv"):
    failures.append("report sweep at the default radii differs from medusa sweep")
text = open("default.html").read()
if "computed at report time" not in text or not re.search(r"at nine radii from half to one and a half times", text):
    failures.append("default.html: does not say that and how the radii were chosen")
print(f"default radii: {[str(x) for x in radii]}")

# 3. --no-sweep: none computed, and the page says how to get one.
call("report", "run.h5", "-o", "none.html", "--no-sweep")
data = page_data("none.html")
if data["sweeps"] or 'id="crocker"' in open("none.html").read():
    failures.append("--no-sweep: a sweep is shown")

# 4. A run larger than --max-sweep-events: no default sweep, one note on the page and on stderr that
# give the run's event times (its batch records, /events/batch_index) and the ways to a sweep.
import h5py  # noqa: E402
with h5py.File("run.h5", "r") as f:
    event_times = len(f["events/batch_index"])
if event_times < 2:
    failures.append(f"run.h5 has {event_times} event times: the limit cannot be tested")
limit = event_times - 1
result = call("report", "run.h5", "-o", "large.html", "--max-sweep-events", str(limit))
data = page_data("large.html")
notes = [n for n in data["scale"]["notes"] if "no radius sweep is computed" in n]
if data["sweeps"]:
    failures.append("--max-sweep-events below the run's event times: a sweep was computed")
if len(notes) != 1:
    failures.append(f"--max-sweep-events: expected one note on the page, got {data['scale']['notes']}")
else:
    for word in [f"{event_times} event times", f"--max-sweep-events {limit}", "medusa sweep", "--sweep-radii",
                 "run.crocker.csv", "--max-sweep-events 0"]:
        if word not in notes[0]:
            failures.append(f"--max-sweep-events: the note does not say '{word}': {notes[0]}")
    if notes[0] not in result.stderr:
        failures.append(f"--max-sweep-events: the note is not on stderr: {result.stderr}")
    print(f"large run: {notes[0]}")
for extra, what in [(["--max-sweep-events", str(event_times)], "a limit equal to the run's event times"),
                    (["--max-sweep-events", "0"], "--max-sweep-events 0"),
                    (["--max-sweep-events", "1", "--sweep-radii", "2:3:1"], "radii given")]:
    call("report", "run.h5", "-o", "limit.html", "-q", *extra)
    data = page_data("limit.html")
    if not data["sweeps"] or not data["sweeps"][0]["origin"].startswith("computed at report time"):
        failures.append(f"{what}: no sweep computed")
    if any("no radius sweep is computed" in n for n in data["scale"]["notes"]):
        failures.append(f"{what}: the page says no sweep is computed")

# 5. A sweep file beside the store is read, not recomputed.
call("sweep", run, "--radii", "2:3:1", "-o", "run", "--quiet")
result = call("report", "run.h5", "-o", "filed.html")
data = page_data("filed.html")
if not data["sweeps"] or not data["sweeps"][0]["origin"].startswith("read from") or "radius sweep of" in result.stderr:
    failures.append(f"sweep file beside the store not used: {[w['origin'] for w in data['sweeps']]}")
elif page_sweep(data["sweeps"][0]) != sweep_csv("run.crocker.csv"):
    failures.append("sweep file beside the store shown with other values")

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
