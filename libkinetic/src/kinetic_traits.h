// What differs between 3D runs and planar runs (docs/MATH.md §5.7), as a compile-time traits type:
// the engine is Engine<KineticTraits3> or Engine<KineticTraits2>, chosen once per run from the
// trajectories' dimension, so no event pays for a runtime test of the dimension. Top simplices have
// dimension + 1 vertices and facets dimension; the certificate formulas (engine.h), the flip rule and
// the Euler check (dimension_policy.h) and the static CGAL structures (static_delaunay.h) are chosen
// on it. Everything else is shared.
#pragma once

#include <cstddef>

namespace medusa::kinetic::detail {

template <int D> struct KineticTraits {
  static_assert(D == 2 || D == 3, "runs are planar or three-dimensional");
  static constexpr int dimension = D;
  static constexpr std::size_t top_size = D + 1;
};

using KineticTraits2 = KineticTraits<2>;
using KineticTraits3 = KineticTraits<3>;

} // namespace medusa::kinetic::detail
