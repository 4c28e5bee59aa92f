// The alpha-complex state of a finite simplex of Del (shortness, membership, radius certificate),
// and the enumeration of the finite faces of a simplex.
#pragma once

#include "cell_triangulation.h"
#include "medusa/kinetic/simplex.h"

#include <array>
#include <cstddef>
#include <cstdint>

namespace medusa::kinetic::detail {

// A run holds one per finite face of Del, about 27 per cell in 3D, in a table at a load of 3/5 (32
// bytes a slot with its key, FiniteKeys): the flags and the three counts share one word.
struct Face {
  Face() : is_short(false), in_k(false), tops(0), short_cofaces(0), k_cofaces(0) {}

  bool is_short : 1;
  bool in_k : 1;
  // Top simplices of Del (infinite ones included) that contain this simplex: at most max_face_tops
  // (Engine::apply_top_change refuses more). An edge lies in one per vertex of its link, a cycle of
  // distinct vertices; only a million cells on one circle would come near.
  std::uint64_t tops : 20;
  // Its finite (k+1)-cofaces in Del that are short, and those in K: the frontier rule asks whether a
  // short simplex has a short coface (docs/MATH.md §4.4), the membership rule whether any coface is in K
  // (4.5). Kept up to date by Engine::count_in_facets wherever a flag changes or a face comes or
  // goes, so neither rule searches the triangulation (edges and larger; the audit recounts). Each
  // counts cofaces recorded in the table, every one of which lies in a top simplex holding this
  // simplex before or after the change being applied: at most 2 max_face_tops, which 21 bits hold.
  std::int64_t short_cofaces : 21;
  std::int64_t k_cofaces : 21;
  int cert = -1;
  // A cell that held this simplex when a change made the cell or a walk last found it: where the
  // walks to its cofaces start (Engine::cell_holding). Only a hint, checked before use: cells die,
  // and their records are reused.
  CellIndex cell = no_cell;
};
static_assert(sizeof(Face) == 16, "a run holds one Face per finite face of Del");
// The largest count Face::tops takes.
constexpr int max_face_tops = (1 << 19) - 1;

// Calls f on every non-empty subset of the vertices of t that avoids the infinite vertex, or, with
// `size` given, on those of that many vertices only.
template <class F> void for_each_face(const Simplex& t, F&& f, std::size_t size = 0) {
  const std::size_t n = t.size();
  for (unsigned mask = 1; mask < (1u << n); ++mask) {
    if (size != 0 && static_cast<std::size_t>(__builtin_popcount(mask)) != size)
      continue;
    std::array<VertexId, 4> v{};
    std::size_t k = 0;
    bool finite = true;
    for (std::size_t i = 0; i < n; ++i)
      if (mask & (1u << i)) {
        v[k++] = t[i];
        finite = finite && t[i] != infinite_vertex;
      }
    if (finite)
      f(Simplex::from_range(v.begin(), v.begin() + k));
  }
}

} // namespace medusa::kinetic::detail
