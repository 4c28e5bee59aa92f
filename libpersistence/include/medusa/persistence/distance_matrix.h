// Pairwise distances between the diagrams of many runs (docs/MATH.md §7.7), computed on worker threads.
#pragma once

#include "medusa/persistence/points.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace medusa::persistence {

using DiagramMetric = std::function<double(const PointDiagram&, const PointDiagram&)>;

// Symmetric, zero diagonal, row-major.
struct DistanceMatrix {
  std::size_t size = 0;
  std::vector<double> values;

  double at(std::size_t i, std::size_t j) const { return values[i * size + j]; }
};

// metric(diagrams[i], diagrams[j]) for every i < j, the pairs shared among `workers` threads (the
// metric must be safe to call concurrently). An exception of the metric is rethrown here.
DistanceMatrix distance_matrix(const std::vector<PointDiagram>& diagrams, const DiagramMetric& metric,
                               unsigned workers = 2);

} // namespace medusa::persistence
