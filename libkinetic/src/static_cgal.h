// What the planar and 3D static structures share (static_delaunay_2.cpp, static_delaunay_3.cpp):
// the points of a StaticInput as CGAL points of either dimension, exact or scaled into doubles,
// and CGAL's Delaunay triangulation of them read back as top simplices (infinite vertex = -1).
// Only the CGAL types and the alpha shapes' face enumerations differ between the two dimensions.
#pragma once

#include "static_delaunay.h"
#include "triangulation.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace medusa::kinetic::detail {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;

// Epeck's exact number type is gmpxx's mpq_class.
inline Epeck::FT exact(const CGAL::Gmpq& q) { return Epeck::FT(mpq_class(q.mpq())); }

template <class K, int D>
using PointOf = std::conditional_t<D == 2, typename K::Point_2, typename K::Point_3>;
template <class K, int D> using LabelledPoints = std::vector<std::pair<PointOf<K, D>, VertexId>>;

template <class K, int D> PointOf<K, D> make_point(const std::array<typename K::FT, 3>& c) {
  if constexpr (D == 2)
    return PointOf<K, D>(c[0], c[1]); // a planar run: z is constant and plays no part
  else
    return PointOf<K, D>(c[0], c[1], c[2]);
}

// The points 2^k a + b: the points a + 2^-k b scaled by 2^k, exact in doubles for the k that
// delaunay_just_after picks (so Epick's exact predicates decide on the exact points).
template <int D> LabelledPoints<Epick, D> scaled_points(const StaticInput& input, int k) {
  LabelledPoints<Epick, D> pts;
  pts.reserve(input.ids.size());
  for (std::size_t i = 0; i < input.ids.size(); ++i) {
    const MovingPoint& m = input.motion[i];
    std::array<double, 3> c{};
    for (std::size_t a = 0; a < D; ++a)
      c[a] = std::ldexp(double(m.a[a]), k) + double(m.b[a]);
    pts.emplace_back(make_point<Epick, D>(c), input.ids[i]);
  }
  return pts;
}

// The points a + u b exactly.
template <int D> LabelledPoints<Epeck, D> exact_points(const StaticInput& input, const CGAL::Gmpq& u) {
  LabelledPoints<Epeck, D> pts;
  pts.reserve(input.ids.size());
  for (std::size_t i = 0; i < input.ids.size(); ++i) {
    const MovingPoint& m = input.motion[i];
    std::array<Epeck::FT, 3> c;
    for (std::size_t a = 0; a < D; ++a)
      c[a] = exact(CGAL::Gmpq(CGAL::Gmpz(m.a[a])) + u * CGAL::Gmpq(CGAL::Gmpz(m.b[a])));
    pts.emplace_back(make_point<Epeck, D>(c), input.ids[i]);
  }
  return pts;
}

// The top simplex of a cell (3D) or face (2D) handle of dt: D + 1 vertices, the infinite one as -1.
template <int D, class Dt, class Handle> Simplex top_simplex(const Dt& dt, Handle c) {
  std::array<VertexId, D + 1> v;
  for (int i = 0; i <= D; ++i)
    v[static_cast<std::size_t>(i)] = dt.is_infinite(c->vertex(i)) ? infinite_vertex : c->vertex(i)->info();
  return Simplex::from_range(v.begin(), v.end());
}

// Every top simplex of dt, infinite ones included; none when the points span fewer than D dimensions.
template <int D, class Dt> std::vector<Simplex> top_simplices(const Dt& dt) {
  std::vector<Simplex> result;
  if (dt.dimension() < D)
    return result;
  if constexpr (D == 2) {
    for (auto f = dt.all_faces_begin(); f != dt.all_faces_end(); ++f)
      result.push_back(top_simplex<2>(dt, f));
  } else {
    for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c)
      result.push_back(top_simplex<3>(dt, c));
  }
  return result;
}

// The top simplices of the Delaunay triangulation Dt (vertices labelled with their ids) of pts, and
// the affine dimension of pts in `dimension`.
template <int D, class Dt>
std::vector<Simplex> triangulate(const std::vector<std::pair<typename Dt::Point, VertexId>>& pts,
                                 int& dimension) {
  Dt dt(pts.begin(), pts.end());
  dimension = dt.dimension();
  return top_simplices<D>(dt);
}

} // namespace medusa::kinetic::detail
