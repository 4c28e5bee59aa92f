// A kinetic certificate (docs/MATH.md §3.1): the Delaunay certificate of a facet or the radius certificate
// of a finite face, with the version that invalidates its stale queue entries.
#pragma once

#include "medusa/kinetic/simplex.h"

#include <cstdint>

namespace medusa::kinetic::detail {

enum class CertKind : std::uint8_t { delaunay, radius };

// What a Delaunay certificate that vanishes for the whole slab is replaced by (docs/MATH.md §3.9 takes
// such a certificate as valid, which is not always so; Engine::install).
enum class Substitute : std::uint8_t {
  none,
  // A hull ridge (case B of docs/MATH.md §3.2) whose orientation vanishes: its facets stay in one plane
  // (line), and the certificate is then that they lie side by side there, the negated
  // Engine::fold_poly, which fails when a facet degenerates and the two fold onto each other.
  hull_fold,
  // A finite facet whose in-sphere (in-circle) certificate vanishes: its five (four) points stay
  // cospherical, so no in-sphere test orders them, and the certificate is then that its two top
  // simplices keep their recorded orientations (Engine::cell_orientations_poly).
  cell_orientations
};

struct Certificate {
  CertKind kind = CertKind::delaunay;
  bool alive = false;
  Substitute substitute = Substitute::none;
  // A Delaunay certificate's facet as (cell, index) in the triangulation held as cells
  // (cell_triangulation.h): the cell of the facet's first apex (Engine::install_touched_facets), and
  // the facet's index there (the position of the cell's vertex off the facet), so that the facet and
  // its apices are reached from the certificate without a look-up by vertex ids; cell -1 for a
  // radius certificate. Placed beside the flags, it leaves the record at 32 bytes.
  std::int8_t facet_index = 0;
  Simplex key; // the facet (delaunay) or the finite face (radius)
  std::uint32_t version = 0;
  std::int32_t cell = -1;
};
static_assert(sizeof(Certificate) <= 32, "a run holds about one certificate per face of Del");

} // namespace medusa::kinetic::detail
