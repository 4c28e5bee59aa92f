"""`medusa run` on a CSV whose centres have more decimals than the 10^-6 grid holds, and exponents
(run with /usr/bin/python3).

usage: check_csv_rounding.py <medusa> <cells.csv.gz with 6 decimals> <workdir>

Rewrites every centre of a real CC3D CSV so that it rounds back to itself on the grid (docs/MATH.md
§1.2): some with extra digits that round down, some that round up, some halfway (ties to even), some
in exponent notation, some unchanged. Checks that:
* without a flag `medusa run` refuses the file: exit 3, one line naming the file, line, cell and
  column and pointing to --round-csv, and no store;
* `medusa run --round-csv` says in one line how many positions moved and how far; the store records
  the policy, that count and the largest move, equal to the count and exact fraction computed here;
  the stored positions are the original ones, and the diagrams equal those of the original file;
* `medusa info` reports the rounding.
"""
import gzip
import os
import re
import shutil
import sys
from decimal import Decimal
from fractions import Fraction

from cli_checks import run_logged as run

if not __debug__:
    sys.exit("these checks are assert statements: run without -O and without PYTHONOPTIMIZE")

SCALE = 10**6


def grid_text(units):
    """The decimal text of `units` grid units (units >= 0)."""
    return f"{units // SCALE}.{units % SCALE:06d}"


def rewritten(units, mode):
    """(text, rounding offset in grid units or None) of a centre of `units` grid units that rounds
    back to `units` on the grid, ties to even."""
    if mode == 0:  # extra digits below half a unit: rounds down
        return grid_text(units) + "4999", Fraction(4999, 10**4)
    if mode == 1 and units > 0:  # one unit less and six tenths: rounds up
        return grid_text(units - 1) + "6", Fraction(4, 10)
    if mode == 2 and units > 0 and units % 2 == 0:  # halfway from the odd unit below: ties to even
        return grid_text(units - 1) + "5", Fraction(1, 2)
    if mode == 3:  # exponent notation, exact
        digits = str(units)
        return f"{digits[0]}.{digits[1:] or '0'}e{len(digits) - 1 - 6}", None
    return grid_text(units), None


def main(medusa, source, work):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    original = os.path.join(work, "original.csv")
    noisy = os.path.join(work, "noisy.csv")
    with gzip.open(source, "rt") as f:
        lines = f.read().splitlines()
    header = lines[0].split(",")
    columns = [header.index(c) for c in ("xCOM", "yCOM", "zCOM")]
    out, positions, moved, largest, modes = [lines[0]], 0, 0, Fraction(0), set()
    for k, line in enumerate(lines[1:]):
        fields = line.split(",")
        row_moved = False
        for a, c in enumerate(columns):
            units = int(Decimal(fields[c]) * SCALE)
            assert Decimal(units) == Decimal(fields[c]) * SCALE and units >= 0, fields[c]
            mode = (k + a) % 5
            text, offset = rewritten(units, mode)
            exact = Fraction(Decimal(text)) * SCALE
            assert round(exact) == units and abs(exact - units) == (offset or 0), (text, units)
            if offset is not None:
                row_moved = True
                largest = max(largest, offset)
                modes.add(mode)
            elif text != grid_text(units):
                modes.add(mode)
            fields[c] = text
        positions += 1
        moved += row_moved
        out.append(",".join(fields))
    assert modes == {0, 1, 2, 3}, f"every kind of rewrite must occur, got {sorted(modes)}"
    with open(original, "w") as f:
        f.write("\n".join(lines) + "\n")
    with open(noisy, "w") as f:
        f.write("\n".join(out) + "\n")
    print(f"{positions} positions, {moved} rounded, largest move {largest} grid units")

    refused = run([medusa, "run", "noisy.csv", "-o", "refused.h5", "--radius", "3"], work)
    assert refused.returncode == 3, refused.returncode
    errors = refused.stderr.splitlines()
    assert len(errors) == 1, errors
    assert re.match(r"medusa: .*noisy\.csv:2: MCS \d+, cell \d+: column xCOM: '\d+\.\d{10}' has 10 decimals, more than the "
                    r"6 that the grid \(10\^-6 lattice units\) holds exactly; --round-csv rounds", errors[0]), errors
    assert not os.path.exists(os.path.join(work, "refused.h5"))

    result = run([medusa, "run", "noisy.csv", "-o", "noisy.h5", "--radius", "3", "--round-csv"], work)
    assert result.returncode == 0, result.returncode
    notes = [line for line in result.stderr.splitlines() if "rounded" in line]
    assert len(notes) == 1, notes
    assert notes[0].startswith(f"medusa: CSV centres rounded to the 10^-6 grid: {moved} of {positions} "
                               "positions moved, the largest by 0.5 grid units"), notes[0]
    assert "--round-csv" in notes[0], notes[0]
    reference = run([medusa, "run", "original.csv", "-o", "original.h5", "--radius", "3"], work)
    assert reference.returncode == 0, reference.returncode

    import h5py

    with h5py.File(os.path.join(work, "noisy.h5"), "r") as f, h5py.File(os.path.join(work, "original.h5"), "r") as g:
        assert f.attrs["position_source"].decode() == "csv-centres"
        assert f.attrs["snap_policy"].decode() == "nearest-ties-to-even"
        assert int(f.attrs["snapped_positions"]) == moved, (int(f.attrs["snapped_positions"]), moved)
        assert float(f.attrs["snap_max_displacement"]) == float(largest), f.attrs["snap_max_displacement"]
        assert g.attrs["snap_policy"].decode() == "exact"
        for name in ("cell_id", "first_frame", "position_offset", "positions"):
            assert (f["input"][name][:] == g["input"][name][:]).all(), name

    def diagrams(name):
        with open(os.path.join(work, name)) as f:
            return [line for line in f if not line.startswith("#")]

    rows = diagrams("noisy.diagrams.csv")
    assert len(rows) > 1 and rows == diagrams("original.diagrams.csv")

    info = run([medusa, "info", "noisy.h5"], work)
    assert info.returncode == 0
    assert re.search(rf"^positions: CC3D centres \(cells.csv\) rounded to the grid \(nearest-ties-to-even\): {moved} "
                     r"moved, at most 0.5 grid units", info.stdout, re.M), info.stdout
    print("ok")


if __name__ == "__main__":
    main(*sys.argv[1:])
