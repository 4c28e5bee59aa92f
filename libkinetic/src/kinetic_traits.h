// What differs between 3D runs and planar runs (docs/MATH.md §5.7), as a compile-time traits type:
// the engine is Engine<KineticTraits3> or Engine<KineticTraits2>, chosen once per run from the
// trajectories' dimension, so no event pays for a runtime test of the dimension. Each traits type
// gives the size of a top simplex, the certificate formulas on its points (orientation, in-sphere or
// in-circle, the fold of two hull facets), the flip rule through a facet (docs/MATH.md §4.5: 2-3 / 3-2
// in 3D, 2-2 in the plane; hull flips through the infinite vertex alike) and the Euler characteristic
// of the augmented triangulation. The static CGAL structures are chosen on the dimension in
// static_delaunay.h. Everything else in the engine is shared.
//
// Points are given by an accessor `at` from vertex ids: moving points (the polynomial in u) or points
// at one time enclosure (its value there), as in certificate_polynomials.h.
#pragma once

#include "cell_triangulation.h"
#include "certificate_enclosure.h"
#include "certificate_polynomials.h"
#include "medusa/kinetic/simplex.h"

#include <array>
#include <cstddef>
#include <vector>

namespace medusa::kinetic::detail {

// The change of top simplices of one elementary flip.
struct FlipChange {
  std::vector<Simplex> removed, added; // top simplices; removed.front() contains the facet
  bool three_two = false;              // 3D: a 3-2 flip rather than a 2-3 flip
  // A 3-2 flip: the edge of the facet it removes and the facet's third vertex; the new tetrahedra
  // are z p q edge[0] and z p q edge[1].
  Simplex edge;
  VertexId z = infinite_vertex;
};

template <int D> struct KineticTraits;

// What the two dimensions share: a top simplex's vertices as a sequence.
template <int D> struct KineticTraitsBase {
  static constexpr int dimension = D;
  static constexpr std::size_t top_size = D + 1;
  using Vertices = std::array<VertexId, top_size>;
  // The vertices of s in order, then x...: top_size of them.
  template <class... X> static Vertices join(const Simplex& s, X... x) {
    Vertices v{};
    std::size_t n = 0;
    for (VertexId y : s)
      v[n++] = y;
    ((v[n++] = x), ...);
    return v;
  }
};

template <> struct KineticTraits<3> : KineticTraitsBase<3> {
  // O(v0, v1, v2, v3), the sign of CGAL::orientation.
  template <class NT, class At> static auto orientation(const Vertices& v, const At& at) {
    return certificate::orientation<NT>(at(v[0]), at(v[1]), at(v[2]), at(v[3]));
  }
  // InS(v; y): of sign `outside_sign` times the orientation of v iff y is strictly outside the
  // circumsphere of v, 0 iff on it.
  static constexpr int outside_sign = 1;
  template <class NT, class At> static auto in_sphere(const Vertices& v, VertexId y, const At& at) {
    return certificate::in_sphere<NT>(at(v[0]), at(v[1]), at(v[2]), at(v[3]), at(y));
  }
  // in_sphere<Interval> enclosed from one pass in plain doubles (certificate_enclosure.h).
  template <class At> static IntervalPoly in_sphere_enclosure(const Vertices& v, VertexId y, const At& at) {
    return medusa::kinetic::in_sphere_enclosure(at(v[0]), at(v[1]), at(v[2]), at(v[3]), at(y));
  }
  // Facets a b p and a b q at the ridge a b: dot((b - a) x (p - a), (b - a) x (q - a)). When the
  // four points are coplanar it is positive iff the facets are folded onto each other, negative iff
  // they lie side by side.
  template <class NT, class At> static auto fold(const Simplex& ridge, VertexId p, VertexId q, const At& at) {
    const auto ab = certificate::difference<NT>(at(ridge[0]), at(ridge[1]));
    return certificate::dot<NT>(certificate::cross<NT>(ab, certificate::difference<NT>(at(ridge[0]), at(p))),
                                certificate::cross<NT>(ab, certificate::difference<NT>(at(ridge[0]), at(q))));
  }
  // The flip of `facet` whose apices are p and q: a 3-2 flip when an edge of the facet has exactly
  // the three tetrahedra facet+p, facet+q and edge+p+q; otherwise the 2-3 flip of the facet.
  // has_top(t): is the tetrahedron t in the triangulation.
  template <class HasTop>
  static FlipChange flip(const Simplex& facet, VertexId p, VertexId q, HasTop&& has_top) {
    FlipChange c;
    for (std::size_t i = 0; i < 3; ++i) {
      Simplex e = facet.facet(i);
      Simplex t{e[0], e[1], p, q};
      if (has_top(t)) {
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
  // The augmented triangulation is a triangulated 3-sphere: with V vertices (the infinite one
  // included), E edges, F facets and T top simplices, V - E + F - T = 0.
  static bool euler_characteristic_holds(std::size_t v, std::size_t e, std::size_t f, std::size_t t) {
    return v + f == e + t;
  }
};

template <> struct KineticTraits<2> : KineticTraitsBase<2> {
  // O2(v0, v1, v2) over (x, y), positive counterclockwise.
  template <class NT, class At> static auto orientation(const Vertices& v, const At& at) {
    return certificate::orientation_2<NT>(at(v[0]), at(v[1]), at(v[2]));
  }
  // InC(v; y) is positive iff y is strictly inside the circumcircle of a counterclockwise v: the
  // opposite convention to InS (certificate_polynomials.h).
  static constexpr int outside_sign = -1;
  template <class NT, class At> static auto in_sphere(const Vertices& v, VertexId y, const At& at) {
    return certificate::in_circle<NT>(at(v[0]), at(v[1]), at(v[2]), at(y));
  }
  template <class At> static IntervalPoly in_sphere_enclosure(const Vertices& v, VertexId y, const At& at) {
    return medusa::kinetic::in_circle_enclosure(at(v[0]), at(v[1]), at(v[2]), at(y));
  }
  // Edges a p and a q at the ridge vertex a: dot(p - a, q - a), positive iff folded onto each other
  // when the three points are collinear.
  template <class NT, class At> static auto fold(const Simplex& ridge, VertexId p, VertexId q, const At& at) {
    return certificate::dot<NT>(certificate::difference<NT>(at(ridge[0]), at(p)),
                                certificate::difference<NT>(at(ridge[0]), at(q)));
  }
  // The 2-2 flip of edge xy: the triangles xyp, xyq become pqx, pqy.
  template <class HasTop> static FlipChange flip(const Simplex& facet, VertexId p, VertexId q, HasTop&&) {
    FlipChange c;
    c.removed = {Simplex{facet[0], facet[1], p}, Simplex{facet[0], facet[1], q}};
    c.added = {Simplex{p, q, facet[0]}, Simplex{p, q, facet[1]}};
    return c;
  }
  // A triangulated 2-sphere, whose facets are its edges: V - E + T = 2.
  static bool euler_characteristic_holds(std::size_t v, std::size_t e, std::size_t, std::size_t t) {
    return v + t == e + 2;
  }
};

using KineticTraits2 = KineticTraits<2>;
using KineticTraits3 = KineticTraits<3>;

} // namespace medusa::kinetic::detail
