"""Oracle for test_persistence_clustering: scipy's hierarchical clustering.

Usage: linkage_oracle.py MATRIX METHOD OUT
MATRIX: first line n, then n rows of n distances. OUT: one line per merge "<first> <second> <height>
<size>" (scipy's linkage matrix; clusters n+k are made by merge k), floats with repr.
"""
import sys

import numpy as np
from scipy.cluster.hierarchy import linkage
from scipy.spatial.distance import squareform


def main():
    matrix_file, method, out_file = sys.argv[1:4]
    rows = [line.split() for line in open(matrix_file) if line.strip()]
    n = int(rows[0][0])
    d = np.array([[float(x) for x in row] for row in rows[1:n + 1]])
    z = linkage(squareform(d, checks=True), method=method)
    with open(out_file, 'w') as out:
        for a, b, h, s in z:
            out.write('%d %d %r %d\n' % (int(a), int(b), float(h), int(s)))


main()
