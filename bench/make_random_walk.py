#!/usr/bin/python3
"""A synthetic CompuCell3D-like run: cells on a jittered cubic grid, random-walking between frames.

Writes a cells.csv[.gz] with CC3D's columns (mcs,cell_id,cluster_id,type_id,type_name,xCOM,yCOM,zCOM,
volume) and 6 decimals, so `medusa run` reads it like a CC3D run (tests/data/cc3d/README.txt). Cells
sit on a cubic grid of spacing --spacing lattice units (about the diameter of a 125-voxel cell, as
CC3D's BlobInitializer lays them out), each moved by a uniform jitter of up to --jitter per axis so
that the start is in general position; types 1 and 2 are drawn at random. At every later frame each
cell moves by a Gaussian step of root-mean-square length --step (per axis sigma = step / sqrt(3)),
plus an optional sorting drift --bias per frame that pulls type-1 cells towards the centre of the
aggregate and pushes type-2 cells outwards (so runs with different biases have different diagrams).
Frames are --interval MCS apart. The seed is printed on stderr.

Used by bench/e2e_bench.py (20,000 cells) and bench/run_persistence_benches.sh (10,000 cells; twenty
small runs with four biases).

Usage: make_random_walk.py OUT.csv[.gz] [--cells 20000] [--frames 10] [--seed N] [--bias B] ...
"""
import argparse
import gzip
import math
import sys

import numpy


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("output", nargs="?", help="CSV file to write (gzipped when it ends in .gz)")
    parser.add_argument("-o", "--output", dest="output_option", help="the same as the positional OUT")
    parser.add_argument("--cells", type=int, default=20000)
    parser.add_argument("--frames", type=int, default=10)
    parser.add_argument("--spacing", type=float, default=5.0, help="grid spacing in lattice units")
    parser.add_argument("--jitter", type=float, default=1.0, help="largest initial offset per axis")
    parser.add_argument("--step", type=float, default=0.5, help="RMS step length per frame")
    parser.add_argument("--bias", type=float, default=0.0, help="radial drift per frame (type 1 inwards)")
    parser.add_argument("--interval", type=int, default=100, help="MCS between frames")
    parser.add_argument("--volume", type=int, default=125, help="volume column (voxels) of every cell")
    parser.add_argument("--seed", type=int, default=20261122)
    args = parser.parse_args()
    output = args.output or args.output_option
    if not output:
        parser.error("give the output file (OUT or -o OUT)")
    if args.cells < 4 or args.frames < 2:
        parser.error("need at least 4 cells and 2 frames")
    print(f"make_random_walk.py: seed {args.seed}, {args.cells} cells, {args.frames} frames", file=sys.stderr)

    rng = numpy.random.default_rng(args.seed)
    side = math.ceil(args.cells ** (1.0 / 3.0))
    index = numpy.arange(args.cells)
    grid = numpy.stack([index % side, (index // side) % side, index // (side * side)], axis=1).astype(float)
    # A margin of two spacings keeps every coordinate positive, as on a CC3D lattice.
    positions = (grid + 2.0) * args.spacing + rng.uniform(-args.jitter, args.jitter, size=grid.shape)
    types = rng.integers(1, 3, size=args.cells)
    names = {1: "Condensing", 2: "NonCondensing"}
    sigma = args.step / math.sqrt(3.0)
    centre = (2.0 + (side - 1) / 2.0) * args.spacing
    drift_sign = numpy.where(types == 1, -1.0, 1.0)[:, None]

    opener = gzip.open if output.endswith(".gz") else open
    with opener(output, "wt", newline="") as out:
        out.write("mcs,cell_id,cluster_id,type_id,type_name,xCOM,yCOM,zCOM,volume\n")
        for frame in range(args.frames):
            if frame > 0:
                radial = positions - centre
                norm = numpy.linalg.norm(radial, axis=1)[:, None]
                norm[norm == 0.0] = 1.0
                positions = (positions + rng.normal(0.0, sigma, size=positions.shape) +
                             args.bias * drift_sign * radial / norm)
            mcs = frame * args.interval
            rows = [
                f"{mcs},{i + 1},{i + 1},{t},{names[t]},{x:.6f},{y:.6f},{z:.6f},{args.volume}\n"
                for i, (t, (x, y, z)) in enumerate(zip(types.tolist(), positions.tolist()))
            ]
            out.writelines(rows)


if __name__ == "__main__":
    main()
