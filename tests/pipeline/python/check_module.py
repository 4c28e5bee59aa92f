"""The Python module `medusa` against the `medusa` command line (run with /usr/bin/python3).

usage: check_module.py <medusa> <store> <run input> <radius> <work dir>
       (PYTHONPATH must hold <build dir>/python)

* store.diagrams(...) equals `medusa barcode --format csv` exactly (every double, in order), for every
  filtration and type, in giotto-tda's layout and in GUDHI's (per degree), and GUDHI reads it;
* store.classes(...) equals `medusa classes --format json` (stored forward classes, and reverse ones
  computed on demand);
* store.K_at(t) equals `medusa at --time t -o x.csv`;
* store.betti_curves() equals counting the diagram's points alive at each frame time;
* medusa.run(input, radius) writes a store whose diagrams and classes equal those of <store>, which
  `medusa run` wrote from the same input and radius.
Exit 1 names the first difference.
"""
import csv
import io
import json
import os
import re
import subprocess
import sys

import gudhi
import numpy as np

import medusa

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "cli"))
from cli_checks import cli, normalised  # noqa: E402

if not __debug__:
    sys.exit("these checks are assert statements: run without -O and without PYTHONOPTIMIZE")


def barcode_rows(binary, store):
    rows = {}
    for r in csv.DictReader(io.StringIO(cli(binary, "barcode", store, "--format", "csv"))):
        rows.setdefault((r["direction"], r["type"]), []).append(
            (float(r["birth"]), float(r["death"]), float(r["dimension"])))
    return rows


def check_diagrams(binary, store, s):
    expected = barcode_rows(binary, store)
    assert len(expected) == 2 * (len(s.types) + 1), sorted(expected)
    count = 0
    for (direction, type_name), rows in expected.items():
        got = s.diagrams(type=type_name, filtration=direction, layout="giotto")
        assert got.shape == (len(rows), 3), (direction, type_name, got.shape, len(rows))
        assert [tuple(r) for r in got.tolist()] == rows, f"{direction} {type_name}: diagrams differ"
        per_degree = s.diagrams(type=type_name, filtration=direction)
        for k, points in per_degree.items():
            assert points.tolist() == [[b, d] for b, d, dim in rows if dim == k], (direction, type_name, k)
            assert np.array_equal(points, s.diagrams(type=type_name, dim=k, filtration=direction))
        count += len(rows)
    h1 = s.diagrams(dim=1)
    finite = h1[np.isfinite(h1[:, 1])]
    shifted = finite + np.array([0.0, 1.0])  # every death one MCS later: distance 1 (or half a bar)
    assert finite.size > 0 and 0 < gudhi.bottleneck_distance(finite, shifted) <= 1.0 + 1e-9
    print(f"diagrams: {count} points equal `medusa barcode --format csv`")


def check_classes(binary, store, s):
    total = 0
    for options, kwargs in ((["--type", "all"], {}), (["--type", "1"], {"type": 1}),
                            (["--type", "2", "--filtration", "reverse"], {"type": 2, "filtration": "reverse"}),
                            (["--dim", "0"], {"dim": 0}), (["--shorten"], {"shorten": True}),
                            (["--type", "1", "--filtration", "reverse", "--shorten"],
                             {"type": 1, "filtration": "reverse", "shorten": True})):
        listed = json.loads(cli(binary, "classes", store, "--format", "json", *options))["classes"]
        got = s.classes(**kwargs)
        assert len(got) == len(listed) > 0, (options, len(got), len(listed))
        by_id = {c["id"]: normalised(c) for c in listed}
        for c in got:
            assert normalised(c) == by_id[c["id"]], (options, c["id"])
        total += len(got)
    print(f"classes: {total} equal `medusa classes --format json`")


def check_complex(binary, store, s, work):
    t = s.frame_times[1]
    target = os.path.join(work, "at.csv")
    cli(binary, "at", store, "--time", str(t), "-o", target)
    with open(target) as f:
        rows = [[int(x) for x in r[1:] if x] for r in list(csv.reader(f))[1:]]
    got = s.K_at(t)
    assert got == rows, f"K_at({t}) differs from `medusa at`: {len(got)} against {len(rows)} simplices"
    print(f"K_at({t}): {len(got)} simplices equal `medusa at`")


def check_betti(s):
    times, curves = s.betti_curves(type=1)
    assert list(times) == [float(t) for t in s.frame_times]
    d = s.diagrams(type=1, layout="giotto")
    for k in range(4):
        expected = [int(np.sum((d[:, 2] == k) & (d[:, 0] <= t) & (t < d[:, 1]))) for t in times]
        assert list(curves[k]) == expected, k
    assert curves[0][0] > 0
    print(f"betti_curves: {curves.shape}")


def check_type_names(binary, store, s):
    # A type by its name, as `medusa info` lists it ("cell types: 1 (Condensing): ..."), is that id's type.
    info = subprocess.run([binary, "info", store], capture_output=True, text=True, check=True).stdout
    named = dict((name, int(i)) for i, name in re.findall(r"(\d+) \((\w+)\)", info.split("cell types:")[1].split("\n")[0]))
    assert named, info
    assert s.type_names == {i: name for name, i in named.items()}, s.type_names
    # repr names the store, its types with their names, its frames and MCS, as `medusa info` does.
    frames = int(re.search(r"^frames: (\d+)$", info, re.M).group(1))
    text = repr(s)
    assert text.startswith(f"<medusa.Store '{s.path}': ") and " cells of types " in text, text
    assert text.endswith(f", {frames} frames, MCS {s.frame_times[0]} to {s.frame_times[-1]}>"), text
    assert all(f"{i} ({name})" in text for name, i in named.items()), text
    t_mid = (s.frame_times[0] + s.frame_times[-1]) / 2
    for name, i in named.items():
        assert np.array_equal(s.diagrams(type=name, layout="giotto"), s.diagrams(type=i, layout="giotto")), name
        assert s.K_at(t_mid, type=name.lower()) == s.K_at(t_mid, type=i), name
        assert [c["id"] for c in s.classes(type=name)] == [c["id"] for c in s.classes(type=str(i))], name
    try:
        s.diagrams(type="NoSuchType")
        raise AssertionError("an unknown type name did not raise")
    except medusa.Error as e:
        assert "its cell types are" in str(e), e
    print("types by name:", named)


