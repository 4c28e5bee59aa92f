#!/usr/bin/python3
"""Checks of `medusa run`'s reporting: progress on stderr (--progress, --quiet), --timings, --threads.

Usage: check_run_reporting.py <check> <medusa> <input cells.csv.gz> <work folder>
Each check runs the tool on the input at radius 3 in its own sub-folder of the work folder. stderr of
ctest is not a terminal, so without --progress no progress is expected.
"""
import json
import os
import pty
import re
import shutil
import subprocess
import sys

import h5py
import numpy


def run(medusa, folder, args):
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    result = subprocess.run([medusa, "run", "--force"] + args, cwd=folder, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"medusa run {' '.join(args)} failed ({result.returncode}): {result.stderr}")
    return result


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def check_progress_lists_stages_and_frames(medusa, data, work):
    err = run(medusa, work, [data, "-o", "run.h5", "--radius", "3", "--progress"]).stderr
    print(err)
    for needle in ["medusa: reading", "medusa: kinetic", "medusa store", "medusa: filtrations and reductions",
                   "medusa: exports", "events/s", "elapsed", "ETA ~"]:
        if needle not in err:
            fail(f"stderr lacks {needle!r}")
    for k in (1, 2, 3):
        if f"frame {k}/3" not in err:
            fail(f"stderr lacks 'frame {k}/3'")
    if "\r" in err:
        fail("a non-terminal stderr got in-place updates ('\\r')")
    order = [err.index(s) for s in ["medusa: reading", "frame 3/3", "medusa: filtrations and reductions",
                                   "medusa: exports"]]
    if order != sorted(order):
        fail(f"stages out of order: {order}")


def check_terminal_shows_progress_in_place(medusa, data, work):
    """stderr on a pseudo-terminal: progress without --progress, the kinetic line rewritten with '\r'."""
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    master, slave = pty.openpty()
    process = subprocess.Popen([medusa, "run", "--force", data, "-o", "run.h5", "--radius", "3"], cwd=work,
                               stdout=subprocess.PIPE, stderr=slave)
    os.close(slave)
    err = b""
    while True:
        try:
            chunk = os.read(master, 4096)
        except OSError:  # EIO once the child closed the terminal
            break
        if not chunk:
            break
        err += chunk
    stdout, _ = process.communicate()
    os.close(master)
    err = err.decode()
    print(err)
    if process.returncode != 0:
        fail(f"medusa run failed ({process.returncode})")
    for needle in ["medusa: reading", "\rmedusa: kinetic: frame 1/3", "frame 3/3", "medusa: filtrations and reductions",
                   "medusa: exports"]:
        if needle not in err:
            fail(f"terminal stderr lacks {needle!r}")
    if b"medusa: " in stdout or b"\r" in stdout or not stdout.startswith(b"cells: 251"):
        fail(f"progress on stdout: {stdout[:200]!r}")


def check_no_progress_without_flag(medusa, data, work):
    err = run(medusa, work, [data, "-o", "run.h5", "--radius", "3"]).stderr
    if err:
        fail(f"stderr not empty without --progress on a non-terminal: {err!r}")


def check_quiet_silences_progress(medusa, data, work):
    err = run(medusa, work, [data, "-o", "run.h5", "--radius", "3", "--progress", "--quiet"]).stderr
    if err:
        fail(f"stderr not empty with --quiet: {err!r}")


def check_stdout_same_with_progress(medusa, data, work):
    plain = run(medusa, os.path.join(work, "plain"), [data, "-o", "run.h5", "--radius", "3"]).stdout
    shown = run(medusa, os.path.join(work, "shown"), [data, "-o", "run.h5", "--radius", "3", "--progress"]).stdout
    if not plain or plain != shown:
        fail(f"stdout differs with --progress:\n{plain}\n---\n{shown}")


def persistence_group(path):
    """Every attribute and dataset of /persistence, as comparable Python values."""
    content = {}
    with h5py.File(path, "r") as f:
        group = f["persistence"]
        content["/"] = {k: (v.tobytes() if isinstance(v, numpy.ndarray) else v) for k, v in group.attrs.items()}

        def visit(name, obj):
            attrs = {k: (v.tobytes() if isinstance(v, numpy.ndarray) else v) for k, v in obj.attrs.items()}
            data = obj[()].tobytes() if isinstance(obj, h5py.Dataset) else None
            content[name] = (attrs, data)

        group.visititems(visit)
    return content


def check_threads_give_identical_diagrams(medusa, data, work):
    outputs = {}
    for threads in ("1", "2"):
        folder = os.path.join(work, "threads" + threads)
        stdout = run(medusa, folder, [data, "-o", "run.h5", "--radius", "3", "--threads", threads]).stdout
        with open(os.path.join(folder, "run.diagrams.csv"), "rb") as f:
            # The first line names the run's random id (docs/FORMAT.md): it differs by design.
            first, csv = f.read().split(b"\n", 1)
            if not first.startswith(b"# medusa run "):
                fail(f"run.diagrams.csv does not start with its run id: {first[:80]!r}")
        diagrams = subprocess.run([medusa, "diagrams", "run.h5"], cwd=folder, capture_output=True, text=True,
                                  check=True).stdout
        outputs[threads] = (stdout, csv, diagrams, persistence_group(os.path.join(folder, "run.h5")))
    one, two = outputs["1"], outputs["2"]
    print(f"diagram groups: {len(one[3]) - 1} objects; diagrams.csv: {len(one[1])} bytes")
    if len(one[3]) < 6 * 8:
        fail(f"/persistence holds too few objects: {sorted(one[3])}")
    for name, a, b in zip(["stdout", "diagrams.csv", "medusa diagrams", "/persistence"], one, two):
        if a != b:
            fail(f"{name} differs between --threads 1 and --threads 2")


