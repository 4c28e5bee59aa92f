#!/usr/bin/python3
"""Hera baseline of distance_bench: the same pairwise distances through gudhi.hera, timed in one process.

Usage: hera_baseline.py MANIFEST OUTPUT.json

MANIFEST lines: `group<TAB>metric<TAB>file_1<TAB>...<TAB>file_n`, metric one of bottleneck, w1, w2; each
file holds the finite points of one diagram, `birth death` per line (%.17g), diagonal points already
left out (Hera's bottleneck does not accept them). For every i < j both diagrams of which have points
(GUDHI 3.7's Hera does not return on an empty diagram; distance_bench skips the same pairs) the
distance is computed as our library defines it (docs/MATH.md §7.7): bottleneck exact (delta = 0),
W_p with the L-infinity ground metric (internal_p = inf) and Hera's relative error delta = 0.01.
Only the distance calls are timed, not the reading of the files.
OUTPUT.json: [{"group", "metric", "seconds", "pairs": [[i, j, value], ...]}, ...].
"""
import json
import math
import os
import sys
import time

import numpy as np
import gudhi.hera


def load(path):
    if os.path.getsize(path) == 0:
        return np.empty((0, 2), dtype=np.float64)
    return np.loadtxt(path, dtype=np.float64, ndmin=2).reshape(-1, 2)


def distance_function(metric):
    if metric == "bottleneck":
        return lambda a, b: gudhi.hera.bottleneck_distance(a, b, delta=0)
    order = {"w1": 1.0, "w2": 2.0}[metric]
    return lambda a, b: gudhi.hera.wasserstein_distance(a, b, order=order, internal_p=math.inf, delta=0.01)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    results = []
    with open(sys.argv[1]) as manifest:
        for line in manifest:
            fields = line.rstrip("\n").split("\t")
            group, metric, files = fields[0], fields[1], fields[2:]
            diagrams = [load(f) for f in files]
            distance = distance_function(metric)
            pairs = [(i, j) for i in range(len(diagrams)) for j in range(i + 1, len(diagrams))
                     if len(diagrams[i]) and len(diagrams[j])]
            values = []
            start = time.perf_counter()
            for i, j in pairs:
                values.append(distance(diagrams[i], diagrams[j]))
            seconds = time.perf_counter() - start
            results.append({"group": group, "metric": metric, "seconds": seconds,
                            "pairs": [[i, j, v] for (i, j), v in zip(pairs, values)]})
    with open(sys.argv[2], "w") as out:
        json.dump(results, out)


if __name__ == "__main__":
    main()
