"""medusa.run on a periodic CompuCell3D run (run with /usr/bin/python3) against `medusa run`.

usage: check_periodic_run.py <medusa> <periodic CC3D run folder> <work dir>
       (PYTHONPATH must hold <build dir>/python)

On the first 3 frames of the run (CC3D's centres, written here beside the run's CC3DML):
* medusa.run(folder, radius=3) writes the medusa on the torus (docs/MATH.md §8): its diagrams (every
  filtration and type, every double in order) and classes, with the axes each loop wraps around
  (`wraps`, §8.8), equal those of the store `medusa run` writes, read with the module and with
  `medusa classes --format json`; the store records the periodic axes and periods as `medusa run`'s;
* periodic_as_open=True gives the diagrams of `medusa run --periodic-as-open`, which differ;
* a radius with 4 x radius not below the period is a medusa.Error naming §8.3, and leaves no store.
Exit 1 names the first difference.
"""
import json
import os
import shutil
import sys

import h5py
import numpy as np

import medusa

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "cli"))
from cli_checks import cli, cut_run, normalised  # noqa: E402

if not __debug__:
    sys.exit("these checks are assert statements: run without -O and without PYTHONOPTIMIZE")


def same_diagrams(a, b, types):
    for direction in ("forward", "reverse"):
        for t in [None] + list(types):
            x = a.diagrams(type=t, filtration=direction, layout="giotto")
            y = b.diagrams(type=t, filtration=direction, layout="giotto")
            if not np.array_equal(x, y):
                return f"{direction} {t}: {x.shape} against {y.shape}"
    return ""


def attributes(path):
    with h5py.File(path, "r") as f:
        return f.attrs["periodic_axes"].decode(), [int(f.attrs["periodic_length_" + a]) for a in "xyz"]


def main():
    binary, run, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    folder = os.path.join(work, "periodic_3frames")
    cut_run(run, folder, 3)

    cli_store = os.path.join(work, "cli.h5")
    cli(binary, "run", folder, "--radius", "3", "-o", cli_store, "--quiet")
    ran = medusa.run(folder, radius=3, output=os.path.join(work, "py.h5"))
    s = medusa.open(cli_store)
    assert ran.periodic_axes == s.periodic_axes == "x,y", (ran.periodic_axes, s.periodic_axes)
    assert attributes(ran.path) == attributes(cli_store) == ("x,y", [50000000, 50000000, 0]), \
        (attributes(ran.path), attributes(cli_store))
    assert s.types == ran.types == [1, 2], s.types
    diff = same_diagrams(ran, s, s.types)
    assert not diff, "medusa.run differs from medusa run: " + diff
    points = sum(len(ran.diagrams(type=t, filtration=d, layout="giotto"))
                 for d in ("forward", "reverse") for t in [None, 1, 2])
    print(f"medusa.run: {points} diagram points equal `medusa run`'s on the torus")

    wrapping = 0
    for options, kwargs in ((["--type", "all"], {}), (["--type", "1", "--dim", "1"], {"type": 1, "dim": 1})):
        listed = json.loads(cli(binary, "classes", cli_store, "--format", "json", *options))["classes"]
        got = ran.classes(**kwargs)
        assert [normalised(c) for c in got] == [normalised(c) for c in s.classes(**kwargs)], options
        by_id = {c["id"]: normalised(c) for c in listed}
        assert len(got) == len(listed) > 0, (options, len(got), len(listed))
        for c in got:
            assert normalised(c) == by_id[c["id"]], (options, c["id"], c.get("wraps"), by_id[c["id"]].get("wraps"))
        wrapping += sum(1 for c in got if c["wraps"])
    assert wrapping > 0, "no loop wraps around the domain"
    print(f"classes: equal `medusa classes --format json`, {wrapping} wrapping around the domain")

    as_open = os.path.join(work, "cli_open.h5")
    cli(binary, "run", folder, "--radius", "3", "-o", as_open, "--periodic-as-open", "--quiet")
    ran_open = medusa.run(folder, radius=3, output=os.path.join(work, "py_open.h5"), periodic_as_open=True)
    assert ran_open.periodic_axes == "" and "wraps" not in ran_open.classes(dim=1)[0]
    diff = same_diagrams(ran_open, medusa.open(as_open), s.types)
    assert not diff, "periodic_as_open differs from --periodic-as-open: " + diff
    assert same_diagrams(ran_open, ran, s.types), "the torus gives the diagrams of the open run"
    print("periodic_as_open=True: the diagrams of `medusa run --periodic-as-open`")

    too_large = os.path.join(work, "too_large.h5")
    try:
        medusa.run(folder, radius="12.5", output=too_large)
        raise AssertionError("radius 12.5 on a period of 50 did not raise")
    except medusa.Error as e:
        assert "too large for the periodic lattice" in str(e) and "§8.3" in str(e), e
    left = [n for n in os.listdir(work) if n.startswith("too_large")]
    assert not left, left
    print("radius 12.5: refused, nothing written")


if __name__ == "__main__":
    main()
