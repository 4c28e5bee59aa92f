#!/usr/bin/python3
"""Writes a synthetic CC3D-like run (cells.csv) for the persistence benchmarks.

Cells start on a jittered cubic grid with CC3D's cell spacing (cubes of side 5, as the BlobInitializer
of examples/sorting_3d lays them out), get type 1 or 2 at random, and move by small Gaussian steps
between frames saved every 100 MCS. A sorting bias pulls type-1 cells towards the centre of the
aggregate and pushes type-2 cells outwards, so runs with different biases have different diagrams.
The columns and the 6 decimals are those of the bundled runs (tests/data/cc3d/README.txt), so
`medusa run out.csv --radius 3` reads the file like a real run.

Usage: make_random_walk.py --cells N --frames F --seed S [--step 0.7] [--bias 0.0] [--jitter 0.5] -o out.csv
"""
import argparse
import math
import random


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cells", type=int, required=True)
    parser.add_argument("--frames", type=int, required=True)
    parser.add_argument("--seed", type=int, required=True)
    parser.add_argument("--step", type=float, default=0.7, help="standard deviation of a step per axis")
    parser.add_argument("--bias", type=float, default=0.0, help="radial drift per frame (type 1 in)")
    parser.add_argument("--spacing", type=float, default=5.0)
    parser.add_argument("--jitter", type=float, default=0.5, help="start offset from the grid, per axis")
    parser.add_argument("-o", "--output", required=True)
    args = parser.parse_args()
    if args.cells < 5 or args.frames < 2:
        parser.error("need at least 5 cells and 2 frames")

    rng = random.Random(args.seed)
    side = math.ceil(args.cells ** (1.0 / 3.0))
    margin = 2 * args.spacing
    centre = margin + args.spacing * (side - 1) / 2.0
    cells = []
    for index in range(args.cells):
        i, j, k = index % side, (index // side) % side, index // (side * side)
        position = [margin + args.spacing * g + rng.uniform(-args.jitter, args.jitter) for g in (i, j, k)]
        cells.append((rng.choice((1, 2)), position))

    names = {1: "Condensing", 2: "NonCondensing"}
    with open(args.output, "w") as out:
        out.write("mcs,cell_id,cluster_id,type_id,type_name,xCOM,yCOM,zCOM,volume\n")
        for frame in range(args.frames):
            for cell_id, (cell_type, position) in enumerate(cells, start=1):
                out.write("%d,%d,%d,%d,%s,%.6f,%.6f,%.6f,125\n" % (100 * frame, cell_id, cell_id, cell_type,
                                                                   names[cell_type], *position))
            for cell_type, position in cells:
                radial = [x - centre for x in position]
                norm = math.sqrt(sum(r * r for r in radial)) or 1.0
                drift = -args.bias if cell_type == 1 else args.bias
                for axis in range(3):
                    position[axis] += rng.gauss(0.0, args.step) + drift * radial[axis] / norm


if __name__ == "__main__":
    main()
