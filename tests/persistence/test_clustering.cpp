// Distance matrices over many diagrams and hierarchical clustering, against hand derivations and
// scipy's linkage.
#include "medusa/core/error.h"
#include "medusa/persistence/bottleneck.h"
#include "medusa/persistence/clustering.h"
#include "oracle.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <random>
#include <set>
#include <stdexcept>

using namespace medusa;
using namespace medusa::persistence;
using namespace medusa::persistence::test;

namespace {

DistanceMatrix line_matrix(const std::vector<double>& x) {
  DistanceMatrix d{x.size(), std::vector<double>(x.size() * x.size())};
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = 0; j < x.size(); ++j)
      d.values[i * x.size() + j] = std::abs(x[i] - x[j]);
  return d;
}

// The leaves below each cluster id (leaves, then one per merge).
std::vector<std::set<std::size_t>> members(const Dendrogram& d) {
  std::vector<std::set<std::size_t>> m(d.leaves);
  for (std::size_t i = 0; i < d.leaves; ++i)
    m[i] = {i};
  for (const Merge& merge : d.merges) {
    std::set<std::size_t> s = m.at(merge.first);
    s.insert(m.at(merge.second).begin(), m.at(merge.second).end());
    m.push_back(s);
  }
  return m;
}

void check_merge(const Merge& m, std::size_t first, std::size_t second, double height, std::size_t size) {
  CHECK(m.first == first);
  CHECK(m.second == second);
  CHECK(m.height == Approx(height).epsilon(1e-15));
  CHECK(m.size == size);
}

} // namespace

// Points 0, 1, 3, 7 on a line. Single: {0,1} at 1, +2 at 2, +3 at 4. Average: {0,1} at 1; then
// d({0,1},2) = (3+2)/2 = 2.5 < d(2,3) = 4, so +2 at 2.5; finally (7+6+4)/3 = 17/3.
TEST_CASE("Single and average linkage of four points on a line give the hand-derived dendrograms") {
  const auto d = line_matrix({0, 1, 3, 7});
  const Dendrogram single = single_linkage(d);
  REQUIRE(single.merges.size() == 3);
  check_merge(single.merges[0], 0, 1, 1, 2);
  check_merge(single.merges[1], 2, 4, 2, 3);
  check_merge(single.merges[2], 3, 5, 4, 4);
  const Dendrogram average = average_linkage(d);
  REQUIRE(average.merges.size() == 3);
  check_merge(average.merges[0], 0, 1, 1, 2);
  check_merge(average.merges[1], 2, 4, 2.5, 3);
  check_merge(average.merges[2], 3, 5, 17.0 / 3, 4);
}

TEST_CASE("Single and average linkage agree with scipy on random distance matrices") {
  for (unsigned seed : {31u, 32u}) {
    CAPTURE(seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    const std::size_t n = 12;
    std::vector<std::pair<double, double>> pts(n);
    for (auto& p : pts)
      p = {unit(rng), unit(rng)};
    DistanceMatrix d{n, std::vector<double>(n * n)};
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j)
        d.values[i * n + j] = std::hypot(pts[i].first - pts[j].first, pts[i].second - pts[j].second);
    TempDir dir("linkage");
    {
      std::FILE* out = std::fopen(dir.file("matrix.txt").c_str(), "w");
      REQUIRE(out);
      std::fprintf(out, "%zu\n", n);
      for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = 0; j < n; ++j)
          std::fprintf(out, "%.17g ", d.at(i, j));
        std::fprintf(out, "\n");
      }
      std::fclose(out);
    }
    for (const std::string method : {"single", "average"}) {
      CAPTURE(method);
      run(python() + " " + data_path("persistence/linkage_oracle.py") + " " + dir.file("matrix.txt") + " " +
          method + " " + dir.file(method + ".txt"));
      Dendrogram scipy{n, {}};
      std::istringstream in(read_text(dir.file(method + ".txt")));
      for (std::string a, b, h, s; in >> a >> b >> h >> s;)
        scipy.merges.push_back({std::stoul(a), std::stoul(b), std::stod(h), std::stoul(s)});
      const Dendrogram ours = method == "single" ? single_linkage(d) : average_linkage(d);
      REQUIRE(ours.merges.size() == n - 1);
      REQUIRE(scipy.merges.size() == n - 1);
      // Cluster numbering follows the merge order in both, so compare the leaf sets and heights.
      const auto ours_members = members(ours), scipy_members = members(scipy);
      for (std::size_t k = 0; k + 1 < n; ++k) {
        CAPTURE(k);
        CHECK(ours.merges[k].height == Approx(scipy.merges[k].height).epsilon(1e-12));
        CHECK(ours_members[n + k] == scipy_members[n + k]);
        CHECK(ours.merges[k].size == scipy.merges[k].size);
      }
    }
  }
}

TEST_CASE("The distance matrix is the same on one and two workers and symmetric with a zero diagonal") {
  const unsigned seed = 41;
  CAPTURE(seed);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0, 5);
  std::vector<PointDiagram> diagrams(7);
  for (auto& diagram : diagrams)
    for (int k = 0; k < 6; ++k) {
      const double b = unit(rng);
      diagram.finite.push_back({b, b + unit(rng)});
    }
  const DiagramMetric metric = [](const PointDiagram& a, const PointDiagram& b) {
    return bottleneck_distance(a, b).total;
  };
  const DistanceMatrix one = distance_matrix(diagrams, metric, 1);
  const DistanceMatrix two = distance_matrix(diagrams, metric, 2);
  CHECK(one.values == two.values);
  for (std::size_t i = 0; i < diagrams.size(); ++i) {
    CHECK(two.at(i, i) == 0);
    for (std::size_t j = 0; j < diagrams.size(); ++j)
      CHECK(two.at(i, j) == bottleneck_distance(diagrams[i], diagrams[j]).total);
  }
}

TEST_CASE("An exception of the metric on a worker reaches the caller") {
  std::vector<PointDiagram> diagrams(4);
  const DiagramMetric failing = [](const PointDiagram&, const PointDiagram&) -> double {
    throw InputError("metric: test failure");
  };
  CHECK_THROWS_AS(distance_matrix(diagrams, failing, 2), InputError);
  DistanceMatrix bad{2, {0, 1, 2, 0}};
  CHECK_THROWS_AS(single_linkage(bad), InputError);
}
