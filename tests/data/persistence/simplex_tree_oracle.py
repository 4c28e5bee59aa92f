"""Oracle for test_persistence_gudhi: persistence over Z/2 of a filtered simplicial complex.

Usage: simplex_tree_oracle.py IN OUT
IN: one simplex per line "<filtration> <v0> <v1> ...", faces before cofaces.
OUT: one line "<dim> <birth> <death>" per pair of positive length (death inf for essential
classes), floats with repr.
"""
import sys

import gudhi


def main():
    stree = gudhi.SimplexTree()
    for line in open(sys.argv[1]):
        f = line.split()
        if f:
            stree.insert([int(v) for v in f[1:]], filtration=float(f[0]))
    stree.compute_persistence(homology_coeff_field=2, min_persistence=0.0, persistence_dim_max=True)
    with open(sys.argv[2], 'w') as out:
        for dim, (b, d) in stree.persistence():
            out.write('%d %r %r\n' % (dim, b, d))


main()
