// Collision checks: two cells at one position at a frame, or meeting inside a slab (docs/MATH.md §2.5).
#pragma once

#include "engine.h"

#include "collision.h"
#include "medusa/core/error.h"

#include <algorithm>
#include <string>
#include <vector>

namespace medusa::kinetic::detail {

template <class K> void Engine<K>::check_collisions_at_frame(std::size_t k) const {
  std::vector<std::pair<GridPoint, std::size_t>> pos;
  for (std::size_t i = 0; i < traj.cells.size(); ++i)
    if (traj.cells[i].present(k))
      pos.emplace_back(traj.cells[i].at(k), i);
  std::sort(pos.begin(), pos.end());
  for (std::size_t i = 1; i < pos.size(); ++i)
    if (pos[i].first == pos[i - 1].first)
      throw GeometryError("cells " + std::to_string(traj.cells[pos[i - 1].second].cell_id) + " and " +
                          std::to_string(traj.cells[pos[i].second].cell_id) +
                          " are at the same position at frame " + std::to_string(k) + " (time " +
                          std::to_string(traj.frame_times[k]) + ")");
}

// Collision inside the slab (docs/MATH.md §2.5): p_i(u) = p_j(u) for some u in (now, 1). Tested on the
// Delaunay edges at the slab start and on every edge when it is created: colliding cells are
// joined by a Delaunay edge just before they meet. Decided in integers (meeting_in_slab); only a
// real collision builds the rational root.
template <class K> void Engine<K>::check_collision(const Simplex& e) const {
  const std::optional<MeetingTime> meeting = meeting_in_slab(pt(e[0]), pt(e[1]));
  if (!meeting)
    return;
  mpq_class root(mpz_class(meeting->num), mpz_class(meeting->den));
  root.canonicalize();
  if (!(now < SlabTime(Rational(root.get_mpq_t()))))
    return;
  double t = double(traj.frame_times[slab]) +
             root.get_d() * double(traj.frame_times[slab + 1] - traj.frame_times[slab]);
  throw GeometryError("cells " + std::to_string(traj.cells[static_cast<std::size_t>(e[0])].cell_id) +
                      " and " + std::to_string(traj.cells[static_cast<std::size_t>(e[1])].cell_id) +
                      " collide at time " + std::to_string(t));
}

template <class K> void Engine<K>::check_collisions_in_slab() const {
  // In the plane the Delaunay edges are the triangulation's facets, whose table is smaller than the
  // faces' (which holds the triangles too): this pass runs at every frame.
  if constexpr (dim == 2) {
    tri.for_each_facet([this](const Simplex& e, const detail::Triangulation::Apices&) {
      if (is_finite(e))
        check_collision(e);
    });
    return;
  }
  faces.for_each([this](const Simplex& s, const Face&) {
    if (s.size() == 2)
      check_collision(s);
  });
}

} // namespace medusa::kinetic::detail
