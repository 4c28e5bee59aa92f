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
#include <sstream>
#include <vector>

namespace medusa::kinetic::detail {

template <class K>
void Engine<K>::change_tops(const std::vector<Simplex>& removed, const std::vector<CellIndex>& removed_cells,
                            const std::vector<Simplex>& added, OldMembership* old_k,
                            const int* added_orientations) {
  apply_top_change(removed, removed_cells, added, added_orientations);
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
void Engine<K>::apply_top_change(const std::vector<Simplex>& removed,
                                 const std::vector<CellIndex>& removed_cells,
                                 const std::vector<Simplex>& added, const int* added_orientations,
                                 const HeldFlip* held_flip) {
  TouchedFaces& touched = touched_scratch;
  collect_touched_faces(removed, added, touched);
  if (touched.faces.size() <= max_prefetched_faces) {
    // A flip: its records are requested together, so their cache misses overlap (FlatSimplexMap::prefetch).
    for (const TouchedFace& t : touched.faces)
      if (t.face.size() > 1)
        faces.prefetch(t.face);
  }
  std::vector<int>& orientations = orientation_scratch;
  orientations.assign(added.size(), 0);
  for (std::size_t i = 0; i < added.size(); ++i) {
    const Simplex& t = added[i];
    if (is_finite(t)) {
      orientations[i] = added_orientations != nullptr ? added_orientations[i] : orientation_sign_plus(t);
      if (orientations[i] == 0)
        throw flat_top_simplex_error(t);
    }
  }
  std::vector<int>& dropped = dropped_certs_scratch;
  dropped.clear();
  if (held_flip != nullptr) {
    flip_cells(*held_flip, added, orientations, dropped);
  } else {
    std::vector<typename CellTriangulation<dim>::NewTop> news;
    news.reserve(added.size());
    for (std::size_t i = 0; i < added.size(); ++i)
      news.push_back({added[i], orientations[i]});
    cells.replace(removed_cells, news, dropped, &created_cells);
  }
  for (int id : dropped)
    kill_cert(id);
  release_if_large(dropped);
  release_if_large(orientations);
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
    const int tops = static_cast<int>(state.tops) + t.delta;
    if (tops > max_face_tops)
      throw too_many_tops_error(f);
    state.tops = static_cast<unsigned>(tops);
    t.leaves = tops == 0;
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
  // Each face of a flip's new cells names one of them (Face::cell), so that the walks to its cofaces
  // start there. A larger change leaves the hints to be found again when they are needed.
  if (touched.local_count > 0)
    for (const CellIndex c : created_cells) {
      const unsigned mask = touched.local_mask(cells.top(c));
      for (unsigned sub = mask; sub != 0; sub = (sub - 1) & mask)
        if (const int k = touched.index_of_mask[sub]; k >= 0)
          if (Face* state = touched.faces[static_cast<std::size_t>(k)].state)
            state->cell = c;
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

// A flip made on the cell its certificate names, without a look-up by vertex ids: 2-3 (2-2 in the
// plane) through the facet, 3-2 around the change's edge.
template <class K>
void Engine<K>::flip_cells(const HeldFlip& held_flip, const std::vector<Simplex>& added,
                           const std::vector<int>& orientations, std::vector<int>& dropped) {
  const CellIndex c = held_flip.cell;
  const int i = held_flip.index;
  const FlipChange& change = *held_flip.change;
  if (!cells.alive(c) || i < 0 || i > dim)
    throw InternalError("a flipped facet's certificate names no living cell");
  const Simplex facet = cells.facet(c, i);
  const VertexId p = cells.vertex(c, i), q = cells.apex_across(c, i);
  const auto orientation_for = [&](const Simplex& t) {
    for (std::size_t k = 0; k < added.size(); ++k)
      if (added[k] == t)
        return orientations[k];
    std::ostringstream os;
    os << "the flip of facet " << facet << " makes " << t << ", which the change does not add";
    throw InternalError(os.str());
  };
  std::array<CellIndex, dim> made{};
  std::size_t count = 0;
  if (!change.three_two) {
    std::array<int, dim> o{};
    for (int k = 0; k < dim; ++k)
      o[static_cast<std::size_t>(k)] =
          orientation_for(facet.facet(static_cast<std::size_t>(k)).with(p).with(q));
    cells.flip(c, i, o, dropped, made);
    count = dim;
  } else if constexpr (dim == 3) {
    // c holds the edge a b; the ring of cells around it has the other vertices z, p and q, and the
    // new cells are z p q a and z p q b.
    const Simplex ring{change.z, p, q};
    const std::array<int, 2> o{orientation_for(ring.with(change.edge[0])),
                               orientation_for(ring.with(change.edge[1]))};
    std::array<CellIndex, 2> two{};
    cells.flip_edge(c, cells.index_of(c, change.edge[0]), cells.index_of(c, change.edge[1]), o, dropped, two);
    made[0] = two[0];
    made[1] = two[1];
    count = 2;
  }
  // In the order of `added`, which decides the first apex of the facets between new cells.
  created_cells.clear();
  for (const Simplex& t : added)
    for (std::size_t k = 0; k < count; ++k)
      if (cells.top(made[k]) == t)
        created_cells.push_back(made[k]);
  if (created_cells.size() != added.size())
    throw InternalError("a flip on held cells made other top simplices than the change adds");
}

// The certificates of the new cells' facets, in canonical order, each named by the cell of its first
// apex: across the boundary of the change the cell outside, which was there first; between two new
// cells the one added first. The first apex is the one a facet's certificate is built from
// (Engine::delaunay_poly), so this fixes each certificate's formula whatever the cells' numbering.
template <class K> void Engine<K>::install_touched_facets() {
  const bool few = created_cells.size() <= max_scanned_created;
  if (!few) {
    if (created_position.size() < cells.capacity())
      created_position.resize(cells.capacity(), -1);
    for (std::size_t k = 0; k < created_cells.size(); ++k)
      created_position[static_cast<std::size_t>(created_cells[k])] = static_cast<int>(k);
  }
  const auto position = [&](CellIndex c) {
    if (!few)
      return created_position[static_cast<std::size_t>(c)];
    for (std::size_t k = 0; k < created_cells.size(); ++k)
      if (created_cells[k] == c)
        return static_cast<int>(k);
    return -1;
  };
  auto& owned = facet_scratch;
  owned.clear();
  for (std::size_t k = 0; k < created_cells.size(); ++k) {
    const CellIndex c = created_cells[k];
    for (int i = 0; i <= dim; ++i) {
      const CellIndex n = cells.neighbor(c, i);
      const int pn = position(n);
      if (pn >= 0 && pn < static_cast<int>(k))
        continue; // listed from n
      owned.push_back(
          {cells.facet(c, i), pn < 0 ? std::make_pair(n, cells.mirror_index(c, i)) : std::make_pair(c, i)});
    }
  }
  if (!few)
    for (CellIndex c : created_cells)
      created_position[static_cast<std::size_t>(c)] = -1;
  std::sort(owned.begin(), owned.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  if (few)
    for (const auto& [facet, owner] : owned) {
      // Each install retires the facet's certificate and reads the apex of the facet's owner, the
      // far apex of a facet round the flip: cache misses of their own, which overlap when requested
      // together (as the touched faces' look-ups do).
      certificates.prefetch(cells.cert(owner.first, owner.second));
      if (const VertexId x = cells.vertex(owner.first, owner.second); x != infinite_vertex)
        __builtin_prefetch(&pt(x));
    }
  for (const auto& [facet, owner] : owned)
    install_facet(owner.first, owner.second);
  release_if_large(owned);
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

template <class K> bool Engine<K>::gabriel_now(const Simplex& s, Face& f) {
  // Not strictly inside the smallest circumball: sign^+ of G1/G2 >= 0 (docs/MATH.md §3.4, §4.1 Lemma 4.2),
  // for every link vertex (each tested once). The certificates are first evaluated at now's
  // enclosure only (certificate::PointAtTime); the few that this leaves undecided get sign^+ from
  // their polynomials (sign_plus_now: interval polynomial, then exact).
  std::vector<VertexId>& link = link_scratch;
  link.clear();
  const CellIndex c = cell_holding(s, f);
  if (c == no_cell) {
    std::ostringstream os;
    os << "face " << s << " is not in the triangulation";
    throw InternalError(os.str());
  }
  if (s.size() == static_cast<std::size_t>(dim)) {
    // A facet: its link is its two apices.
    for (VertexId x : cells.apices(c, cells.facet_index(c, s)).v)
      if (x != infinite_vertex)
        link.push_back(x);
  } else {
    cells.for_each_cell_containing_from(c, s, [&](CellIndex holder) {
      for (int k = 0; k <= dim; ++k)
        if (const VertexId x = cells.vertex(holder, k);
            x != infinite_vertex && !s.contains(x) && std::find(link.begin(), link.end(), x) == link.end())
          link.push_back(x);
    });
  }
  std::size_t n_undecided = 0; // moved to the front of link
  {
    CGAL::Protect_FPU_rounding<true> guard;
    const auto at = points_at_now();
    for (VertexId x : link) {
      const Interval g = s.size() == 2
                             ? certificate::gabriel_edge<Interval>(at(s[0]), at(s[1]), at(x))
                             : certificate::gabriel_triangle<Interval>(at(s[0]), at(s[1]), at(s[2]), at(x));
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
  const bool after =
      s.size() == top_size() ? f.is_short : f.is_short && (f.k_cofaces > 0 || gabriel_now(s, f));
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
