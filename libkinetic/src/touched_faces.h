// The faces touched when top simplices of Del are replaced (a flip, a static repair, the initial
// triangulation), each once and in canonical order (docs/MATH.md §5.2), with the change in the number
// of top simplices that hold each face. The engine then looks each face up once.
#pragma once

#include "medusa/kinetic/simplex.h"

#include <array>
#include <cstdint>
#include <vector>

namespace medusa::kinetic::detail {

struct Face;

struct TouchedFace {
  // Built in place (emplace_back): a temporary copied in is read back as wide words just after its
  // fields were written one by one, which stalls the load on the stores, once per face of every flip.
  TouchedFace(const Simplex& f, int d) : face(f), delta(d) {}

  Simplex face;
  int delta = 0; // (added top simplices holding it) - (removed ones holding it)
  // Filled by the engine while it applies the change: the face's entry in its table (none for a
  // vertex), whether the face was in K before, and whether it leaves or enters Del.
  Face* state = nullptr;
  bool old_in_k = false;
  bool leaves = false;
  bool created = false;
};

struct TouchedFaces {
  // Finite faces of every dimension, vertices included, in canonical order (by size, then
  // lexicographically: sorted by Simplex's operator<). Every facet of a touched face is touched too
  // (it lies in the same top simplex), so the engine finds it here by binary search.
  std::vector<TouchedFace> faces;

  // The entry of a touched face; nullptr when s is not touched.
  TouchedFace* find(const Simplex& s);
  // For a flip (local_count > 0): the bit mask of s's vertices over `local`, 0 when one is not there.
  unsigned local_mask(const Simplex& s) const;

  // A flip's faces are subsets of its few vertices (collect_touched_faces): then a face is found by
  // its bit mask over `local` (an index into `faces`, -1 for none) instead of by binary search.
  // local_count is 0 for larger changes.
  static constexpr std::size_t max_local = 6; // a flip spans dim + 2 <= 5 vertices; room for one more
  std::array<VertexId, max_local> local{};
  std::size_t local_count = 0;
  std::array<std::int8_t, std::size_t{1} << max_local> index_of_mask{};
};

// A flip changes top simplices spanned by at most dim + 2 vertices: their faces are enumerated as
// subsets of that vertex set, without sorting; larger changes are sorted and merged.
void collect_touched_faces(const std::vector<Simplex>& removed, const std::vector<Simplex>& added,
                           TouchedFaces& out);

} // namespace medusa::kinetic::detail
