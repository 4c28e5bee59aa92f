// Insertions and deletions at frames as local changes of Del(now+) (docs/MATH.md §4.5, §5.6): a new
// cell replaces the top simplices whose circumsphere it lies in (Bowyer-Watson), a leaving cell's
// star is filled with the Delaunay triangulation of its link. A static rebuild costs a CGAL
// triangulation of every cell per change, and a growing CompuCell3D tissue divides a few percent of
// its cells per frame. Both decide with the predicates just after now (sign^+, docs/MATH.md §3.7,
// §5.5). Where one of them vanishes for the whole slab, or a check of the result fails, they return
// false and change nothing, and the caller rebuilds statically. Ties the predicates do not meet are
// kept as they are (docs/MATH.md §5.3): the triangulation is Delaunay either way.
#pragma once

#include "engine.h"

#include <algorithm>
#include <cstdint>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace medusa::kinetic::detail {

namespace {

// Squared distance between two cells at a frame, in doubles: it only picks where to start looking,
// so rounding can cost a scan but never decides anything.
double squared_distance(const MovingPoint& p, const MovingPoint& q) {
  double d = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const double x = static_cast<double>(p.a[i]) - static_cast<double>(q.a[i]);
    d += x * x;
  }
  return d;
}

} // namespace

// Whether v lies strictly inside the circumsphere (circumcircle) of the top simplex t of cell c just
// after now, or, for an infinite t, strictly beyond its hull facet: +1 yes, -1 no, 0 when the
// predicate vanishes for the whole slab (undecided; the caller rebuilds statically).
template <class K> int Engine<K>::in_conflict_just_after(CellIndex c, VertexId v) {
  const Simplex t = cells.top(c);
  if (is_finite(t)) {
    const int o = cells.orientation(c);
    // The in-sphere (in-circle) test has the sign outside_sign * o while v is outside (delaunay_poly).
    const int s = sign_plus_now(
        [&](auto tag) { return K::template in_sphere<decltype(tag)>(K::join(t), v, moving()); });
    return s == 0 ? 0 : (s * o * K::outside_sign < 0 ? 1 : -1);
  }
  // t = [-1 hull facet]: v is beyond the facet iff it lies on the other side of it than the facet's
  // finite top simplex.
  const Simplex f = t.facet(0);
  const Apices ap = cells.apices(c, 0); // c's vertex 0 is the infinite one
  const VertexId z = ap.v[1];
  std::array<VertexId, 4> seq{};
  std::copy(f.begin(), f.end(), seq.begin());
  seq[f.size()] = z;
  const int inner = orientation_of(seq.data(), f.size() + 1, ap, z);
  const int s = facet_side_just_after(f, v);
  return s == 0 ? 0 : (s == inner ? -1 : 1);
}

// The sign just after now of the orientation of the finite facet f followed by x: which side of f's
// plane (line) x is on; 0 when x stays in it for the whole slab.
template <class K> int Engine<K>::facet_side_just_after(const Simplex& f, VertexId x) {
  return sign_plus_now(
      [&](auto tag) { return K::template orientation<decltype(tag)>(K::join(f, x), moving()); });
}

// A top simplex whose circumsphere holds v just after now: one of those at v's nearest cell, which is
// v's neighbour in Del(now+) (a Gabriel edge, even among equal distances); otherwise, after rounding
// in doubles picked another, one found by a scan. Returns false when none is found with decided
// predicates. Insertions happen at frames, where now is u = 0 and each cell sits at its `a`.
template <class K> bool Engine<K>::find_conflict(VertexId v, CellIndex& seed) {
  VertexId nearest = infinite_vertex;
  double best = 0;
  for (std::size_t i = 0; i < alive.size(); ++i)
    if (alive[i] && static_cast<VertexId>(i) != v) {
      const double d = squared_distance(pt(static_cast<VertexId>(i)), pt(v));
      if (nearest == infinite_vertex || d < best) {
        best = d;
        nearest = static_cast<VertexId>(i);
      }
    }
  // A tie (0) is passed over here: if it touches the conflict region, the flood of insert_locally
  // meets it again and gives up; elsewhere it does not matter.
  std::vector<CellIndex> candidates;
  if (nearest != infinite_vertex)
    cells.for_each_cell_containing(Simplex{nearest}, [&](CellIndex c) { candidates.push_back(c); });
  for (CellIndex c : candidates)
    if (in_conflict_just_after(c, v) > 0) {
      seed = c;
      return true;
    }
  candidates.clear();
  cells.for_each_cell([&](CellIndex c) { candidates.push_back(c); });
  for (CellIndex c : candidates)
    if (in_conflict_just_after(c, v) > 0) {
      seed = c;
      return true;
    }
  return false;
}

