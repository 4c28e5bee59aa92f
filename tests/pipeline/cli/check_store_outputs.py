"""Checks of `medusa` outputs against independent readers (run with /usr/bin/python3).

usage: check_store_outputs.py pers <medusa> <store> <workdir>   GUDHI reads the .pers export
       check_store_outputs.py truncated <medusa> <store> <workdir>  a truncated store is rejected
"""
import os
import subprocess
import sys

if not __debug__:
    sys.exit("these checks are assert statements: run without -O and without PYTHONOPTIMIZE")


def run(args, cwd):
    print("$", " ".join(args))
    return subprocess.run(args, cwd=cwd, capture_output=True, text=True)


def check_pers(medusa, store, work):
    import gudhi

    path = os.path.join(work, "forward_all.pers")
    result = run([medusa, "barcode", store, "--format", "pers", "--filtration", "forward", "--type", "all", "-o", path], work)
    assert result.returncode == 0, result.stderr
    with open(path) as f:
        lines = [line for line in f.read().splitlines() if line]
    assert lines, "empty .pers export"
    total = 0
    for k in range(4):
        intervals = gudhi.read_persistence_intervals_in_dimension(persistence_file=path, only_this_dim=k)
        expected = sum(1 for line in lines if line.split()[0] == str(k))
        print(f"H{k}: GUDHI read {len(intervals)} intervals, the file has {expected} lines")
        assert len(intervals) == expected
        total += len(intervals)
    assert total == len(lines)
    # The whole medusa is connected: at MCS 0 the cells are 5x5x5 cubes packed in a ball, so
    # neighbouring centres are 5 apart and every such edge (radius 2.5 <= rho = 3) is in K(t0).
    h0 = gudhi.read_persistence_intervals_in_dimension(persistence_file=path, only_this_dim=0)
    essential = sum(1 for birth, death in h0 if death == float("inf"))
    print(f"essential H0 classes: {essential}")
    assert essential == 1
    # The text diagram of the same selection lists the same pairs.
    text = run([medusa, "diagrams", store, "--filtration", "forward", "--type", "all"], work)
    assert text.returncode == 0, text.stderr
    pairs = [line for line in text.stdout.splitlines() if line and not line.startswith("#")]
    assert len(pairs) == len(lines), (len(pairs), len(lines))


def check_truncated(medusa, store, work):
    with open(store, "rb") as f:
        data = f.read()
    path = os.path.join(work, "truncated.h5")
    with open(path, "wb") as f:
        f.write(data[: len(data) // 2])
    result = run([medusa, "info", path], work)
    print(result.stderr, end="")
    assert result.returncode == 5, result.returncode
    assert result.stderr.count("\n") == 1 and result.stderr.startswith("medusa: "), result.stderr
    assert "truncated.h5" in result.stderr


if __name__ == "__main__":
    mode, medusa, store, work = sys.argv[1:5]
    os.makedirs(work, exist_ok=True)
    {"pers": check_pers, "truncated": check_truncated}[mode](medusa, os.path.join(work, store), work)
    print("ok")
