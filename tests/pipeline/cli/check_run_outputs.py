"""`medusa run` trusts nothing in -o, and a mix of two runs' outputs is refused (docs/FORMAT.md,
"One result per run").

usage: check_run_outputs.py unsafe <medusa> <small run csv> <workdir>
       check_run_outputs.py written <medusa> <small run csv> <workdir>
       check_run_outputs.py stale <medusa> <small run csv> <workdir>
       check_run_outputs.py mixed <medusa> <small run csv> <plot_store.py> <workdir>

unsafe: -o naming the input file, a file the input folder's reader reads, a device, a FIFO, a folder,
        a dangling link or a link to a device is refused with exit 2 and one line, and nothing is
        changed or created; -o through a link to a regular file writes that file and keeps the link.
written: the -o of every other command that writes one file (classes, barcode, at, report) likewise:
        a device, a FIFO (at once, not waiting for a reader) or a link to a device is refused with
        exit 2 and left as it was; through a link to a regular file the file is written.
stale:  `medusa run --force` over a store names the files other commands wrote from it under their
        default names (curves, sorting measures, report), which it leaves as they were.
mixed:  a diagrams CSV or barcode SVG beside a store from another run makes `medusa info` and
        examples/plot_store.py exit 5.
Run with /usr/bin/python3.
"""
import hashlib
import os
import shutil
import stat
import subprocess
import sys

from cli_checks import run_logged

if not __debug__:
    sys.exit("these checks are assert statements: run without -O and without PYTHONOPTIMIZE")


run = run_logged


