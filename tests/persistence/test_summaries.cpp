// Summaries (docs/MATH.md §7.8) and the point form of diagrams (7.3, 7.7).
#include "cell_list.h"
#include "medusa/core/error.h"
#include "medusa/persistence/diagram.h"
#include "medusa/persistence/points.h"
#include "medusa/persistence/summaries.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace medusa;
using namespace medusa::persistence;
using namespace medusa::persistence::test;

namespace {

Diagram diagram_of(const std::vector<Cell>& cells, Direction direction) {
  return compute_diagram(cells, make_filtration(cells, direction));
}

} // namespace

TEST_CASE("Reverse diagrams become points (-t_birth, -t_death) and normalise to (t_end - t) / span") {
  const auto cells = symmetric_cells();
  const PointDiagram r = to_points(diagram_of(cells, Direction::reverse), 1);
  REQUIRE(r.finite.size() == 1);
  CHECK(r.finite[0].birth == -8);
  CHECK(r.finite[0].death == -6);
  const PointDiagram r0 = to_points(diagram_of(cells, Direction::reverse), 0);
  CHECK(r0.finite.empty());
  CHECK(r0.essential == std::vector<double>{-10});
  const PointDiagram rn = normalise_time(r, Direction::reverse, 0, 10);
  REQUIRE(rn.finite.size() == 1);
  CHECK(rn.finite[0].birth == Approx(0.2));
  CHECK(rn.finite[0].death == Approx(0.4));
  const PointDiagram f =
      normalise_time(to_points(diagram_of(cells, Direction::forward), 1), Direction::forward, 0, 10);
  REQUIRE(f.finite.size() == 1);
  CHECK(f.finite[0].birth == Approx(0.2));
  CHECK(f.finite[0].death == Approx(0.4));
  CHECK_THROWS_AS(normalise_time(r, Direction::forward, 1, 1), InputError);
  // Zero-length pairs are left out unless asked for.
  const Diagram fd = diagram_of(cells, Direction::forward);
  CHECK(to_points(fd, 0).finite.empty());
  CHECK(to_points(fd, 0, true).finite.size() == 2);
}

// Points (0,2), (1,3) and an essential class born at 0.5: beta(s) = #{b <= s < d}.
TEST_CASE("The Betti curve counts the points alive at each sample time, essential classes included") {
  const PointDiagram d{{{0, 2}, {1, 3}}, {0.5}};
  CHECK(betti_curve(d, {-1, 0, 0.5, 1, 2, 2.5, 3, 10}) == std::vector<std::size_t>{0, 1, 2, 3, 2, 2, 1, 1});
}

// Filled triangle (cell_list.h): three components at 0, two from 1, one from 2; a loop on [3, 4).
TEST_CASE("The forward Betti curves of a medusa are the ranks of its sublevel homology") {
  const auto cells = filled_triangle();
  const Diagram d = diagram_of(cells, Direction::forward);
  const std::vector<double> times{0, 0.5, 1, 2, 3, 3.5, 4, 5};
  CHECK(betti_curve(to_points(d, 0), times) == std::vector<std::size_t>{3, 3, 2, 1, 1, 1, 1, 1});
  CHECK(betti_curve(to_points(d, 1), times) == std::vector<std::size_t>{0, 0, 0, 0, 1, 1, 0, 0});
}

TEST_CASE("Total persistence sums (d - b)^p over finite points and counts essential ones apart") {
  const PointDiagram d{{{0, 2}, {1, 3.5}, {4, 4}}, {0, 1}};
  const TotalPersistence p1 = total_persistence(d);
  CHECK(p1.value == 4.5);
  CHECK(p1.essential_count == 2);
  CHECK(total_persistence(d, 2).value == 10.25);
  CHECK(total_persistence(d, 2).p == 2);
}

TEST_CASE("Persistence image pixels are integrals of the weighted Gaussian surface") {
  // One point (0.5, 1.0): pi = 0.5, weight 0.5 with pi_max = 1. Independent check: midpoint-rule
  // integration of the density over each pixel.
  const PointDiagram d{{{0.5, 1.0}, {0.3, 0.3}}, {0.2}};
  PersistenceImageParams params;
  params.birth_min = 0;
  params.birth_max = 1;
  params.persistence_min = 0;
  params.persistence_max = 1;
  params.birth_pixels = 3;
  params.persistence_pixels = 2;
  params.sigma = 0.15;
  params.pi_max = 1;
  const PersistenceImage image = persistence_image(d, params);
  CHECK(image.essential_count == 1);
  CHECK(image.params.sigma == 0.15);
  CHECK(image.params.birth_pixels == 3);
  REQUIRE(image.pixels.size() == 6);
  const double pi = 3.14159265358979323846;
  const int steps = 400;
  for (std::size_t r = 0; r < 2; ++r)
    for (std::size_t c = 0; c < 3; ++c) {
      const double x0 = c / 3.0, y0 = r / 2.0, w = 1 / 3.0, h = 0.5;
      double sum = 0;
      for (int i = 0; i < steps; ++i)
        for (int j = 0; j < steps; ++j) {
          const double x = x0 + (i + 0.5) * w / steps, y = y0 + (j + 0.5) * h / steps;
          sum += std::exp(-((x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5)) / (2 * 0.15 * 0.15));
        }
      const double expected = 0.5 / (2 * pi * 0.15 * 0.15) * sum * (w / steps) * (h / steps);
      CAPTURE(r, c);
      CHECK(image.at(r, c) == Approx(expected).epsilon(1e-5));
    }
  // Over a grid much wider than sigma the pixels sum to the weight.
  params.birth_min = -5;
  params.birth_max = 6;
  params.persistence_min = -5;
  params.persistence_max = 6;
  const PersistenceImage wide = persistence_image(d, params);
  double total = 0;
  for (double v : wide.pixels)
    total += v;
  CHECK(total == Approx(0.5).epsilon(1e-12));
  params.sigma = 0;
  CHECK_THROWS_AS(persistence_image(d, params), InputError);
}
