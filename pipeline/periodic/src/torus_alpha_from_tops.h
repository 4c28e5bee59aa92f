// The alpha complex on the torus read off a triangulation of its lift: shared by the periodic and the
// tiled constructions of torus_alpha_complex (docs/MATH.md §8.7).
#pragma once

#include "medusa/kinetic/simplex.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <set>
#include <vector>

namespace medusa::periodic::detail {

using Offset = std::array<std::int64_t, 3>;

// A vertex of a top simplex of the lift: point `id` translated by `offset` periods, at `p`.
template <class Point> struct LiftedVertex {
  kinetic::VertexId id = 0;
  Offset offset{};
  Point p;
};

// The torus simplex a lifted vertex set maps to: its (id, offset) pairs translated so that one of them
// has offset zero, the smallest such list over the choices (independent of the lift).
template <class Point> std::vector<std::int64_t> torus_key(const std::vector<const LiftedVertex<Point>*>& s) {
  std::vector<std::int64_t> best;
  for (const LiftedVertex<Point>* base : s) {
    std::vector<std::array<std::int64_t, 4>> image;
    for (const LiftedVertex<Point>* v : s)
      image.push_back({v->id, v->offset[0] - base->offset[0], v->offset[1] - base->offset[1],
                       v->offset[2] - base->offset[2]});
    std::sort(image.begin(), image.end());
    std::vector<std::int64_t> key;
    for (const auto& e : image)
      key.insert(key.end(), e.begin(), e.end());
    if (best.empty() || key < best)
      best = std::move(key);
  }
  return best;
}

// The alpha complex is the closure of the simplices of Del whose smallest circumsphere has radius at
// most rho and holds no vertex of a coface strictly inside (docs/MATH.md §8.7): each top simplex
// votes, for each of its faces, on that face's shortness and whether it is attached. `eligible`
// says which faces of a top simplex see all their cofaces (every face for a periodic triangulation;
// the faces with an original vertex for the tiled copies). `Geometry` decides exactly, for the
// smallest circumsphere of the points, whether its radius is at most rho (short(points)) and whether
// q lies strictly inside it (strictly_inside(points, q)).
template <class Geometry, class Point, class Eligible>
std::vector<kinetic::Simplex> alpha_from_tops(const std::vector<std::vector<LiftedVertex<Point>>>& tops,
                                              const Geometry& geometry,
                                              const std::vector<kinetic::VertexId>& ids, Eligible eligible) {
  struct Vote {
    std::vector<kinetic::VertexId> ids;
    bool top = false, attached = false;
  };
  std::map<std::vector<std::int64_t>, Vote> votes;
  for (const auto& top : tops) {
    const std::size_t n = top.size();
    for (unsigned mask = 1; mask < (1u << n); ++mask) {
      std::vector<const LiftedVertex<Point>*> face;
      std::vector<const Point*> pts;
      for (std::size_t i = 0; i < n; ++i)
        if (mask & (1u << i)) {
          face.push_back(&top[i]);
          pts.push_back(&top[i].p);
        }
      if (face.size() < 2 || !eligible(face))
        continue;
      if (!geometry.is_short(pts))
        continue;
      Vote& vote = votes[torus_key(face)];
      if (vote.ids.empty())
        for (const auto* v : face)
          vote.ids.push_back(v->id);
      if (face.size() == n)
        vote.top = true;
      for (std::size_t i = 0; i < n && !vote.attached; ++i)
        if (!(mask & (1u << i)) && geometry.strictly_inside(pts, top[i].p))
          vote.attached = true;
    }
  }
  std::set<kinetic::Simplex> complex;
  for (kinetic::VertexId v : ids)
    complex.insert(kinetic::Simplex{v});
  for (auto& kv : votes) {
    if (!kv.second.top && kv.second.attached)
      continue;
    std::vector<kinetic::VertexId>& v = kv.second.ids;
    std::sort(v.begin(), v.end());
    for (unsigned mask = 1; mask < (1u << v.size()); ++mask) {
      std::vector<kinetic::VertexId> sub;
      for (std::size_t i = 0; i < v.size(); ++i)
        if (mask & (1u << i))
          sub.push_back(v[i]);
      complex.insert(kinetic::Simplex::from_range(sub.begin(), sub.end()));
    }
  }
  return {complex.begin(), complex.end()};
}

} // namespace medusa::periodic::detail
