#!/usr/bin/python3
"""`medusa run` on hand-built periodic runs that medusa must refuse: each refusal is one line on stderr
naming the file and cell (exit 3) or the radius and period (exit 4), and no store (nor temporary file)
is left behind.

usage: check_periodic_errors.py MEDUSA WORKDIR
"""
import os
import re
import shutil
import subprocess
import sys

XML = """<CompuCell3D>
  <Potts>
    <Dimensions x="10" y="10" z="10"/>
    <Boundary_x>Periodic</Boundary_x>
  </Potts>
</CompuCell3D>
"""

# Four cells (a 3D run needs at least four); cell 7 steps from x = 1 to x = 6 on a period of 10.
AMBIGUOUS = ("mcs,cell_id,type_id,xCOM,yCOM,zCOM\n"
             "0,1,1,2,1,1\n0,2,1,2,4,1\n0,3,1,2,1,4\n0,7,1,1,5,5\n"
             "100,1,1,2,1,1\n100,2,1,2,4,1\n100,3,1,2,1,4\n100,7,1,6,5,5\n")


def snapshot(cells):
    """A 10 x 4 x 4 CC3D-like ASCII snapshot; cells maps (x, y, z) to a cell id (type 1)."""
    n = 10 * 4 * 4
    ids = []
    for p in range(n):
        ids.append(cells.get((p % 10, (p // 10) % 4, p // 40), 0))
    types = [1 if i else 0 for i in ids]
    return ("# vtk DataFile Version 5.1\nvtk output\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS 10 4 4\n"
            "SPACING 1 1 1\nORIGIN 0 0 0\nPOINT_DATA %d\nFIELD FieldData 2\nCellType 1 %d unsigned_char\n%s\n"
            "CellId 1 %d long\n%s\n" % (n, n, " ".join(map(str, types)), n, " ".join(map(str, ids))))


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def check(medusa, work, name, run, pattern, code=3, radius="1", options=("--periodic-as-open",)):
    out = os.path.join(work, name + ".h5")
    p = subprocess.run([medusa, "run", run, *options, "--snap", "--radius", radius, "-o", out],
                       capture_output=True, text=True)
    assert p.returncode == code, "%s: exit %d, expected %d; stderr: %s" % (name, p.returncode, code, p.stderr)
    lines = p.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("medusa: "), "%s: stderr is not one line: %r" % (name, p.stderr)
    assert re.search(pattern, lines[0]), "%s: %r does not match %r" % (name, lines[0], pattern)
    left = [f for f in os.listdir(work) if f.startswith(name + ".")]
    assert not left, "%s: files left behind: %s" % (name, left)
    print("ok:", lines[0])


def main():
    medusa, work = sys.argv[1], sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)

    ambiguous = os.path.join(work, "ambiguous_run")
    write(os.path.join(ambiguous, "cells.csv"), AMBIGUOUS)
    write(os.path.join(ambiguous, "Simulation", "run.xml"), XML)
    check(medusa, work, "ambiguous", ambiguous,
          r"cells\.csv: cell 7 moves 5 along x between MCS 0 and MCS 100, half the period.*ambiguous")

    # Cell 4 has voxels at x = 0 and x = 5: half the period of 10 apart along the periodic x.
    wide = os.path.join(work, "wide_run")
    cells = {(2, 0, 0): 1, (2, 2, 0): 2, (2, 0, 2): 3, (0, 1, 1): 4, (5, 1, 2): 4, (2, 2, 2): 5}
    write(os.path.join(wide, "LatticeData", "Step_000.vtk"), snapshot(cells))
    write(os.path.join(wide, "LatticeData", "Step_100.vtk"), snapshot(cells))
    write(os.path.join(wide, "Simulation", "run.xml"), XML.replace('y="10" z="10"', 'y="4" z="4"'))
    check(medusa, work, "wide", wide, r"Step_000\.vtk: cell 4: its voxels span 6 of the 10 lattice sites along x")
    # The same VTK run read as periodic refuses it too.
    check(medusa, work, "wide_periodic", wide, r"Step_000\.vtk: cell 4: its voxels span", options=())

    # Radius 2.5 on a period of 10: 4 rho = 10 is not below the period (docs/MATH.md §8.3).
    radius = os.path.join(work, "radius_run")
    write(os.path.join(radius, "cells.csv"), AMBIGUOUS.replace("100,7,1,6,5,5", "100,7,1,2,5,5"))
    write(os.path.join(radius, "Simulation", "run.xml"), XML)
    check(medusa, work, "radius", radius, r"radius 2\.5 is too large for the periodic lattice: .* period 10 along x",
          code=4, radius="2.5", options=())


if __name__ == "__main__":
    main()
