// Wasserstein distances W_p, p >= 1, ground metric L-infinity (docs/MATH.md §7.7).
#pragma once

#include "medusa/persistence/distance.h"
#include "medusa/persistence/points.h"

#include <cstddef>
#include <vector>

namespace medusa::persistence {

struct WassersteinOptions {
  double p = 1.0;                // order, >= 1
  double delta = 0.01;           // relative error allowed for large diagrams
  std::size_t exact_limit = 400; // up to this many finite points in a + b, use the exact Hungarian method
  bool ignore_essential = false;
};

// Exact W_p of the finite parts: Hungarian method on the augmented bipartite graph
// (a + diagonal copies of b) vs (b + diagonal copies of a), O((n+m)^3).
double wasserstein_finite_exact(const std::vector<Point>& a, const std::vector<Point>& b, double p);

// Approximate W_p of the finite parts by an auction algorithm with epsilon-scaling (as Hera does). It
// stops when the cost of its matching is certified, by the dual bound of the prices, to be within a
// factor (1 + delta) of the optimum; falls back to the exact method if that does not happen.
struct ApproximateDistance {
  double value = 0;          // the W_p cost of an actual matching (an upper bound)
  double relative_error = 0; // certified: value <= (1 + relative_error) * exact
  bool exact = false;        // the fallback was used
};
ApproximateDistance wasserstein_finite_auction(const std::vector<Point>& a, const std::vector<Point>& b,
                                               double p, double delta);

// W_p of two diagrams: finite part (exact up to exact_limit points, else auction within delta),
// essential part (sorted births, (sum |b - b'|^p)^(1/p); +inf when the counts differ) and the
// combination (finite^p + essential^p)^(1/p), or the finite part only when ignore_essential.
DistanceResult wasserstein_distance(const PointDiagram& a, const PointDiagram& b,
                                    const WassersteinOptions& options = {});

} // namespace medusa::persistence
