// Summaries of a diagram (docs/MATH.md §7.8): Betti curves, total persistence, persistence images. Inputs
// are point diagrams (b <= d; reverse diagrams already mapped to -t by to_points, docs/MATH.md §7.3).
#pragma once

#include "medusa/persistence/points.h"

#include <cstddef>
#include <vector>

namespace medusa::persistence {

// beta(s) = #{(b, d) : b <= s < d} at each sample time s, essential classes included.
std::vector<std::size_t> betti_curve(const PointDiagram& diagram, const std::vector<double>& times);

struct TotalPersistence {
  double p = 1;
  double value = 0;                // sum over finite points of (d - b)^p
  std::size_t essential_count = 0; // reported alongside, never summed
};
TotalPersistence total_persistence(const PointDiagram& diagram, double p = 1.0);

// Grid over birth x persistence; all parameters are recorded in the image.
struct PersistenceImageParams {
  double birth_min = 0, birth_max = 1;
  double persistence_min = 0, persistence_max = 1;
  std::size_t birth_pixels = 20, persistence_pixels = 20; // resolution
  double sigma = 0.1;                                     // Gaussian standard deviation
  double pi_max = 1;                                      // weight w(pi) = min(pi / pi_max, 1)
  bool normalised_time = false; // whether the points went through normalise_time (docs/MATH.md §7.7)
};

struct PersistenceImage {
  PersistenceImageParams params;
  // pixels[r * birth_pixels + c]: row r of persistence, column c of birth; each the integral of the
  // weighted Gaussian surface over the pixel (differences of Gaussian CDFs).
  std::vector<double> pixels;
  std::size_t essential_count = 0; // essential points are excluded and counted here

  double at(std::size_t persistence_row, std::size_t birth_column) const {
    return pixels[persistence_row * params.birth_pixels + birth_column];
  }
};

// Throws InputError on an empty grid, sigma <= 0 or pi_max <= 0.
PersistenceImage persistence_image(const PointDiagram& diagram, const PersistenceImageParams& params);

} // namespace medusa::persistence
