"""Oracle for test_persistence_gudhi: the static alpha complex of a point set with GUDHI.

Usage: alpha_oracle.py POINTS TYPES OUT
POINTS: one point per line "x y z"; TYPES: one integer type per point (same order).
Writes to OUT:
  S <filtration> <v0> <v1> ...       every simplex of the alpha complex (filtration = squared radius)
  P <type> <dim> <birth> <death>     persistence over Z/2 of positive length (type -1: whole complex,
                                     else the full subcomplex on the vertices of that type); death inf
                                     for essential classes
Floats are printed with repr (round-trip exact).
"""
import sys

import gudhi


def main():
    points_file, types_file, out_file = sys.argv[1:4]
    points = [[float(x) for x in line.split()] for line in open(points_file) if line.strip()]
    types = [int(line) for line in open(types_file) if line.strip()]
    stree = gudhi.AlphaComplex(points=points, precision='exact').create_simplex_tree()
    simplices = list(stree.get_filtration())
    lines = []
    for simplex, value in simplices:
        lines.append('S %r %s' % (value, ' '.join(str(v) for v in sorted(simplex))))

    def persistence(tree):
        tree.compute_persistence(homology_coeff_field=2, min_persistence=0.0, persistence_dim_max=True)
        return [(dim, b, d) for dim, (b, d) in tree.persistence()]

    result = [(-1, p) for p in persistence(stree)]
    for t in sorted(set(types)):
        sub = gudhi.SimplexTree()
        for simplex, value in simplices:
            if all(types[v] == t for v in simplex):
                sub.insert(simplex, value)
        result += [(t, p) for p in persistence(sub)]
    for t, (dim, b, d) in result:
        lines.append('P %d %d %r %r' % (t, dim, b, d))
    with open(out_file, 'w') as f:
        f.write('\n'.join(lines) + '\n')


main()