def digest(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def listing(folder):
    return sorted(os.listdir(folder))


def refused(result, fragment):
    lines = result.stderr.strip().splitlines()
    assert result.returncode == 2, f"exit {result.returncode}, expected 2"
    assert len(lines) == 1 and lines[0].startswith("medusa: "), result.stderr
    assert fragment in lines[0], f"'{fragment}' not in {lines[0]}"


def check_unsafe(medusa, csv, work):
    shutil.copyfile(csv, os.path.join(work, "in.csv.gz"))
    os.makedirs(os.path.join(work, "folder", "LatticeData"))
    shutil.copyfile(csv, os.path.join(work, "folder", "cells.csv.gz"))
    os.mkfifo(os.path.join(work, "fifo.h5"))
    os.makedirs(os.path.join(work, "dir.h5"))
    os.symlink("/dev/null", os.path.join(work, "null_link.h5"))
    os.symlink(os.path.join(work, "dir.h5"), os.path.join(work, "dir_link.h5"))
    os.symlink(os.path.join(work, "nowhere.h5"), os.path.join(work, "dangling.h5"))
    before = {p: digest(os.path.join(work, p)) for p in ["in.csv.gz", "folder/cells.csv.gz"]}
    names = listing(work)
    cases = [
        (["in.csv.gz", "-o", "in.csv.gz"], "is the input"),
        (["in.csv.gz", "-o", "./in.csv.gz"], "is the input"),
        (["folder", "-o", "folder/cells.csv.gz"], "inside the input folder"),
        (["folder", "-o", "folder/LatticeData/x.h5"], "inside the input folder"),
        (["in.csv.gz", "-o", "/dev/null"], "is a device"),
        (["in.csv.gz", "-o", "fifo.h5"], "is a FIFO"),
        (["in.csv.gz", "-o", "dir.h5"], "is a folder"),
        (["in.csv.gz", "-o", "null_link.h5"], "symbolic link to a device"),
        (["in.csv.gz", "-o", "dir_link.h5"], "symbolic link to a folder"),
        (["in.csv.gz", "-o", "dangling.h5"], "symbolic link to nothing"),
        # A side output's name is checked too: `in.h5` writes in.diagrams.csv, here a FIFO.
        (["in.csv.gz", "-o", "side.h5"], "side.diagrams.csv is a FIFO"),
    ]
    os.mkfifo(os.path.join(work, "side.diagrams.csv"))
    names = listing(work)
    for args, fragment in cases:
        # --force: an existing output is replaced only if it is safe to (the refusals come after it).
        refused(run([medusa, "run", *args, "--force", "--radius", "3", "-q"], work), fragment)
        assert listing(work) == names, f"files changed: {listing(work)} (was {names})"
        assert {p: digest(os.path.join(work, p)) for p in before} == before, "an input changed"
        assert stat.S_ISFIFO(os.lstat(os.path.join(work, "fifo.h5")).st_mode)
        assert os.path.islink(os.path.join(work, "null_link.h5"))
        assert stat.S_ISCHR(os.stat("/dev/null").st_mode)
        assert not os.path.exists("/dev/null.diagrams.csv") and not os.path.exists("/dev/null.barcode.svg")
    # Through a link to a regular file: the file is written, the link stays a link.
    with open(os.path.join(work, "target.h5"), "w") as f:
        f.write("old\n")
    os.symlink("target.h5", os.path.join(work, "link.h5"))
    result = run([medusa, "run", "in.csv.gz", "-o", "link.h5", "--force", "--radius", "3", "-q"], work)
    assert result.returncode == 0, result.stderr
    assert os.path.islink(os.path.join(work, "link.h5"))
    assert run([medusa, "info", "target.h5"], work).returncode == 0
    print(f"{len(cases)} unsafe outputs refused")


def check_written(medusa, csv, work):
    assert run([medusa, "run", csv, "-o", "s.h5", "--radius", "3", "-q"], work).returncode == 0
    # Each command and the ending its -o needs.
    commands = {
        "classes": (["classes", "s.h5", "--type", "all", "--dim", "1", "--format", "csv"], ".csv"),
        "barcode": (["barcode", "s.h5"], ".txt"),
        "at": (["at", "s.h5", "--time", "100"], ".vtk"),
        "report": (["report", "s.h5", "-q"], ".html"),
    }
    for ext in {e for _, e in commands.values()}:
        os.mkfifo(os.path.join(work, "fifo" + ext))
        os.symlink("/dev/null", os.path.join(work, "null_link" + ext))
    names = listing(work)
    checked = 0
    for name, (args, ext) in commands.items():
        cases = [("fifo" + ext, "is a FIFO"), ("null_link" + ext, "symbolic link to a device")]
        if name != "at":  # at's -o must end in .vtk or .csv, which /dev/null does not
            cases.append(("/dev/null", "is a device"))
        for output, fragment in cases:
            # A FIFO opened for writing waits for a reader: the timeout turns a hang into a failure.
            result = subprocess.run([medusa, *args, "-o", output], cwd=work, capture_output=True, text=True,
                                    timeout=120)
            print("$", name, output, "->", result.returncode, result.stderr.strip()[-300:])
            refused(result, fragment)
            assert listing(work) == names, f"files changed: {listing(work)} (was {names})"
            assert stat.S_ISFIFO(os.lstat(os.path.join(work, "fifo" + ext)).st_mode)
            assert os.path.islink(os.path.join(work, "null_link" + ext))
            assert stat.S_ISCHR(os.stat("/dev/null").st_mode)
            checked += 1
        # Through a link to a regular file: the file is written, the link stays a link.
        target, link = f"{name}.target", f"{name}.link{ext}"
        with open(os.path.join(work, target), "w") as f:
            f.write("old\n")
        os.symlink(target, os.path.join(work, link))
        result = run([medusa, *args, "-o", link], work)
        assert result.returncode == 0, result.stderr
        assert os.path.islink(os.path.join(work, link))
        with open(os.path.join(work, target)) as f:
            assert f.read() != "old\n", f"{name} did not write through {link}"
        names = listing(work)
    assert checked == 3 * len(commands) - 1
    # The commands whose -o is a prefix: a device or FIFO named as the prefix, or a prefix ending in '/',
    # would have them write /dev/null.curves.csv (as root, into /dev) or hidden files.
    os.mkfifo(os.path.join(work, "fifo"))
    os.makedirs(os.path.join(work, "out"))
    names = listing(work)
    prefixed = {
        "curves": (["curves", "s.h5"], ".curves.csv"),
        "sweep": (["sweep", "s.h5", "--radius", "3"], ".crocker.csv"),
        "compare": (["compare", "s.h5", "s.h5"], ".distances.csv"),
    }
    for name, (args, first) in prefixed.items():
        for prefix, fragment in [("/dev/null", "is a device"), ("fifo", "is a FIFO"), ("out/", "ends in '/'")]:
            result = subprocess.run([medusa, *args, "-o", prefix], cwd=work, capture_output=True, text=True, timeout=120)
            print("$", name, "-o", prefix, "->", result.returncode, result.stderr.strip()[-300:])
            refused(result, fragment)
            assert prefix + first in result.stderr, f"{name}: the refusal does not name {prefix}{first}"
            assert listing(work) == names and not os.listdir(os.path.join(work, "out")), f"files changed: {listing(work)}"
            assert not [f for f in os.listdir("/dev") if f.startswith("null.")], "an output was written in /dev"
            assert stat.S_ISCHR(os.stat("/dev/null").st_mode)
            checked += 1
    assert checked == 3 * len(commands) - 1 + 3 * len(prefixed)
    print(f"{checked} unsafe outputs refused")


def check_stale(medusa, csv, work):
    assert run([medusa, "run", csv, "-o", "s.h5", "--radius", "3", "-q"], work).returncode == 0
    first = run([medusa, "run", csv, "-o", "t.h5", "--radius", "3"], work)
    assert first.returncode == 0 and "left as they were" not in first.stderr, first.stderr
    assert run([medusa, "curves", "s.h5"], work).returncode == 0
    assert run([medusa, "report", "s.h5", "-o", "s.report.html", "--no-sweep", "-q"], work).returncode == 0
    before = {p: digest(os.path.join(work, p)) for p in ["s.curves.csv", "s.report.html"]}
    again = run([medusa, "run", csv, "-o", "s.h5", "--radius", "2.5", "--force"], work)
    assert again.returncode == 0, again.stderr
    wanted = ("medusa: warning: written from the store this run replaced, and left as they were: s.curves.csv, "
              "s.curves.svg, s.sorting.csv, s.sorting.svg, s.report.html (rerun the commands that wrote them)")
    assert wanted in again.stderr.splitlines(), again.stderr
    assert {p: digest(os.path.join(work, p)) for p in before} == before, "a stale output was changed"
    quiet = run([medusa, "run", csv, "-o", "s.h5", "--radius", "2.5", "--force", "-q"], work)
    assert quiet.returncode == 0 and quiet.stderr == "", quiet.stderr
    print("the stale outputs are named")


def check_mixed(medusa, csv, plot_store, work):
    for name, radius in [("a.h5", "3"), ("b.h5", "2.5")]:
        assert run([medusa, "run", csv, "-o", name, "--radius", radius, "-q"], work).returncode == 0
    assert run([medusa, "info", "a.h5"], work).returncode == 0
    for side in ["diagrams.csv", "barcode.svg", "diagram.svg"]:
        folder = os.path.join(work, "mix_" + side)
        os.makedirs(folder)
        for suffix in ["h5", "diagrams.csv", "barcode.svg", "diagram.svg"]:
            shutil.copyfile(os.path.join(work, "a." + suffix), os.path.join(folder, "a." + suffix))
        shutil.copyfile(os.path.join(work, "b." + side), os.path.join(folder, "a." + side))
        result = run([medusa, "info", "a.h5"], folder)
        assert result.returncode == 5, result.stderr
        assert "a." + side in result.stderr and "another run" in result.stderr, result.stderr
        if side == "diagrams.csv":
            plot = run(["/usr/bin/python3", plot_store, "a.h5"], folder)
            assert plot.returncode == 5, plot.stderr
            assert "another run" in plot.stderr, plot.stderr
    # The matching set plots.
    plot = run(["/usr/bin/python3", plot_store, "a.h5"], work)
    assert plot.returncode == 0, plot.stderr


def main():
    mode, medusa, csv = sys.argv[1:4]
    work = sys.argv[-1]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    if mode == "unsafe":
        check_unsafe(medusa, csv, work)
    elif mode == "written":
        check_written(medusa, csv, work)
    elif mode == "stale":
        check_stale(medusa, csv, work)
    else:
        check_mixed(medusa, csv, sys.argv[4], work)
    print("ok")


if __name__ == "__main__":
    main()
