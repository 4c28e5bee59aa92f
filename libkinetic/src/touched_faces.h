// The faces and facets touched when top simplices of Del are replaced (a flip, a static repair, the
// initial triangulation), each once and in canonical order (MATH.md 5.2), with the change in the
// number of top simplices that hold each face. The engine then looks each face up once.
#pragma once

#include "medusa/kinetic/simplex.h"

#include <vector>

namespace medusa::kinetic::detail {

struct TouchedFace {
  Simplex face;
  int delta = 0; // (added top simplices holding it) - (removed ones holding it)
};

struct TouchedFaces {
  std::vector<TouchedFace> faces; // finite faces of every dimension, vertices included
  std::vector<Simplex> facets;    // facets of the changed top simplices, infinite ones included
};

// A flip changes top simplices spanned by at most dim + 2 vertices: their faces are enumerated as
// subsets of that vertex set, without sorting; larger changes are sorted and merged.
void collect_touched_faces(const std::vector<Simplex>& removed, const std::vector<Simplex>& added,
                           TouchedFaces& out);

} // namespace medusa::kinetic::detail
