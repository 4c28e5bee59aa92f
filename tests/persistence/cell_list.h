// Builds medusa cell lists for the persistence tests from (vertices, birth, death) triples: ids are
// deliberately not consecutive, facets are looked up by vertex tuple and lifetime.
#pragma once

#include "medusa/medusa/cell.h"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <vector>

namespace medusa::persistence::test {

using medusa::Cell;
using medusa::VirtualTime;

inline VirtualTime vt(std::uint32_t batch, std::uint32_t rank, double time) { return {batch, rank, time}; }

struct CellSpec {
  std::vector<kinetic::VertexId> vertices;
  VirtualTime birth;
  VirtualTime death;
  medusa::CellKind kind = medusa::CellKind::regular;
};

// Ids are 1000 + 7 * (position in the list), descending order would work as well: the library maps
// them. The facet of a cell is the cell of the facet simplex whose lifetime contains the cell's
// (docs/MATH.md §6.4).
inline std::vector<Cell> make_cells(const std::vector<CellSpec>& specs) {
  std::vector<Cell> cells;
  for (std::size_t i = 0; i < specs.size(); ++i) {
    Cell c;
    c.id = 1000 + 7 * i;
    c.vertices = specs[i].vertices;
    std::sort(c.vertices.begin(), c.vertices.end());
    c.birth = specs[i].birth;
    c.death = specs[i].death;
    c.kind = specs[i].kind;
    cells.push_back(std::move(c));
  }
  for (Cell& c : cells) {
    if (c.vertices.size() < 2)
      continue;
    for (std::size_t k = 0; k < c.vertices.size(); ++k) {
      std::vector<kinetic::VertexId> facet = c.vertices.to_vector();
      facet.erase(facet.begin() + static_cast<std::ptrdiff_t>(k));
      bool found = false;
      for (const Cell& f : cells)
        if (f.vertices == facet && f.birth <= c.birth && c.death <= f.death) {
          c.facets.push_back(f.id);
          found = true;
          break;
        }
      if (!found)
        throw std::logic_error("test cell list: a facet is missing");
    }
  }
  return cells;
}

// Cells with ids equal to their positions, as parts of the library require (make_cells numbers them
// apart).
inline std::vector<Cell> positional(std::vector<Cell> cells) {
  std::map<medusa::CellId, medusa::CellId> to;
  for (std::size_t i = 0; i < cells.size(); ++i)
    to[cells[i].id] = i;
  for (Cell& c : cells) {
    c.id = to.at(c.id);
    for (std::uint32_t& f : c.facets)
      f = static_cast<std::uint32_t>(to.at(f));
  }
  return cells;
}

// Every subset of `vertices` with at least one element, as cell specs with one lifetime.
inline void add_closure(std::vector<CellSpec>& specs, std::vector<kinetic::VertexId> vertices,
                        VirtualTime birth, VirtualTime death) {
  const std::size_t n = vertices.size();
  for (std::size_t size = 1; size <= n; ++size)
    for (unsigned mask = 1; mask < (1u << n); ++mask) {
      if (static_cast<std::size_t>(__builtin_popcount(mask)) != size)
        continue;
      std::vector<kinetic::VertexId> s;
      for (std::size_t k = 0; k < n; ++k)
        if (mask & (1u << k))
          s.push_back(vertices[k]);
      bool present = false;
      for (const auto& existing : specs)
        present = present || existing.vertices == s;
      if (!present)
        specs.push_back({s, birth, death});
    }
}

// A time-symmetric medusa on [0, 10]: a path 0-1-2 throughout, the edge 0-2 over [2, 8] and the
// triangle over [4, 6]; forward H1 (2, 4), reverse H1 (8, 6).
inline std::vector<Cell> symmetric_cells() {
  std::vector<CellSpec> s;
  add_closure(s, {0, 1}, vt(0, 0, 0), vt(5, 0, 10));
  add_closure(s, {1, 2}, vt(0, 0, 0), vt(5, 0, 10));
  s.push_back({{0, 2}, vt(1, 0, 2), vt(4, 0, 8)});
  s.push_back({{0, 1, 2}, vt(2, 0, 4), vt(3, 0, 6)});
  return make_cells(s);
}

// Vertices a=0, b=1, c=2 at t=0; edges ab at 1, bc at 2, ca at 3; triangle abc at 4; all die at 5.
// Batches 0..5 are the times 0..5.
inline std::vector<Cell> filled_triangle() {
  std::vector<CellSpec> s;
  for (int v = 0; v < 3; ++v)
    s.push_back({{v}, vt(0, 0, 0), vt(5, 0, 5)});
  s.push_back({{0, 1}, vt(1, 0, 1), vt(5, 0, 5)});
  s.push_back({{1, 2}, vt(2, 0, 2), vt(5, 0, 5)});
  s.push_back({{0, 2}, vt(3, 0, 3), vt(5, 0, 5)});
  s.push_back({{0, 1, 2}, vt(4, 0, 4), vt(5, 0, 5)});
  return make_cells(s);
}

} // namespace medusa::persistence::test
