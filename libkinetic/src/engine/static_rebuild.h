// Static rebuilds of Del with CGAL at now+ (insertions, deletions, repairs; docs/MATH.md §5.4, §5.5).
#pragma once

#include "engine.h"

#include "certificate_polynomials.h"
#include "medusa/core/error.h"
#include "static_delaunay.h"

#include <algorithm>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace medusa::kinetic::detail {

template <class K> detail::StaticInput Engine<K>::static_input(const std::vector<VertexId>& ids) const {
  detail::StaticInput in;
  for (VertexId v : ids) {
    in.ids.push_back(v);
    in.motion.push_back(pt(v));
  }
  return in;
}

template <class K> std::vector<VertexId> Engine<K>::alive_ids() const {
  std::vector<VertexId> ids;
  for (std::size_t i = 0; i < alive.size(); ++i)
    if (alive[i])
      ids.push_back(static_cast<VertexId>(i));
  return ids;
}

// Rebuilds Del of the current vertex set at now+ with CGAL and replaces the differing top simplices.
template <class K> void Engine<K>::rebuild_static(OldMembership* old_k) {
  ++stats.static_rebuilds;
  std::vector<VertexId> ids = alive_ids();
  int dimension = 0;
  std::vector<Simplex> tops =
      now.is_rational() ? detail::delaunay_just_after(dim, static_input(ids), now.rational(), dimension)
                        : delaunay_after_algebraic_now(ids, dimension);
  if (dimension < dim) {
    // docs/MATH.md §5.7: degenerate input is reported, in either dimension, at the MCS the input names.
    const std::string at =
        now.is_rational() && now.rational() == 0
            ? "frame " + std::to_string(slab) + " (MCS " + std::to_string(traj.frame_times[slab]) + ")"
            : "a time between MCS " + std::to_string(traj.frame_times[slab]) + " and " +
                  std::to_string(traj.frame_times[slab + 1]);
    if (ids.size() < top_size())
      throw GeometryError("fewer than " + std::to_string(top_size()) + " cells are present at " + at +
                          ": the " + std::to_string(dim) + "D alpha complex needs at least " +
                          std::to_string(top_size()));
    if constexpr (dim == 2)
      throw GeometryError("all cells lie on one line at " + at +
                          ": the 2D method needs cells spanning the plane");
    throw GeometryError("all cells lie in one plane at " + at +
                        " (a 2D run given as 3D data?): the 3D method needs cells spanning space");
  }
  // CGAL lists the simplices in an order that follows its insertion order, which its spatial sort
  // draws from CGAL's default random generator (process-wide state). Sorted, the order of the
  // changes below, and of the certificates they build, does not depend on it.
  std::sort(tops.begin(), tops.end());
  std::vector<Simplex> removed, added;
  std::vector<CellIndex> removed_cells, kept;
  if (cells.size() == 0) {
    added = std::move(tops); // the first triangulation: no table of the target is needed
  } else {
    std::unordered_set<Simplex, SimplexHash> target(tops.begin(), tops.end());
    std::unordered_map<Simplex, CellIndex, SimplexHash> current;
    cells.for_each_cell([&](CellIndex c) {
      const Simplex t = cells.top(c);
      current.emplace(t, c);
      if (!target.count(t))
        removed_cells.push_back(c);
    });
    removed = sort_by_top(removed_cells);
    for (const Simplex& t : tops)
      if (const auto it = current.find(t); it != current.end())
        kept.push_back(it->second);
      else
        added.push_back(t);
  }
  change_tops(removed, removed_cells, added, old_k);
  reinstall_hull_ridges_over(added, removed);
  reorient_kept(kept);
}

// A hull ridge's certificate (docs/MATH.md §3.2 case B) is oriented by the recorded orientation of the top
// simplex below one of its hull facets, which is not a face of the ridge's own top simplices. A
// static change can replace that simplex and leave the ridge's top simplices as they were, so
// change_tops does not rebuild the certificate. After a flip that is harmless: the old and the
// new simplex below lie on the inner side of the hull facet just after now, so the orientation is
// the same. A static change may replace one whose recorded orientation had turned stale (flat at
// now, inside out just after, which is why the frame or the batch repairs), and the certificate
// built on it keeps the wrong sign and fails after every repair (docs/MATH.md §5.10). So the certificates of
// the hull ridges over every hull facet of an added top simplex are built again, unless the change built them
// already (infinite facets of changed top simplices).
template <class K>
void Engine<K>::reinstall_hull_ridges_over(const std::vector<Simplex>& added,
                                           const std::vector<Simplex>& removed) {
  std::unordered_set<Simplex, SimplexHash> built;
  for (const auto* list : {&added, &removed})
    for (const Simplex& t : *list)
      if (!is_finite(t))
        for (std::size_t i = 0; i < t.size(); ++i)
          built.insert(t.facet(i));
  std::vector<Simplex> ridges;
  for (std::size_t k = 0; k < added.size(); ++k) {
    if (!is_finite(added[k]))
      continue;
    for (int i = 0; i <= dim; ++i)
      for_each_hull_ridge_over(created_cells[k], i, [&](const Simplex& ridge) {
        if (built.insert(ridge).second)
          ridges.push_back(ridge);
      });
  }
  std::sort(ridges.begin(), ridges.end()); // certificates built in a canonical order
  for (const Simplex& r : ridges)
    install_facet_at(r);
}

