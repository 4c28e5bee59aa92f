#!/usr/bin/python3
"""A random walk on the 3-torus as a CC3D-like run folder, and the static rebuild it is compared with.

    periodic_walk.py make FOLDER [CELLS]   cells.csv + Simulation/run.xml (periodic x, y, z), 3 frames,
                                           density of 1,000 cells in 40^3, steps up to 0.5 per axis
    periodic_walk.py static FOLDER RADIUS  CPU seconds per frame of GUDHI's alpha complex (CGAL inside)
                                           of the 27 tiled copies of the cells, up to RADIUS
"""
import csv
import itertools
import os
import random
import sys
import time


def make(folder, n):
    random.seed(11)
    side = round(40 * (n / 1000) ** (1 / 3))
    os.makedirs(os.path.join(folder, "Simulation"), exist_ok=True)
    axes = "".join("    <Boundary_%s>Periodic</Boundary_%s>\n" % (a, a) for a in "xyz")
    with open(os.path.join(folder, "Simulation", "run.xml"), "w") as f:
        f.write('<CompuCell3D>\n  <Potts>\n    <Dimensions x="%d" y="%d" z="%d"/>\n%s  </Potts>\n'
                '</CompuCell3D>\n' % (side, side, side, axes))
    pos = [[random.uniform(0, side) for _ in range(3)] for _ in range(n)]
    rows = ["mcs,cell_id,type_id,xCOM,yCOM,zCOM"]
    for frame in range(3):
        for i, p in enumerate(pos):
            rows.append("%d,%d,%d,%.3f,%.3f,%.3f" % (100 * frame, i + 1, 1 + i % 2, p[0] % side, p[1] % side,
                                                      p[2] % side))
        for p in pos:
            for a in range(3):
                p[a] += random.uniform(-0.5, 0.5)
    with open(os.path.join(folder, "cells.csv"), "w") as f:
        f.write("\n".join(rows) + "\n")
    print("%s: %d cells, lattice %d^3" % (folder, n, side))


def static(folder, radius):
    import gudhi
    import xml.etree.ElementTree as ET
    side = float(ET.parse(os.path.join(folder, "Simulation", "run.xml")).find("Potts/Dimensions").get("x"))
    frames = {}
    for r in csv.DictReader(open(os.path.join(folder, "cells.csv"))):
        frames.setdefault(r["mcs"], []).append((float(r["xCOM"]), float(r["yCOM"]), float(r["zCOM"])))
    for mcs, pts in frames.items():
        t = time.process_time()
        tiled = [(x + i * side, y + j * side, z + k * side) for (x, y, z) in pts
                 for i, j, k in itertools.product((-1, 0, 1), repeat=3)]
        gudhi.AlphaComplex(points=tiled).create_simplex_tree(max_alpha_square=radius * radius)
        print("MCS %s: %d points, %.2f s CPU" % (mcs, len(tiled), time.process_time() - t))


if __name__ == "__main__":
    if sys.argv[1] == "make":
        make(sys.argv[2], int(sys.argv[3]) if len(sys.argv) > 3 else 10000)
    else:
        static(sys.argv[2], float(sys.argv[3]))