def check_slices(binary, store, s, work):
    # slices(): the Betti numbers of K_t at the frames, as `medusa curves --frames-only` writes them.
    prefix = os.path.join(work, "frames")
    subprocess.run([binary, "curves", store, "--frames-only", "-o", prefix], capture_output=True, check=True)
    with open(prefix + ".curves.csv") as f:
        rows = list(csv.DictReader(f))
    checked = 0
    for t in [None] + list(s.types):
        times, betti = s.slices(type=t)
        label = "all" if t is None else str(t)
        expected = [r for r in rows if r["type"] == label]
        assert [float(r["time"]) for r in expected] == list(times), (label, times)
        for k in range(3):
            assert [int(r["b%d" % k]) for r in expected] == list(betti[k]), (label, k, betti[k])
        checked += len(expected)
    assert checked > 0
    name = s.type_names[s.types[0]]
    assert np.array_equal(s.slices(type=name)[1], s.slices(type=s.types[0])[1])
    print(f"slices: {checked} rows of medusa curves --frames-only")


def check_run_options(binary, work):
    # A VTK folder is read as `medusa run` reads it, snapping off-grid centroids: the same diagrams.
    folder = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "data", "cc3d", "nosorting_3d")
    cli_store = os.path.join(work, "nosorting_cli.h5")
    subprocess.run([binary, "run", "--force", "-q", "--source", "vtk", "--threads", "1", folder, "-o", cli_store],
                   check=True)
    ran = medusa.run(folder, source="vtk", output=os.path.join(work, "nosorting_py.h5"), force=True, threads=1)
    cli_view = medusa.open(cli_store)
    for t in [None] + list(cli_view.types):
        assert np.array_equal(ran.diagrams(type=t, layout="giotto"), cli_view.diagrams(type=t, layout="giotto")), t
    # A refusal names medusa.run's keyword arguments, not the command line's flags.
    for kwargs, csv_text, wanted in (
            ({"source": "vtk", "snap": False}, None, "(snap=False)"),
            ({"radius": 3}, "mcs,cell_id,type_id,xCOM,yCOM,zCOM\n0,1,1,0.1234567,0,0\n", "round_csv=True rounds")):
        source = folder
        if csv_text is not None:
            source = os.path.join(work, "seven_decimals.csv")
            with open(source, "w") as f:
                f.write(csv_text)
        try:
            medusa.run(source, output=os.path.join(work, "refused.h5"), force=True, threads=1, **kwargs)
            raise AssertionError(f"medusa.run{kwargs} was not refused")
        except medusa.Error as e:
            assert wanted in str(e) and " --" not in str(e), e
    # A store in a folder that does not exist is refused before any reading, naming the folder.
    missing = os.path.join(work, "no_such_folder")
    try:
        medusa.run(folder, output=os.path.join(missing, "run.h5"), threads=1)
        raise AssertionError("medusa.run into a missing folder was not refused")
    except medusa.Error as e:
        assert str(e) == f"output {missing}/run.h5: the folder {missing} does not exist", e
    assert not os.path.exists(missing)
    print("medusa.run: VTK snapped as by medusa run; refusals name keyword arguments and a missing folder")


def main():
    binary, store, run_input, radius, work = sys.argv[1:6]
    os.makedirs(work, exist_ok=True)
    s = medusa.open(store)
    check_diagrams(binary, store, s)
    check_classes(binary, store, s)
    check_complex(binary, store, s, work)
    check_betti(s)
    check_type_names(binary, store, s)
    check_slices(binary, store, s, work)
    check_run_options(binary, work)
    try:
        s.K_at(-1.0)
        raise AssertionError("K_at before the run did not raise")
    except medusa.Error as e:
        assert str(e).startswith("time -1 is outside the run"), e
    # Values the command line refuses are refused here too, not answered with an empty or final result.
    for call, wanted in ((lambda: s.K_at(float("nan")), "time nan is outside the run"),
                         (lambda: s.betti_curves(times=[float("nan"), 50.0]), "times holds nan"),
                         (lambda: s.diagrams(dim=5), "dim=5 is not in range 0 to 3"),
                         (lambda: s.classes(dim=-1), "dim=-1 is not in range 0 to 3")):
        try:
            call()
            raise AssertionError(f"not refused: {wanted}")
        except medusa.Error as e:
            assert str(e).startswith(wanted), e
    ran = medusa.run(run_input, radius=radius, output=os.path.join(work, "run.h5"), force=True)
    for direction in ("forward", "reverse"):
        for t in [None] + list(s.types):
            a, b = ran.diagrams(type=t, filtration=direction, layout="giotto"), s.diagrams(type=t, filtration=direction, layout="giotto")
            assert np.array_equal(a, b), f"medusa.run: {direction} {t} differs from medusa run"
    assert [normalised(c) for c in ran.classes()] == [normalised(c) for c in s.classes()]
    print("medusa.run: the same diagrams and classes as `medusa run`")


if __name__ == "__main__":
    main()
