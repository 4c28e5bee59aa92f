// The combinatorial rules that depend on the dimension d of the run (3, or 2 for planar runs): the
// elementary flip through a facet (docs/MATH.md §4.5: 2-3 / 3-2 in 3D, 2-2 in 2D; hull flips through the
// infinite vertex alike) and the Euler characteristic of the augmented triangulation. Top simplices
// have d + 1 vertices and facets d; the geometric rules (certificate polynomials) are in engine.h and
// the static structures in static_delaunay.h.
#pragma once

#include "medusa/kinetic/simplex.h"
#include "triangulation.h"

#include <cstddef>
#include <vector>

namespace medusa::kinetic::detail {

struct FlipChange {
  std::vector<Simplex> removed, added; // top simplices; removed.front() contains the facet
  bool three_two = false;              // 3D: a 3-2 flip rather than a 2-3 flip
  // A 3-2 flip: the edge of the facet it removes and the facet's third vertex; the new tetrahedra
  // are z p q edge[0] and z p q edge[1].
  Simplex edge;
  VertexId z = infinite_vertex;
};

// The flip of `facet` whose apices are p and q.
inline FlipChange flip_change(int dim, const Simplex& facet, VertexId p, VertexId q,
                              const Triangulation& tri) {
  FlipChange c;
  if (dim == 2) {
    // 2-2 flip of edge xy: the triangles xyp, xyq become pqx, pqy.
    c.removed = {Simplex{facet[0], facet[1], p}, Simplex{facet[0], facet[1], q}};
    c.added = {Simplex{p, q, facet[0]}, Simplex{p, q, facet[1]}};
    return c;
  }
  // A 3-2 flip applies when an edge of the facet has exactly the three tetrahedra facet+p, facet+q
  // and edge+p+q; otherwise the 2-3 flip of the facet.
  for (std::size_t i = 0; i < 3; ++i) {
    Simplex e = facet.facet(i);
    Simplex t{e[0], e[1], p, q};
    if (tri.has_top(t)) {
      c.three_two = true;
      c.edge = e;
      c.z = facet[i];
      const VertexId z = c.z;
      c.removed = {Simplex{facet[0], facet[1], facet[2], p}, Simplex{facet[0], facet[1], facet[2], q}, t};
      c.added = {Simplex{z, p, q, e[0]}, Simplex{z, p, q, e[1]}};
      return c;
    }
  }
  c.removed = {Simplex{facet[0], facet[1], facet[2], p}, Simplex{facet[0], facet[1], facet[2], q}};
  for (std::size_t i = 0; i < 3; ++i) {
    Simplex e = facet.facet(i);
    c.added.push_back(Simplex{e[0], e[1], p, q});
  }
  return c;
}

// The augmented triangulation is a triangulated sphere S^d: with V vertices (the infinite one
// included), E edges, F facets and T top simplices, V - E + F - T = 0 in 3D and V - E + T = 2 in 2D
// (where the facets are the edges).
inline bool euler_characteristic_holds(int dim, std::size_t v, std::size_t e, std::size_t f, std::size_t t) {
  if (dim == 2)
    return v + t == e + 2;
  return v + f == e + t;
}

} // namespace medusa::kinetic::detail
