// The triangulation held as cells beside the engine's own, under the audit: every change of `tri`
// is made again on cell_mirror through its cells (a flip on the cell its certificate names), each
// Delaunay certificate names the cell that holds its facet (Certificate::cell), and each audit
// compares the two. This checks the cell structure on every event stream an audited run or test
// produces (flips, hull flips, local insertions and deletions, static repairs, degenerate groups)
// before the engine is moved onto it.
#pragma once

#include "engine.h"

#include "medusa/core/error.h"

#include <algorithm>
#include <array>
#include <sstream>
#include <string>
#include <vector>

namespace medusa::kinetic::detail {

// The most cells mirror_cert scans (a flip makes two or three, a local insertion or deletion a few
// dozen); it bisects more cells when they are sorted, and walks otherwise.
constexpr std::size_t max_scanned_cells = 64;

template <class K>
void Engine<K>::mirror_top_change(const std::vector<Simplex>& removed, const std::vector<Simplex>& added,
                                  const std::vector<int>& orientations, const std::vector<int>& dropped,
                                  const HeldFlip* held_flip) {
  if (!cell_mirror)
    return;
  if (held_flip != nullptr) {
    mirror_flip(*held_flip, added, orientations, dropped);
    return;
  }
  std::vector<CellIndex> held;
  held.reserve(removed.size());
  for (const Simplex& t : removed) {
    held.push_back(cell_mirror->find(t));
    if (held.back() == no_cell) {
      std::ostringstream os;
      os << "the cell triangulation lacks the removed top simplex " << t;
      throw InternalError(os.str());
    }
  }
  std::vector<typename CellTriangulation<dim>::NewTop> news;
  news.reserve(added.size());
  for (std::size_t i = 0; i < added.size(); ++i)
    news.push_back({added[i], orientations[i]});
  std::vector<int> mirrored;
  cell_mirror->replace(held, news, mirrored, &mirror_created);
  // Static rebuilds and local insertions and deletions add their top simplices sorted, so that their
  // cells are found by bisection.
  mirror_created_sorted = std::is_sorted(added.begin(), added.end());
  if (mirrored != dropped)
    throw InternalError("the cell triangulation dropped other certificates than the triangulation (" +
                        std::to_string(mirrored.size()) + " against " + std::to_string(dropped.size()) + ")");
}

// A flip made on the cell its certificate names, without a look-up by vertex ids: 2-3 (2-2 in the
// plane) through the facet, 3-2 around the change's edge. The new cells come in the cell
// triangulation's order, so each takes the orientation of the added simplex with its vertices.
template <class K>
void Engine<K>::mirror_flip(const HeldFlip& held_flip, const std::vector<Simplex>& added,
                            const std::vector<int>& orientations, const std::vector<int>& dropped) {
  CellTriangulation<dim>& cells = *cell_mirror;
  const CellIndex c = held_flip.cell;
  const int i = held_flip.index;
  const FlipChange& change = *held_flip.change;
  if (!cells.alive(c) || i < 0 || i > dim)
    throw InternalError("a flipped facet's certificate names no living cell");
  const Simplex facet = cells.facet(c, i);
  const VertexId p = cells.vertex(c, i), q = cells.apex_across(c, i);
  const auto orientation_of = [&](const Simplex& t) {
    for (std::size_t k = 0; k < added.size(); ++k)
      if (added[k] == t)
        return orientations[k];
    std::ostringstream os;
    os << "the flip of facet " << facet << " in the cell triangulation makes " << t
       << ", which the triangulation's flip does not";
    throw InternalError(os.str());
  };
  std::vector<int> mirrored;
  if (!change.three_two) {
    std::array<int, dim> o{};
    for (int k = 0; k < dim; ++k)
      o[static_cast<std::size_t>(k)] =
          orientation_of(facet.facet(static_cast<std::size_t>(k)).with(p).with(q));
    std::array<CellIndex, dim> created{};
    cells.flip(c, i, o, mirrored, created);
    mirror_created.assign(created.begin(), created.end());
    mirror_created_sorted = false;
  } else if constexpr (dim == 3) {
    // c holds the edge a b; the ring of cells around it has the other vertices z, p and q, and the
    // new cells are z p q a and z p q b.
    const Simplex ring{change.z, p, q};
    const std::array<int, 2> o{orientation_of(ring.with(change.edge[0])),
                               orientation_of(ring.with(change.edge[1]))};
    std::array<CellIndex, 2> created{};
    cells.flip_edge(c, cells.index_of(c, change.edge[0]), cells.index_of(c, change.edge[1]), o, mirrored,
                    created);
    mirror_created.assign(created.begin(), created.end());
    mirror_created_sorted = false;
  }
  std::vector<int> expected = dropped;
  std::sort(expected.begin(), expected.end());
  std::sort(mirrored.begin(), mirrored.end());
  if (mirrored != expected)
    throw InternalError("a flip on held cells dropped other certificates than the triangulation (" +
                        std::to_string(mirrored.size()) + " against " + std::to_string(expected.size()) +
                        ")");
}

// Either cell of the facet names its certificate: the one the last change made, when it made one
// (a facet on the boundary of a flip has one new cell and one old), else the first apex's.
template <class K>
void Engine<K>::mirror_cert(const Simplex& facet, const std::array<VertexId, 2>& apices, int id) {
  if (!cell_mirror)
    return;
  const std::array<Simplex, 2> tops{facet.with(apices[0]), facet.with(apices[1])};
  CellIndex c = no_cell;
  if (mirror_created.size() <= max_scanned_cells) {
    for (CellIndex made : mirror_created)
      if (cell_mirror->alive(made))
        if (const Simplex t = cell_mirror->top(made); t == tops[0] || t == tops[1])
          c = made;
  } else if (mirror_created_sorted) {
    for (std::size_t k = 0; k < 2 && c == no_cell; ++k) {
      const auto it =
          std::lower_bound(mirror_created.begin(), mirror_created.end(), tops[k],
                           [&](CellIndex made, const Simplex& t) { return cell_mirror->top(made) < t; });
      if (it != mirror_created.end() && cell_mirror->alive(*it) && cell_mirror->top(*it) == tops[k])
        c = *it;
    }
  }
  if (c == no_cell)
    c = cell_mirror->find(tops[0]);
  if (c == no_cell) {
    std::ostringstream os;
    os << "the cell triangulation lacks the top simplex " << tops[0];
    throw InternalError(os.str());
  }
  const int i = cell_mirror->index_of(c, cell_mirror->top(c) == tops[0] ? apices[0] : apices[1]);
  cell_mirror->set_cert(c, i, id);
  certificates.set_cell(id, c, i);
}

template <class K> void Engine<K>::mirror_orientation(const Simplex& t, int orientation) {
  if (cell_mirror)
    cell_mirror->set_orientation(cell_mirror->find(t), orientation);
}

template <class K> std::string Engine<K>::mirror_difference() const {
  if (!cell_mirror)
    return "";
  if (std::string v = cell_mirror->first_violation(); !v.empty())
    return "cell triangulation: " + v;
  if (cell_mirror->size() != tri.tops().size())
    return "the cell triangulation has " + std::to_string(cell_mirror->size()) +
           " top simplices, the triangulation " + std::to_string(tri.tops().size());
  for (int id = 0; id < static_cast<int>(certificates.size()); ++id) {
    const Certificate& cert = certificates[id];
    if (!cert.alive || cert.kind != CertKind::delaunay)
      continue;
    const CellIndex c = cert.cell;
    if (!cell_mirror->alive(c) || cert.facet_index < 0 || cert.facet_index > dim ||
        cell_mirror->cert(c, cert.facet_index) != id || cell_mirror->facet(c, cert.facet_index) != cert.key) {
      std::ostringstream os;
      os << "certificate " << id << " of facet " << cert.key << " names a cell that does not hold it";
      return os.str();
    }
  }
  std::string difference;
  cell_mirror->for_each_cell([&](CellIndex c) {
    if (!difference.empty())
      return;
    const Simplex t = cell_mirror->top(c);
    std::ostringstream os;
    if (!tri.has_top(t) || tri.orientation(t) != cell_mirror->orientation(c)) {
      os << "top simplex " << t << " differs in the cell triangulation";
      difference = os.str();
      return;
    }
    for (int i = 0; i <= dim; ++i) {
      const Simplex f = cell_mirror->facet(c, i);
      if (tri.other_apex(f, cell_mirror->vertex(c, i)) != cell_mirror->apex_across(c, i) ||
          tri.two_sided(f).cert != cell_mirror->cert(c, i)) {
        os << "facet " << f << " differs in the cell triangulation";
        difference = os.str();
        return;
      }
    }
  });
  return difference;
}

} // namespace medusa::kinetic::detail