EVENT_KINDS = ["flips23", "flips32", "flips22", "hull_flips", "radius_events", "insertions", "deletions"]


def check_planar_run_reports_its_2_2_flips(medusa, data, work):
    """A planar run flips 2-2: the summary, --timings' events and its event counts all include them."""
    out = run(medusa, work, [data, "-o", "run.h5", "--radius", "3", "--timings", "t.json"]).stdout
    print(out)
    with open(os.path.join(work, "t.json")) as f:
        t = json.load(f)
    c = t["event_counts"]
    print(c)
    if "dimension 2" not in out:
        fail("the input is not read as a planar run")
    if not (c["flips22"] > 0 and c["flips23"] == c["flips32"] == 0):
        fail(f"expected 2-2 flips only: {c}")
    if t["events"] != sum(c[k] for k in EVENT_KINDS):
        fail(f"events {t['events']} is not the sum of {c}")
    m = re.search(r"events: (\d+) flips \((\d+) 2-2, (\d+) hull\), (\d+) radius events, (\d+) insertions, "
                  r"(\d+) deletions", out)
    if not m:
        fail("no planar events line (flips 2-2 and hull) on stdout")
    flips, f22, hull, radius, insertions, deletions = (int(x) for x in m.groups())
    if (f22, hull, radius, insertions, deletions) != (c["flips22"], c["hull_flips"], c["radius_events"],
                                                      c["insertions"], c["deletions"]):
        fail(f"summary counts {m.groups()} differ from --timings {c}")
    if flips != f22 + hull or flips + radius + insertions + deletions != t["events"]:
        fail(f"summary: {flips} flips is not {f22} + {hull}, or the total is not {t['events']}")


def check_timings_file(medusa, data, work):
    # This script holds 256 MiB while medusa runs: Linux carries getrusage's peak across execve, and
    # the peak reported must still be medusa's own (a 3-frame run of 251 cells needs far less).
    ballast = bytearray(256 * 2**20)
    for i in range(0, len(ballast), 4096):
        ballast[i] = 1
    result = run(medusa, work, [data, "-o", "run.h5", "--radius", "3", "--timings", "t.json", "--threads", "2"])
    with open(os.path.join(work, "t.json")) as f:
        t = json.load(f)
    print(json.dumps(t, indent=1))
    stages = ["reading", "kinetic", "medusa_store", "filtrations", "reduction", "exports"]
    for key, total in (("stage_seconds", "total_seconds"), ("stage_cpu_seconds", "total_cpu_seconds")):
        if list(t[key]) != stages:
            fail(f"{key}: stages {list(t[key])}, expected {stages}")
        if any(not (v >= 0) for v in t[key].values()):
            fail(f"{key}: a negative stage time")
        if abs(sum(t[key].values()) - t[total]) > 1e-6 * max(1.0, t[total]):
            fail(f"{total} is not the sum of the stages")
    if (t["cells"], t["frames"], t["radius"], t["threads"]) != (251, 3, "3", 2):
        fail(f"run facts {t['cells']}, {t['frames']}, {t['radius']}, {t['threads']}")
    if not 0 < t["peak_rss_bytes"] < len(ballast):
        fail(f"peak RSS {t['peak_rss_bytes']} is not medusa's own")
    after = [t["peak_rss_bytes_after_stage"][s] for s in stages]
    if not (0 < after[0] and after == sorted(after) and after[-1] <= t["peak_rss_bytes"]):
        fail(f"peak RSS after each stage {after} is not a non-decreasing series up to {t['peak_rss_bytes']}")
    # The summary on stdout counts the same events: "events: N flips (...), R radius events, I insertions,
    # D deletions".
    m = re.search(r"events: (\d+) flips .*?, (\d+) radius events, (\d+) insertions, (\d+) deletions", result.stdout)
    if not m:
        fail("no events line on stdout")
    summary_events = sum(int(x) for x in m.groups())
    c = t["event_counts"]
    parts = sum(c[k] for k in EVENT_KINDS)
    if not (t["events"] == parts == summary_events and t["events"] > 0):
        fail(f"events {t['events']}, parts {parts}, summary {summary_events}")
    if t["store"]["bytes"] != os.path.getsize(os.path.join(work, "run.h5")):
        fail("store bytes differ from the file size")
    with h5py.File(os.path.join(work, "run.h5"), "r") as f:
        stored_cells = len(f["cells"]["id"])
    if stored_cells != t["store"]["cells"]:
        fail(f"store cells {t['store']['cells']}, the store holds {stored_cells}")
    at_frame = t["peak_rss_bytes_at_frame"]
    if not (len(at_frame) == 3 and at_frame == sorted(at_frame) and at_frame[-1] <= t["peak_rss_bytes"]):
        fail(f"peak RSS at frames {at_frame}: expected one per frame (3), non-decreasing")
    if len(t["kinetic_seconds_per_frame"]) != 2:
        fail("expected one kinetic time per slab (2)")


CHECKS = {
    "progress": check_progress_lists_stages_and_frames,
    "no_progress": check_no_progress_without_flag,
    "terminal": check_terminal_shows_progress_in_place,
    "quiet": check_quiet_silences_progress,
    "stdout": check_stdout_same_with_progress,
    "threads": check_threads_give_identical_diagrams,
    "timings": check_timings_file,
    "planar_events": check_planar_run_reports_its_2_2_flips,
}

if __name__ == "__main__":
    check, medusa, data, work = sys.argv[1:5]
    CHECKS[check](medusa, data, os.path.join(work, check))
    print("ok")
