// A kinetic certificate (MATH.md 3.1): the Delaunay certificate of a facet or the radius certificate
// of a finite face, with the version that invalidates its stale queue entries.
#pragma once

#include "medusa/kinetic/simplex.h"

#include <cstdint>

namespace medusa::kinetic::detail {

enum class CertKind : std::uint8_t { delaunay, radius };

struct Certificate {
  CertKind kind = CertKind::delaunay;
  Simplex key; // the facet (delaunay) or the finite face (radius)
  std::uint32_t version = 0;
  bool alive = false;
  // A hull ridge (case B of MATH.md 3.2) whose orientation vanishes for the whole slab: its facets
  // stay in one plane (line), and the certificate is then that they lie side by side there, the
  // negated Engine::fold_poly, which fails when a facet degenerates and the two fold onto each other.
  bool fold = false;
  // A finite facet whose in-sphere (in-circle) certificate vanishes for the whole slab: its five
  // (four) points stay cospherical, so no in-sphere test orders them, and the certificate is then
  // that its two top simplices keep their recorded orientations (Engine::cell_orientations_poly).
  bool orientations = false;
};

} // namespace medusa::kinetic::detail
