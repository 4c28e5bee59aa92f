"""Oracle for test_persistence_distances: GUDHI's exact bottleneck distance and Hera's Wasserstein
distance (ground metric L-infinity) on the finite parts of pairs of diagrams.

Usage: distance_oracle.py CASES OUT
CASES: blocks "case <id> <p>" followed by lines "a <birth> <death>" and "b <birth> <death>" (death may
be inf). OUT: one line "<id> <bottleneck> <wasserstein>" per case, floats with repr.
"""
import sys

import gudhi
import gudhi.hera
import numpy as np


def wasserstein_distance(x, y, p):
    # Hera (GUDHI 3.7) crashes or hangs when one side has no finite point, so it gets the finite
    # parts only when both are non-empty; otherwise every point goes to the diagonal. Essential
    # classes are matched by sorted births (docs/MATH.md §7.7) and combined here.
    fx = x[np.isfinite(x[:, 1])]
    fy = y[np.isfinite(y[:, 1])]
    ex = sorted(x[~np.isfinite(x[:, 1])][:, 0])
    ey = sorted(y[~np.isfinite(y[:, 1])][:, 0])
    if len(ex) != len(ey):
        return float('inf')
    if len(fx) and len(fy):
        finite = gudhi.hera.wasserstein_distance(fx, fy, order=p, internal_p=np.inf, delta=1e-9) ** p
    else:
        finite = sum(((d - b) / 2) ** p for b, d in list(fx) + list(fy))
    essential = sum(abs(a - b) ** p for a, b in zip(ex, ey))
    return (finite + essential) ** (1 / p)


def main():
    cases = []
    for line in open(sys.argv[1]):
        f = line.split()
        if not f:
            continue
        if f[0] == 'case':
            cases.append((f[1], float(f[2]), [], []))
        else:
            (cases[-1][2] if f[0] == 'a' else cases[-1][3]).append([float(f[1]), float(f[2])])
    with open(sys.argv[2], 'w') as out:
        for name, p, a, b in cases:
            x = np.array(a, dtype=float).reshape(-1, 2)
            y = np.array(b, dtype=float).reshape(-1, 2)
            bottleneck = gudhi.bottleneck_distance(x, y, e=0)
            wasserstein = wasserstein_distance(x, y, p)
            out.write('%s %r %r\n' % (name, float(bottleneck), float(wasserstein)))


main()
