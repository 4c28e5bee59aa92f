// Collision checks: two cells at one position at a frame, or meeting inside a slab (docs/MATH.md §2.5).
#pragma once

#include "engine.h"
#include "medusa/core/grid_text.h"

#include "collision.h"
#include "medusa/core/error.h"

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace medusa::kinetic::detail {

template <class K> void Engine<K>::check_collisions_at_frame(std::size_t k) const {
  std::vector<std::pair<GridPoint, std::size_t>> pos;
  for (std::size_t i = 0; i < traj.cells.size(); ++i)
    if (traj.cells[i].present(k))
      pos.emplace_back(traj.cells[i].at(k), i);
  std::sort(pos.begin(), pos.end());
  for (std::size_t i = 1; i < pos.size(); ++i) {
    if (pos[i].first != pos[i - 1].first)
      continue;
    std::string at;
    for (int a = 0; a < K::dimension; ++a)
      at += (a ? ", " : "") + grid_coordinate_text(pos[i].first[static_cast<std::size_t>(a)], traj.scale);
    throw GeometryError("cells " + std::to_string(traj.cells[pos[i - 1].second].cell_id) + " and " +
                        std::to_string(traj.cells[pos[i].second].cell_id) +
                        " are at the same position at frame " + std::to_string(k) + " (MCS " +
                        std::to_string(traj.frame_times[k]) + ", centre (" + at +
                        ")): two cells cannot share a centre (docs/MATH.md §2.5)");
  }
}

// Collision inside the slab (docs/MATH.md §2.5): p_i(u) = p_j(u) for some u in (now, 1). Tested on the
// Delaunay edges at the slab start and on every edge when it is created: colliding cells are
// joined by a Delaunay edge just before they meet. Decided in integers (meeting_in_slab); only a
// real collision builds the rational root.
template <class K>
void Engine<K>::note_collision(const Simplex& e, std::optional<Collision>& earliest) const {
  const std::optional<MeetingTime> meeting = meeting_in_slab(pt(e[0]), pt(e[1]));
  if (!meeting)
    return;
  mpq_class root(mpz_class(meeting->num), mpz_class(meeting->den));
  root.canonicalize();
  if (!(now < SlabTime(Rational(root.get_mpq_t()))))
    return;
  if (!earliest || root < earliest->first || (root == earliest->first && e < earliest->second))
    earliest.emplace(std::move(root), e);
}

template <class K> void Engine<K>::throw_collision(const Collision& c) const {
  const auto& [u, e] = c;
  const double t = double(traj.frame_times[slab]) +
                   u.get_d() * double(traj.frame_times[slab + 1] - traj.frame_times[slab]);
  throw GeometryError(
      "cells " + std::to_string(traj.cells[static_cast<std::size_t>(e[0])].cell_id) + " and " +
      std::to_string(traj.cells[static_cast<std::size_t>(e[1])].cell_id) + " collide at time " +
      std::to_string(t) + " (between the frames at MCS " + std::to_string(traj.frame_times[slab]) + " and " +
      std::to_string(traj.frame_times[slab + 1]) + "): two cells cannot share a centre (docs/MATH.md §2.5)");
}

// Of the collisions the Delaunay edges at the slab start foretell, the earliest is reported (among
// equal times the pair first in trajectory order), whatever order the edges are visited in.
template <class K> void Engine<K>::check_collisions_in_slab() const {
  std::optional<Collision> earliest;
  faces.for_each([&](const Simplex& s, const Face&) {
    if (s.size() == 2)
      note_collision(s, earliest);
  });
  if (earliest)
    throw_collision(*earliest);
}

} // namespace medusa::kinetic::detail