// Bowyer-Watson just after now: the top simplices in conflict with v form a region star-shaped from
// v, connected through their facets; it is replaced by the cone from v over its boundary facets.
template <class K>
bool Engine<K>::insert_locally(VertexId v, std::vector<CellIndex>& removed, std::vector<Simplex>& added,
                               std::vector<int>& orientations) {
  CellIndex seed = no_cell;
  if (!find_conflict(v, seed))
    return false;
  std::unordered_map<CellIndex, bool> in_conflict{{seed, true}};
  std::vector<CellIndex> unvisited{seed};
  std::vector<Simplex> boundary;
  removed.clear();
  while (!unvisited.empty()) {
    const CellIndex t = unvisited.back();
    unvisited.pop_back();
    removed.push_back(t);
    for (int i = 0; i <= dim; ++i) {
      const Simplex f = cells.facet(t, i);
      const CellIndex other = cells.neighbor(t, i);
      auto [it, fresh] = in_conflict.try_emplace(other, false);
      if (fresh) {
        const int c = in_conflict_just_after(other, v);
        if (c == 0)
          return false;
        it->second = c > 0;
        if (it->second)
          unvisited.push_back(other);
      }
      if (!it->second)
        boundary.push_back(f);
    }
  }
  added.clear();
  orientations.clear();
  for (const Simplex& f : boundary) {
    const Simplex t = f.with(v);
    int s = 0;
    if (is_finite(t) && (s = orientation_sign_plus(t)) == 0)
      return false; // flat for the whole slab: a tie the static rebuild settles
    added.push_back(t);
    orientations.push_back(s);
  }
  return true;
}

