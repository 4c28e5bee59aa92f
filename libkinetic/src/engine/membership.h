// Triangulation changes and the alpha complex on them: replacing top simplices, cofaces, the frontier
// of radius certificates (docs/MATH.md §4.4), the Gabriel test and membership re-evaluation (4.5).
#pragma once

#include "engine.h"

#include "certificate_polynomials.h"
#include "face.h"
#include "medusa/core/error.h"
#include "touched_faces.h"

#include <algorithm>
#include <array>
#include <optional>
#include <vector>

namespace medusa::kinetic::detail {

template <class K>
void Engine<K>::change_tops(const std::vector<Simplex>& removed, const std::vector<Simplex>& added,
                            OldMembership* old_k, const int* added_orientations) {
  apply_top_change(removed, added, added_orientations);
  if (old_k != nullptr)
    for (const TouchedFace& t : touched_scratch.faces)
      old_k->emplace(t.face, t.old_in_k);
  finish_top_change();
  // After the touched faces are let go: the first triangulation touches every face, and its facets'
  // certificates, with their roots and queue entries, are the last large thing it builds.
  install_touched_facets();
}

// A flip touches at most 2^(dim + 2) - 1 = 31 faces; a larger change overflows the cache anyway.
constexpr std::size_t max_prefetched_faces = 32;

// The caller may pass the orientations sign^+ of the added top simplices (0 for infinite ones) it
// has computed.

template <class K>
void Engine<K>::apply_top_change(const std::vector<Simplex>& removed, const std::vector<Simplex>& added,
                                 const int* added_orientations, const HeldFlip* held_flip) {
  TouchedFaces& touched = touched_scratch;
  collect_touched_faces(removed, added, touched);
  if (touched.faces.size() <= max_prefetched_faces) {
    // A flip: its records are requested together, so their cache misses overlap (FlatSimplexMap::prefetch).
    for (const Simplex& t : removed)
      tri.prefetch_top(t);
    for (const TouchedFace& t : touched.faces)
      if (t.face.size() > 1)
        faces.prefetch(t.face);
  }
  std::vector<int>& dropped = dropped_certs_scratch;
  dropped.clear();
  for (const Simplex& t : removed)
    tri.remove_top(t, dropped);
  for (int id : dropped)
    kill_cert(id);
  std::vector<int> mirrored_orientations;
  for (std::size_t i = 0; i < added.size(); ++i) {
    const Simplex& t = added[i];
    int s = 0;
    if (is_finite(t)) {
      s = added_orientations != nullptr ? added_orientations[i] : orientation_sign_plus(t);
      if (s == 0)
        throw flat_top_simplex_error(t);
    }
    tri.add_top(t, s);
    if (cell_mirror)
      mirrored_orientations.push_back(s);
  }
  mirror_top_change(removed, added, mirrored_orientations, dropped, held_flip);
  release_if_large(dropped);
  // Each face counts the top simplices (infinite ones included) that hold it, so its presence in
  // Del after the change needs no search of the triangulation. With room reserved, no entry moves
  // while the new faces are added: the pointers held in `touched` stay valid until an erase.
  faces.reserve_more(touched.faces.size());
  auto state_of = [&](const Simplex& x) { return state_in_touched(x); };
  for (TouchedFace& t : touched.faces) {
    const Simplex& f = t.face;
    t.state = nullptr;
    t.leaves = t.created = false;
    if (f.size() == 1) {
      t.old_in_k = in_k(f);
      continue;
    }
    auto [added_state, fresh] = faces.add(f);
    if (fresh && t.delta < 0)
      throw InternalError("a removed top simplex held a face that is not in the triangulation");
    Face& state = *added_state;
    t.state = &state;
    t.old_in_k = state.in_k;
    state.tops += t.delta;
    t.leaves = state.tops == 0;
    if (t.leaves) {
      // Leaving Del: its facets are touched, and those staying lose it as a coface.
      FaceStates::count_in_facets(f, -int(state.is_short), -int(state.in_k), state_of);
      kill_cert(state.cert);
      state.cert = -1;
      state.is_short = state.in_k = false;
    } else {
      t.created = fresh;
    }
  }
  std::optional<Collision> collision;
  for (TouchedFace& t : touched.faces) {
    if (!t.created)
      continue;
    const Simplex& f = t.face;
    if (f.size() == 2 && slab + 1 < traj.frames())
      note_collision(f, collision);
    Face& state = *t.state;
    // Created in canonical order, f comes after its facets. A long facet makes f long (R is monotone,
    // docs/MATH.md §4.1) with no radius polynomial: f's longness is implied, as for any face with a long
    // face (4.4, "skipped (implied)"), and f is not in the frontier.
    state.is_short = !FaceStates::has_long_facet(f, state_of) && compute_short(f);
    FaceStates::count_in_facets(f, int(state.is_short), 0, state_of); // a new face is not in K yet
  }
  // The earliest of the collisions the change foretells, not the first edge's (docs/MATH.md §2.5).
  if (collision)
    throw_collision(*collision);
  // Frontier membership of every surviving touched simplex: their cofaces changed (docs/MATH.md §4.4,
  // "after any change of Del"). Cofaces of new simplices are new, hence touched as well.
  for (TouchedFace& t : touched.faces)
    if (t.state != nullptr && !t.leaves) {
      Face& state = *t.state;
      set_frontier(t.face, state, FaceStates::in_frontier(t.face, state, [&](const Simplex& x) {
                     return state_of(x)->is_short;
                   }));
    }
}

template <class K> void Engine<K>::install_touched_facets() {
  for (const Simplex& f : touched_scratch.facets)
    install_facet(f);
  release_if_large(touched_scratch.facets);
}

template <class K> void Engine<K>::finish_top_change() {
  // Erasing moves entries: no state pointer is read from here on.
  for (TouchedFace& t : touched_scratch.faces) {
    if (t.leaves)
      faces.erase(t.face);
    t.state = nullptr;
  }
  release_if_large(touched_scratch.faces);
}

// Creates or drops the radius certificate of s so that exactly the frontier carries one.
template <class K> void Engine<K>::set_frontier(const Simplex& s, Face& f, bool want) {
  if (want && f.cert < 0)
    install_radius(s, f);
  else if (!want && f.cert >= 0) {
    kill_cert(f.cert);
    f.cert = -1;
  }
}

template <class K> bool Engine<K>::gabriel_now(const Simplex& s) {
  // Not strictly inside the smallest circumball: sign^+ of G1/G2 >= 0 (docs/MATH.md §3.4, §4.1 Lemma 4.2),
  // for every link vertex (each tested once). The certificates are first evaluated at now's
  // enclosure only (certificate::PointAtTime); the few that this leaves undecided get sign^+ from
  // their polynomials (sign_plus_now: interval polynomial, then exact).
  std::vector<VertexId>& link = link_scratch;
  link.clear();
  if (s.size() == static_cast<std::size_t>(dim)) {
    // A facet: its link is its two apices, kept with it.
    const detail::Triangulation::Apices& ap = tri.two_sided(s);
    for (VertexId x : ap.v)
      if (x != infinite_vertex)
        link.push_back(x);
  } else {
    tri.for_each_top_containing(s, [&](const Simplex& t) {
      for (VertexId x : t)
        if (x != infinite_vertex && !s.contains(x) && std::find(link.begin(), link.end(), x) == link.end())
          link.push_back(x);
    });
  }
  std::size_t n_undecided = 0; // moved to the front of link
  {
    CGAL::Protect_FPU_rounding<true> guard;
    const auto at = points_at_now();
    for (VertexId x : link) {
      const Interval g =
          s.size() == 2 ? certificate::gabriel_edge<Interval>(at(s[0]), at(s[1]), at(x))[0]
                        : certificate::gabriel_triangle<Interval>(at(s[0]), at(s[1]), at(s[2]), at(x))[0];
      if (g.sup() < 0 || g.inf() > 0)
        ++stats.sign_evaluations;
      if (g.sup() < 0)
        return false;
      if (!(g.inf() > 0))
        link[n_undecided++] = x;
    }
  }
  for (std::size_t i = 0; i < n_undecided; ++i) {
    const VertexId x = link[i];
    int g = sign_plus_now([&](auto tag) {
      using NT = decltype(tag);
      return s.size() == 2 ? certificate::gabriel_edge<NT>(pt(s[0]), pt(s[1]), pt(x))
                           : certificate::gabriel_triangle<NT>(pt(s[0]), pt(s[1]), pt(s[2]), pt(x));
    });
    if (g < 0)
      return false;
  }
  return true;
}

// Every simplex of K is short (its smallest circumsphere is no larger than an empty sphere of
// radius <= rho, docs/MATH.md §4.1), so a long one is out without looking at its cofaces; top simplices
// are always Gabriel (4.1). Cofaces are settled before faces (decreasing dimension), so the counts
// read here are current.
template <class K>
template <class StateOf>
bool Engine<K>::settle(const Simplex& s, Face& f, StateOf&& state_of) {
  const bool after = s.size() == top_size() ? f.is_short : f.is_short && (f.k_cofaces > 0 || gabriel_now(s));
  if (after != f.in_k) {
    FaceStates::count_in_facets(s, 0, after ? +1 : -1, state_of);
    f.in_k = after;
  }
  return after;
}

namespace {

void record(const Simplex& s, bool before, bool after, Step& step) {
  if (before && !after)
    step.left.push_back(s);
  else if (!before && after)
    step.entered.push_back(s);
}

} // namespace

// Re-evaluates membership (docs/MATH.md §4.5 "re-eval") on the touched simplices, in decreasing
// dimension, and fills the step's entered/left lists (in no particular order: emit_batch sorts them).
template <class K> void Engine<K>::settle_membership(const OldMembership& old_k, Step& step) {
  // Only the order of dimensions matters (a simplex reads its cofaces' counts, never those of its
  // peers): bucket by size instead of sorting.
  auto& by_size = settle_scratch;
  for (auto& bucket : by_size)
    bucket.clear();
  for (const auto& [s, before] : old_k)
    by_size[s.size() - 1].emplace_back(s, before);
  auto state_of = [&](const Simplex& x) { return state_in_table(x); };
  for (std::size_t k = by_size.size(); k-- > 0;)
    for (const auto& [s, before] : by_size[k]) {
      bool after = false;
      if (s.size() == 1)
        after = in_k(s);
      else if (Face* f = state_in_table(s))
        after = settle(s, *f, state_of);
      record(s, before, after, step);
    }
  for (auto& bucket : by_size)
    release_if_large(bucket);
}

// settle_membership on the faces of the change being applied (apply_top_change), which are in
// canonical order: backwards is decreasing dimension.
template <class K> void Engine<K>::settle_touched(Step& step) {
  auto state_of = [&](const Simplex& x) { return state_in_touched(x); };
  for (auto it = touched_scratch.faces.rbegin(); it != touched_scratch.faces.rend(); ++it) {
    bool after = false;
    if (it->face.size() == 1)
      after = in_k(it->face);
    else if (!it->leaves)
      after = settle(it->face, *it->state, state_of);
    record(it->face, it->old_in_k, after, step);
  }
}

template <class K> std::vector<Simplex> Engine<K>::current_complex() const {
  std::vector<Simplex> k;
  for (std::size_t i = 0; i < alive.size(); ++i)
    if (alive[i])
      k.push_back(Simplex{static_cast<VertexId>(i)});
  faces.for_each([&](const Simplex& s, const Face& f) {
    if (f.in_k)
      k.push_back(s);
  });
  std::sort(k.begin(), k.end());
  return k;
}

} // namespace medusa::kinetic::detail
