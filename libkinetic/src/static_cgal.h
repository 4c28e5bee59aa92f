// What the planar and 3D static structures share (static_delaunay_2.cpp, static_delaunay_3.cpp):
// the points of a StaticInput as CGAL points of either dimension, exact or scaled into doubles,
// and CGAL's Delaunay triangulation of them read back as top simplices (infinite vertex = -1).
// Only the CGAL types and the alpha shapes' face enumerations differ between the two dimensions.
#pragma once

#include "cell_triangulation.h"
#include "static_delaunay.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
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

// Whether dt, CGAL's Delaunay triangulation of the points at u + delta, is Del(u+) (docs/MATH.md §5.5,
// method A): it has every point as a vertex, and no certificate it rests on has a root in
// (u, u + delta]: the orientation of each finite top simplex, the in-sphere (in-circle) test across
// each facet between two finite ones, and at each ridge of the hull the orientation of a hull facet
// with the neighbouring hull facet's far vertex. dt is a Delaunay triangulation at u + delta, and
// the kinetic structure these certificates make stays one while none of them changes sign, so it is
// the Delaunay triangulation throughout (u, u + delta], hence Del(u+). A triangulation that is flat
// at u + delta holds only when the points are flat for good (docs/MATH.md §5.7); the caller reports them.
template <int D, class Dt>
bool just_after_holds(const Dt& dt, const StaticInput& input, const CGAL::Gmpq& u, const CGAL::Gmpq& delta) {
  if (dt.dimension() < D)
    return flat_for_good(D, input);
  if (dt.number_of_vertices() != input.ids.size())
    return false;                         // two cells meet at u + delta: CGAL keeps one of them
  std::vector<const MovingPoint*> motion; // by vertex id
  for (std::size_t i = 0; i < input.ids.size(); ++i) {
    const auto id = static_cast<std::size_t>(input.ids[i]);
    if (motion.size() <= id)
      motion.resize(id + 1, nullptr);
    motion[id] = &input.motion[i];
  }
  auto m = [&](auto v) { return motion[static_cast<std::size_t>(v->info())]; };
  std::vector<const MovingPoint*> p(D + 1), hull(D + 1);
  auto check = [&](auto c) {
    const bool infinite = dt.is_infinite(c);
    if (!infinite) {
      for (int i = 0; i <= D; ++i)
        p[static_cast<std::size_t>(i)] = m(c->vertex(i));
      if (!orientation_keeps_sign(p, u, delta))
        return false;
    }
    for (int i = 0; i <= D; ++i) {
      const auto n = c->neighbor(i);
      if (std::less<const void*>()(&*n, &*c))
        continue; // each facet once
      const auto q = n->vertex(n->index(c));
      if (!infinite && !dt.is_infinite(n)) {
        if (!in_sphere_keeps_sign(p, *m(q), u, delta))
          return false;
      } else if (infinite && dt.is_infinite(n)) {
        // A ridge of the hull: c's hull facet with the infinite vertex replaced by q, the far vertex
        // of the neighbouring hull facet (finite, since the facet holds the infinite vertex).
        const int j = c->index(dt.infinite_vertex());
        for (int k = 0; k <= D; ++k)
          hull[static_cast<std::size_t>(k)] = m(k == j ? q : c->vertex(k));
        if (!orientation_keeps_sign(hull, u, delta))
          return false;
      }
    }
    return true;
  };
  if constexpr (D == 2) {
    for (auto f = dt.all_faces_begin(); f != dt.all_faces_end(); ++f)
      if (!check(f))
        return false;
  } else {
    for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c)
      if (!check(c))
        return false;
  }
  return true;
}

// The top simplices of the Delaunay triangulation Dt (vertices labelled with their ids) of pts, and
// the affine dimension of pts in `dimension`. Given `after`, pts being the points at after + delta,
// `holds` tells whether it is Del(after+) of the input's motion (just_after_holds).
template <int D, class Dt>
std::vector<Simplex> triangulate(const std::vector<std::pair<typename Dt::Point, VertexId>>& pts,
                                 int& dimension, const StaticInput& input, const CGAL::Gmpq* after,
                                 const CGAL::Gmpq& delta, bool* holds) {
  Dt dt(pts.begin(), pts.end());
  dimension = dt.dimension();
  if (after)
    *holds = just_after_holds<D>(dt, input, *after, delta);
  return top_simplices<D>(dt);
}

} // namespace medusa::kinetic::detail
