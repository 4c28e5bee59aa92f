// A medusa cell: one maximal lifetime interval of an alpha simplex, or an instant cell
// (docs/MATH.md §6.1-§6.3).
#pragma once

#include "medusa/kinetic/simplex.h"
#include "medusa/medusa/small_list.h"

#include <cstdint>
#include <tuple>

namespace medusa {

using kinetic::VertexId;
using CellId = std::uint64_t;

// Virtual time (docs/MATH.md §6.2): the batch index orders exact event times (equal times are one batch),
// the rank orders the steps inside a batch. `time` is a double approximation, for output only.
// The batch index is held in 32 bits, so that a virtual time takes 16 bytes instead of 24: a medusa
// cell holds two and a diagram pair two. A million-cell run of 20 frames has about 45 million
// batches, a hundredth of the limit; a run past it is refused (max_batch).
struct VirtualTime {
  std::uint32_t batch = 0;
  std::uint32_t rank = 0;
  double time = 0.0;

  friend bool operator<(const VirtualTime& a, const VirtualTime& b) {
    return std::tie(a.batch, a.rank) < std::tie(b.batch, b.rank);
  }
  friend bool operator==(const VirtualTime& a, const VirtualTime& b) {
    return a.batch == b.batch && a.rank == b.rank;
  }
  friend bool operator!=(const VirtualTime& a, const VirtualTime& b) { return !(a == b); }
  friend bool operator<=(const VirtualTime& a, const VirtualTime& b) { return !(b < a); }
};
static_assert(sizeof(VirtualTime) == 16, "VirtualTime grew: a medusa cell holds two");

// The largest batch index a VirtualTime holds.
inline constexpr std::uint64_t max_batch = UINT32_MAX;

enum class CellKind : std::uint8_t {
  regular = 0, // a maximal lifetime interval of a simplex of K(t)
  flip = 1,    // the 4-simplex of a finite flip (3-simplex of a 2D 2-2 flip) with R_S <= rho (instant)
  join = 2,    // sigma + {p} at an insertion or deletion of p (instant)
  repair = 3   // a subset of a degenerate group found by a static repair (instant)
};

// Up to four vertices (a tetrahedron) and four facets are held in the cell itself: a medusa holds one
// record per cell, and a heap block per list would cost more than the list. The facets' ids are held
// in 32 bits, which saves 16 bytes a cell: a million-cell run of 20 frames makes about 21 million
// cells, a two-hundredth of the limit; a medusa past it is refused (max_cell_count).
using CellVertices = SmallList<VertexId, 4>;
using CellFacets = SmallList<std::uint32_t, 4>;

// The most cells a medusa holds: their ids are 0 .. max_cell_count - 1.
inline constexpr std::uint64_t max_cell_count = std::uint64_t{UINT32_MAX} + 1;

struct Cell {
  CellId id = 0;
  CellVertices vertices; // sorted; dimension = vertices.size() - 1 (docs/MATH.md §6.1)
  VirtualTime birth;
  VirtualTime death; // closed lifetime [birth, death]; birth == death for instant cells
  CellFacets facets; // ids of the facet cells, one per vertex removed (empty for vertices)
  CellKind kind = CellKind::regular;

  int dim() const { return static_cast<int>(vertices.size()) - 1; }
};
static_assert(sizeof(Cell) <= 96, "Cell grew: a medusa holds one per cell");

} // namespace medusa