// The star of v is filled with the top simplices of Del(link of v)(now+) that lie inside it: a flood
// from the one beside a link facet on v's side, never crossing a link facet. Every link facet is a
// face of Del(V - v) (its outer top simplex keeps its empty circumsphere), hence of Del(link), unless
// a tie just after now let CGAL's perturbation choose otherwise; then the flood would not close, and
// the result is checked: the filled simplices must meet exactly the link facets, each once.
template <class K>
bool Engine<K>::delete_locally(VertexId v, std::vector<CellIndex>& removed, std::vector<Simplex>& added,
                               std::vector<int>& orientations) {
  if (!now.is_rational())
    return false;
  removed.clear();
  cells.for_each_cell_containing(Simplex{v}, [&](CellIndex c) { removed.push_back(c); });
  // Each link facet: the cell of v's star on it, and the times the flood below met it.
  struct Wall {
    CellIndex cell = no_cell;
    int met = 0;
  };
  std::unordered_map<Simplex, Wall, SimplexHash> walls;
  std::vector<VertexId> link;
  for (CellIndex c : removed) {
    const Simplex f = cells.facet(c, cells.index_of(c, v));
    walls.emplace(f, Wall{c, 0});
    for (VertexId w : f)
      if (w != infinite_vertex)
        link.push_back(w);
  }
  std::sort(link.begin(), link.end());
  link.erase(std::unique(link.begin(), link.end()), link.end());
  if (link.size() + 1 == top_size()) {
    // A hull cell with dim neighbours: its star is every top simplex on it, the infinite vertex and
    // the neighbours, and the only way to close the hole with those is the one infinite top simplex
    // over the neighbours, now a hull facet. Unless too few cells remain for any triangulation.
    const auto remaining = static_cast<std::size_t>(std::count(alive.begin(), alive.end(), 1));
    if (walls.size() != top_size() || remaining < top_size())
      return false;
    std::vector<VertexId> w = link;
    w.push_back(infinite_vertex);
    added.assign(1, Simplex::from_range(w.begin(), w.end()));
    orientations.assign(1, 0);
    return true;
  }
  if (link.size() < top_size())
    return false; // too few to span a top simplex: the static rebuild decides (and reports flat input)
  int dimension = 0;
  std::vector<Simplex> local =
      detail::delaunay_just_after(dim, static_input(link), now.rational(), dimension);
  if (dimension < dim)
    return false;
  // CGAL's order follows its spatial sort (a process-wide random generator): sorted, the seed below,
  // and the signs evaluated to find it, do not depend on it.
  std::sort(local.begin(), local.end());
  std::unordered_map<Simplex, std::vector<std::size_t>, SimplexHash> sides; // facet -> its top simplices
  for (std::size_t i = 0; i < local.size(); ++i)
    for (std::size_t j = 0; j < local[i].size(); ++j)
      sides[local[i].facet(j)].push_back(i);
  // The seed: at a finite link facet f, the top simplex of Del(link) on v's side of f (the other one
  // when the only finite apex is on the far side). f is the smallest finite link facet, so that the
  // choice, and whether an undecided side sends the deletion to a static rebuild, does not depend on
  // the order in which v's star was listed.
  const Simplex* smallest = nullptr;
  for (const auto& wall : walls)
    if (is_finite(wall.first) && (smallest == nullptr || wall.first < *smallest))
      smallest = &wall.first;
  if (smallest == nullptr)
    return false;
  const Simplex& f = *smallest;
  const auto it = sides.find(f);
  if (it == sides.end() || it->second.size() != 2)
    return false;
  const auto apex = [&](std::size_t i) {
    return *std::find_if(local[i].begin(), local[i].end(), [&](VertexId x) { return !f.contains(x); });
  };
  std::size_t near = it->second[0], far = it->second[1];
  if (apex(near) == infinite_vertex)
    std::swap(near, far);
  // v's side is the recorded orientation of its top simplex on f: the triangulation's own sign.
  std::array<VertexId, 4> seq{};
  std::copy(f.begin(), f.end(), seq.begin());
  seq[f.size()] = v;
  const CellIndex own_cell = walls.at(f).cell;
  const int own = orientation_of(seq.data(), f.size() + 1,
                                 cells.apices(own_cell, cells.index_of(own_cell, v)), v),
            other = facet_side_just_after(f, apex(near));
  if (own == 0 || other == 0)
    return false;
  const std::size_t seed = own == other ? near : far;
  std::vector<char> filled(local.size(), 0);
  std::vector<std::size_t> unvisited{seed};
  filled[seed] = 1;
  while (!unvisited.empty()) {
    const std::size_t i = unvisited.back();
    unvisited.pop_back();
    for (std::size_t j = 0; j < local[i].size(); ++j) {
      const Simplex f = local[i].facet(j);
      if (const auto w = walls.find(f); w != walls.end()) {
        ++w->second.met;
        continue;
      }
      for (std::size_t k : sides.at(f))
        if (!filled[k]) {
          filled[k] = 1;
          unvisited.push_back(k);
        }
    }
  }
  for (const auto& wall : walls)
    if (wall.second.met != 1)
      return false; // a link facet missing from Del(link), or met from both sides: the flood leaked
  added.clear();
  orientations.clear();
  for (std::size_t i = 0; i < local.size(); ++i) {
    if (!filled[i])
      continue;
    int s = 0;
    if (is_finite(local[i]) && (s = orientation_sign_plus(local[i])) == 0)
      return false;
    added.push_back(local[i]);
    orientations.push_back(s);
  }
  return true;
}

// Inserts or deletes v as a local change if it can (see above), recording it in step as
// record_top_changes records a static rebuild.
template <class K>
bool Engine<K>::record_local_change(Step& step, OldMembership& old_k, VertexId v, bool insert) {
  std::vector<CellIndex> removed_cells;
  std::vector<Simplex> added;
  std::vector<int> orientations;
  if (insert ? insert_locally(v, removed_cells, added, orientations)
             : delete_locally(v, removed_cells, added, orientations)) {
    // Canonical order, as after a static rebuild: the certificates are built in it.
    std::vector<std::pair<Simplex, int>> sorted;
    for (std::size_t i = 0; i < added.size(); ++i)
      sorted.emplace_back(added[i], orientations[i]);
    std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t i = 0; i < sorted.size(); ++i)
      std::tie(added[i], orientations[i]) = sorted[i];
    const std::vector<Simplex> removed = sort_by_top(removed_cells);
    change_tops(removed, removed_cells, added, &old_k, orientations.data());
    reinstall_hull_ridges_over(added, removed);
    ++(insert ? stats.local_insertions : stats.local_deletions);
    record_delaunay_change(step, removed, added);
    return true;
  }
  return false;
}

} // namespace medusa::kinetic::detail
