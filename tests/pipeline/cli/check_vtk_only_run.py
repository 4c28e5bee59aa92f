"""`medusa run` on a CC3D folder with only LatticeData/*.vtk.gz (run with /usr/bin/python3).

usage: check_vtk_only_run.py <medusa> <cc3d run with ASCII LatticeData> <workdir>

Copies the snapshots alone into a fresh folder and checks that:
* `medusa run` needs no flag: it snaps the voxel centroids to the grid and says so in one line on
  stderr; the store records the policy, the number of positions moved and the largest move, and these
  equal an independent computation here (exact fractions, ties to even, docs/MATH.md §1.3), as do the
  stored positions; `medusa info` reports the snap;
* `medusa run --exact-vtk` refuses the same folder: exit 3, one line naming a snapshot and a cell.
"""
import gzip
import os
import re
import shutil
import subprocess
import sys
from fractions import Fraction

if not __debug__:
    sys.exit("these checks are assert statements: run without -O and without PYTHONOPTIMIZE")

SCALE = 10**6


def run(args, cwd):
    print("$", " ".join(args))
    result = subprocess.run(args, cwd=cwd, capture_output=True, text=True)
    print(result.stdout, result.stderr, sep="\n")
    return result


def voxel_sums(path):
    """{cell id: (n, [sum i, sum j, sum k])} of an ASCII STRUCTURED_POINTS snapshot (origin 0, spacing 1)."""
    with gzip.open(path, "rt") as f:
        lines = f.read().split("\n")
    dims = origin = spacing = None
    fields = {}
    k = 0
    while k < len(lines):
        words = lines[k].split()
        if words and words[0] == "DIMENSIONS":
            dims = [int(w) for w in words[1:4]]
        elif words and words[0] == "ORIGIN":
            origin = words[1:4]
        elif words and words[0] == "SPACING":
            spacing = words[1:4]
        elif len(words) == 4 and words[0] in ("CellType", "CellId") and words[1] == "1":
            count = int(words[2])
            values = []
            k += 1
            while len(values) < count:
                values.extend(int(w) for w in lines[k].split())
                k += 1
            fields[words[0]] = values
            continue
        k += 1
    assert origin == ["0", "0", "0"] and spacing == ["1", "1", "1"], (origin, spacing)
    nx, ny, _ = dims
    sums = {}
    for index, (cell, cell_type) in enumerate(zip(fields["CellId"], fields["CellType"])):
        if cell_type == 0:
            continue
        n, s = sums.setdefault(cell, [0, [0, 0, 0]])
        s[0] += index % nx
        s[1] += (index // nx) % ny
        s[2] += index // (nx * ny)
        sums[cell][0] = n + 1
    return sums


def snapped(n, total):
    """round(S * total / n) per coordinate, ties to even, and the largest move as a fraction."""
    point, largest = [], Fraction(0)
    for t in total:
        exact = Fraction(SCALE * t, n)
        q = round(exact)  # Fraction rounds half to even
        point.append(q)
        largest = max(largest, abs(exact - q))
    return point, largest


def main(medusa, source, work):
    shutil.rmtree(work, ignore_errors=True)
    folder = os.path.join(work, "vtk_only")
    shutil.copytree(os.path.join(source, "LatticeData"), os.path.join(folder, "LatticeData"))
    snapshots = sorted(f for f in os.listdir(os.path.join(folder, "LatticeData")) if f.endswith(".vtk.gz"))
    assert len(snapshots) >= 2, snapshots

    expected, moved, largest = {}, 0, Fraction(0)
    for frame, name in enumerate(snapshots):
        for cell, (n, total) in voxel_sums(os.path.join(folder, "LatticeData", name)).items():
            point, move = snapped(n, total)
            expected[(cell, frame)] = point
            moved += move != 0
            largest = max(largest, move)
    assert moved > 0, "the fixture has no centroid off the grid: the test would prove nothing"
    print(f"{len(expected)} positions, {moved} off the grid, largest move {largest} grid units")

    result = run([medusa, "run", "vtk_only", "-o", "vtk_only.h5", "--radius", "3"], work)
    assert result.returncode == 0, result.returncode
    notes = [line for line in result.stderr.splitlines() if "snapped" in line]
    assert len(notes) == 1 and notes[0].startswith("medusa: VTK centroids snapped to the 10^-6 grid"), notes
    assert f"{moved} of {len(expected)} positions moved" in notes[0], notes[0]
    assert re.search(r"^positions: VTK voxel centroids snapped", result.stdout, re.M), result.stdout

    import h5py

    with h5py.File(os.path.join(work, "vtk_only.h5"), "r") as f:
        attrs = f.attrs
        assert attrs["position_source"].decode() == "vtk-centroids-voxel-corner"
        assert attrs["snap_policy"].decode() == "nearest-ties-to-even"
        assert int(attrs["snapped_positions"]) == moved, (int(attrs["snapped_positions"]), moved)
        assert float(attrs["snap_max_displacement"]) == float(largest), (attrs["snap_max_displacement"], largest)
        g = f["input"]
        ids, first = g["cell_id"][:], g["first_frame"][:]
        offsets, positions = g["position_offset"][:], g["positions"][:]
        checked = 0
        for v in range(len(ids)):
            for row in range(offsets[v], offsets[v + 1]):
                frame = int(first[v]) + row - int(offsets[v])
                assert list(positions[row]) == expected[(int(ids[v]), frame)], (ids[v], frame)
                checked += 1
        assert checked == len(expected), (checked, len(expected))

    info = run([medusa, "info", "vtk_only.h5"], work)
    assert info.returncode == 0
    assert re.search(rf"^positions: VTK voxel centroids snapped to the grid \(nearest-ties-to-even\): {moved} moved",
                     info.stdout, re.M), info.stdout

    refused = run([medusa, "run", "vtk_only", "-o", "refused.h5", "--radius", "3", "--exact-vtk"], work)
    assert refused.returncode == 3, refused.returncode
    lines = refused.stderr.splitlines()
    assert len(lines) == 1 and re.match(r"medusa: .*Step_\d+\.vtk\.gz: cell \d+: .*--exact-vtk", lines[0]), lines
    assert not os.path.exists(os.path.join(work, "refused.h5"))
    print("ok")


if __name__ == "__main__":
    main(*sys.argv[1:])