// Del at a rational q after an algebraic now, with q close enough that the result is Del(now+): every
// certificate it rests on (orientations of finite top simplices, in-spheres across finite facets,
// hull ridges) has at q the sign it has just after now. q starts before the next queued event, but
// that bounds the events of the old triangulation only. A top simplex of the new one passing through
// flat in (now, q] would lie folded over its neighbours just after now with every local certificate
// valid, at the hull too (docs/MATH.md §5.5). An in-sphere failing in (now, q] would be flipped at
// now+, but the flips would depend on q, which depends on how the queue's times were rounded.
// Each retry at least quarters q - now (rational_closer_after), so the loop ends once q - now is
// below the distance from now to the first root after it of the result's certificates; the cap,
// 2^-2048 of the first gap, only guards that, as in delaunay_just_after.
template <class K>
std::vector<Simplex> Engine<K>::delaunay_after_algebraic_now(const std::vector<VertexId>& ids,
                                                             int& dimension) {
  Rational q = rational_before_next_event();
  // A certificate whose enclosure keeps one sign on [now, q] has that sign at q and just after now:
  // most of them, and the exact polynomial is built only for those that vanish near now (docs/MATH.md
  // §3.8, filter first).
  double now_lo, now_hi;
  now.enclosure(now_lo, now_hi);
  double q_hi = CGAL::to_interval(q).second;
  const auto same_sign = [&](const auto& build) {
    {
      CGAL::Protect_FPU_rounding<true> guard;
      if (interval_sign(build(Interval()), now_lo, q_hi) != 0) {
        ++stats.sign_evaluations;
        return true;
      }
    }
    return static_cast<int>(CGAL::sign(value_at(build(mpz_class()), q))) == sign_plus_now(build);
  };
  for (int attempt = 0; attempt < 1024; ++attempt) {
    std::vector<Simplex> tops = detail::delaunay_at(dim, static_input(ids), q, dimension);
    if (dimension < dim)
      return tops; // flat input, reported by the caller
    std::unordered_map<Simplex, std::vector<VertexId>, SimplexHash> apices;
    bool holds = true;
    for (const Simplex& t : tops) {
      for (std::size_t i = 0; i < t.size(); ++i)
        apices[t.facet(i)].push_back(t[i]);
      if (holds && is_finite(t))
        holds = same_sign([&](auto tag) { return orientation_poly<decltype(tag)>(t); });
    }
    for (auto it = apices.begin(); holds && it != apices.end(); ++it) {
      const Simplex& f = it->first;
      const VertexId p = it->second.at(0), y = it->second.at(1);
      if (is_finite(f) && (p == infinite_vertex || y == infinite_vertex))
        continue; // case A: the orientation of the top simplex below, checked above
      holds = same_sign([&](auto tag) {
        using NT = decltype(tag);
        if (!is_finite(f)) // case B: the hull is convex at the ridge
          return K::template orientation<NT>(K::join(f.facet(0), p, y), moving());
        return K::template in_sphere<NT>(K::join(f, p), y, moving());
      });
    }
    if (holds)
      return tops;
    q = rational_closer_after(now, q);
    q_hi = CGAL::to_interval(q).second;
  }
  throw InternalError("no rational time just after u ~ " + std::to_string(now.approx()) + " in slab " +
                      std::to_string(slab) + " gives a triangulation valid just after it");
}

// A top simplex that is flat at now and inside out just after can stay in Del(now+) with the same
// vertices: four cells alone in a slab passing through one plane, or every cell of the run passing
// through one plane (mirrored, Del keeps its combinatorics). No flip changes it, and its recorded
// orientation turns stale, so every certificate that reads it would fail at now+ again and again
// (tests/kinetic/test_kinetic_engine.cpp, docs/MATH.md §5.10). The orientation is set anew and
// those certificates are built again: the facets of the top simplex and, for each of its facets on
// the hull, the infinite facets over that facet's own facets (docs/MATH.md §3.2 case B).
template <class K> void Engine<K>::reorient_kept(const std::vector<CellIndex>& kept) {
  for (CellIndex c : kept) {
    const Simplex t = cells.top(c);
    if (!is_finite(t))
      continue;
    const int recorded = cells.orientation(c);
    const int s = orientation_sign_plus(t);
    if (s == recorded)
      continue;
    if (s == 0)
      throw flat_top_simplex_error(t);
    ++stats.reoriented;
    cells.set_orientation(c, s);
    for (int i = 0; i <= dim; ++i) {
      const auto [owner, j] = facet_owner(c, i);
      install_facet(owner, j);
      for_each_hull_ridge_over(c, i, [&](const Simplex& ridge) { install_facet_at(ridge); });
    }
  }
}

// A rational q in (now, next event) (or (now, 1) without one): Del at q is Del(now+) except where a
// certificate fails in (now, q], and those failures are found at now+ and flipped by the caller
// (static repair at an algebraic time, docs/MATH.md §5.4).
template <class K> Rational Engine<K>::rational_before_next_event() const {
  return rational_between(now, certificates.next_time_after(now, SlabTime(Rational(1))));
}

} // namespace medusa::kinetic::detail
