"""Helpers the check scripts of tests/pipeline/cli and tests/pipeline/python share: running the
`medusa` command line, comparing classes listed by it and by the module, and cutting a CompuCell3D
run to its first frames. The scripts of tests/pipeline/python put this folder on sys.path."""
import gzip
import os
import shutil
import subprocess


def cli(binary, *args):
    """stdout of `binary args...`; a non-zero exit fails the check with its stderr."""
    out = subprocess.run([binary, *args], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    return out.stdout


def run_logged(args, cwd):
    """The finished process of `args` run in `cwd`, its command, exit code and the end of its stderr
    printed first (what a failing check's log shows)."""
    result = subprocess.run(args, cwd=cwd, capture_output=True, text=True)
    print("$", " ".join(args), "->", result.returncode, result.stderr.strip()[-300:])
    return result


def normalised(c):
    """A class as a dict whose birth, death and lifetime are floats, whatever wrote it."""
    return {k: (float(v) if k in ("birth", "death", "lifetime") else v) for k, v in c.items()}


def cut_run(run, folder, frames):
    """`folder` (replaced) holds the first `frames` frames of the CSV run `run` (its cells.csv.gz, CC3D's
    own centres) beside a copy of its CC3DML, so that the cut reads as the run does."""
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(os.path.join(folder, "Simulation"))
    for name in os.listdir(os.path.join(run, "Simulation")):
        if name.endswith(".xml"):
            shutil.copy(os.path.join(run, "Simulation", name), os.path.join(folder, "Simulation", name))
    with gzip.open(os.path.join(run, "cells.csv.gz"), "rt") as f:
        lines = f.read().splitlines()
    kept = sorted({int(line.split(",")[0]) for line in lines[1:]})[:frames]
    with open(os.path.join(folder, "cells.csv"), "w") as f:
        f.write("\n".join([lines[0]] + [line for line in lines[1:] if int(line.split(",")[0]) in kept]) + "\n")
