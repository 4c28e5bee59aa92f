// Bottleneck and Wasserstein distances (docs/MATH.md §7.7) against brute-force enumeration of matchings,
// GUDHI / Hera, and a table of hand-derived cases.
#include "medusa/core/error.h"
#include "medusa/persistence/bottleneck.h"
#include "medusa/persistence/wasserstein.h"
#include "oracle.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <limits>
#include <random>

using namespace medusa;
using namespace medusa::persistence;
using namespace medusa::persistence::test;

namespace {

const double inf = std::numeric_limits<double>::infinity();

double linf(const Point& x, const Point& y) {
  return std::max(std::abs(x.birth - y.birth), std::abs(x.death - y.death));
}
double half(const Point& x) { return (x.death - x.birth) / 2; }

// Every partial matching of a into b: point i of a goes to an unused point of b or to the diagonal.
void enumerate(const std::vector<Point>& a, const std::vector<Point>& b, std::size_t i,
               std::vector<char>& used, std::vector<int>& match, const std::function<void()>& visit) {
  if (i == a.size()) {
    visit();
    return;
  }
  match[i] = -1;
  enumerate(a, b, i + 1, used, match, visit);
  for (std::size_t j = 0; j < b.size(); ++j)
    if (!used[j]) {
      used[j] = 1;
      match[i] = static_cast<int>(j);
      enumerate(a, b, i + 1, used, match, visit);
      used[j] = 0;
    }
}

std::pair<double, double> brute_force(const std::vector<Point>& a, const std::vector<Point>& b, double p) {
  double best_b = inf, best_w = inf;
  std::vector<char> used(b.size(), 0);
  std::vector<int> match(a.size(), -1);
  enumerate(a, b, 0, used, match, [&] {
    double worst = 0, sum = 0;
    std::vector<char> matched(b.size(), 0);
    for (std::size_t i = 0; i < a.size(); ++i) {
      const double c = match[i] < 0 ? half(a[i]) : linf(a[i], b[static_cast<std::size_t>(match[i])]);
      if (match[i] >= 0)
        matched[static_cast<std::size_t>(match[i])] = 1;
      worst = std::max(worst, c);
      sum += std::pow(c, p);
    }
    for (std::size_t j = 0; j < b.size(); ++j)
      if (!matched[j]) {
        worst = std::max(worst, half(b[j]));
        sum += std::pow(half(b[j]), p);
      }
    best_b = std::min(best_b, worst);
    best_w = std::min(best_w, sum);
  });
  return {best_b, std::pow(best_w, 1 / p)};
}

// Random points on a small integer grid (ties, duplicates, diagonal points) or real-valued.
std::vector<Point> random_points(std::mt19937& rng, std::size_t n, bool grid) {
  std::vector<Point> points;
  std::uniform_real_distribution<double> unit(0, 10);
  for (std::size_t i = 0; i < n; ++i) {
    double b = grid ? static_cast<double>(rng() % 5) : unit(rng);
    double d = b + (grid ? static_cast<double>(rng() % 4) : unit(rng) / 2);
    if (rng() % 6 == 0)
      d = b; // on the diagonal
    points.push_back({b, d});
    if (rng() % 6 == 0)
      points.push_back(points.back()); // duplicate
  }
  return points;
}

bool close(double x, double y, double rel) {
  return x == y || std::abs(x - y) <= rel * std::max(std::abs(x), std::abs(y));
}

std::vector<Point> parse_finite(const std::string& text) {
  std::vector<Point> points;
  std::istringstream in(text);
  for (std::string token; in >> token;) {
    if (token == "-")
      continue;
    const auto comma = token.find(',');
    points.push_back({std::stod(token.substr(0, comma)), std::stod(token.substr(comma + 1))});
  }
  return points;
}

std::vector<double> parse_essential(const std::string& text) {
  std::vector<double> births;
  std::istringstream in(text);
  for (std::string token; in >> token;)
    if (token != "-")
      births.push_back(std::stod(token));
  return births;
}

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t");
  const auto last = s.find_last_not_of(" \t");
  return first == std::string::npos ? "" : s.substr(first, last - first + 1);
}

} // namespace

TEST_CASE("Bottleneck and exact Wasserstein distances equal brute-force enumeration of matchings") {
  const unsigned seed = 7001;
  CAPTURE(seed);
  std::mt19937 rng(seed);
  int cases = 0;
  for (int round = 0; round < 300; ++round) {
    const bool grid = round % 2 == 0;
    const auto a = random_points(rng, rng() % 5, grid);
    const auto b = random_points(rng, rng() % 5, grid);
    if (a.size() > 5 || b.size() > 5)
      continue;
    for (double p : {1.0, 2.0, 3.5}) {
      CAPTURE(round, p, a.size(), b.size());
      const auto [db, wp] = brute_force(a, b, p);
      CHECK(bottleneck_finite(a, b) == db);
      CHECK(bottleneck_finite(b, a) == db);
      CHECK(bottleneck_finite(a, b, 1) == db); // the pivot selection path
      CHECK(close(wasserstein_finite_exact(a, b, p), wp, 1e-12));
      CHECK(close(wasserstein_finite_exact(b, a, p), wp, 1e-12));
      ++cases;
    }
  }
  CHECK(cases > 300);
}

TEST_CASE("The auction Wasserstein distance is certified within the requested relative error") {
  for (unsigned seed : {8001u, 8002u, 8003u}) {
    CAPTURE(seed);
    std::mt19937 rng(seed);
    const auto a = random_points(rng, 60 + rng() % 60, seed == 8003u);
    const auto b = random_points(rng, 60 + rng() % 60, seed == 8003u);
    for (double p : {1.0, 2.0}) {
      const double exact = wasserstein_finite_exact(a, b, p);
      for (double delta : {0.01, 0.001}) {
        CAPTURE(p, delta, a.size(), b.size());
        const ApproximateDistance approx = wasserstein_finite_auction(a, b, p, delta);
        CHECK(approx.value >= exact * (1 - 1e-12));
        CHECK(approx.value <= exact * (1 + delta) * (1 + 1e-12));
        CHECK(approx.relative_error <= delta);
        CHECK_FALSE(approx.exact); // certified by the auction itself, not by the exact fallback
      }
    }
  }
}

TEST_CASE("Distances agree with GUDHI's bottleneck and Hera's Wasserstein, essential classes included") {
  const unsigned seed = 9001;
  CAPTURE(seed);
  std::mt19937 rng(seed);
  TempDir dir("distances");
  std::vector<std::pair<PointDiagram, PointDiagram>> pairs;
  std::vector<double> orders;
  {
    std::FILE* out = std::fopen(dir.file("cases.txt").c_str(), "w");
    REQUIRE(out);
    for (int k = 0; k < 24; ++k) {
      PointDiagram a{random_points(rng, rng() % 25, k % 3 == 0), {}};
      PointDiagram b{random_points(rng, rng() % 25, k % 3 == 0), {}};
      const std::size_t essential = rng() % 3;
      for (std::size_t e = 0; e < essential; ++e) {
        a.essential.push_back(static_cast<double>(rng() % 7));
        b.essential.push_back(static_cast<double>(rng() % 7));
      }
      if (k % 8 == 7)
        b.essential.push_back(1.0); // counts differ: infinite distance
      const double p = k % 2 == 0 ? 1.0 : 2.0;
      std::fprintf(out, "case %d %g\n", k, p);
      for (const Point& x : a.finite)
        std::fprintf(out, "a %.17g %.17g\n", x.birth, x.death);
      for (double e : a.essential)
        std::fprintf(out, "a %.17g inf\n", e);
      for (const Point& y : b.finite)
        std::fprintf(out, "b %.17g %.17g\n", y.birth, y.death);
      for (double e : b.essential)
        std::fprintf(out, "b %.17g inf\n", e);
      pairs.emplace_back(a, b);
      orders.push_back(p);
    }
    std::fclose(out);
  }
  run(python() + " " + data_path("persistence/distance_oracle.py") + " " + dir.file("cases.txt") + " " +
      dir.file("out.txt"));
  std::istringstream in(read_text(dir.file("out.txt")));
  std::size_t checked = 0;
  for (std::string id, bs, ws; in >> id >> bs >> ws;) {
    const std::size_t k = std::stoul(id);
    CAPTURE(k);
    const auto& [a, b] = pairs.at(k);
    const double gudhi_b = std::stod(bs), hera_w = std::stod(ws);
    // GUDHI's exact mode may differ in the last bits of the mantissa (its documentation says so).
    CHECK(close(bottleneck_distance(a, b).total, gudhi_b, 1e-14));
    WassersteinOptions options;
    options.p = orders[k];
    CHECK(close(wasserstein_distance(a, b, options).total, hera_w, 1e-8));
    ++checked;
  }
  CHECK(checked == pairs.size());
}

TEST_CASE("The table of hand-derived distance cases holds") {
  std::ifstream in(data_path("persistence/distance_cases.txt"));
  REQUIRE(in);
  std::size_t rows = 0;
  for (std::string line; std::getline(in, line);) {
    if (trim(line).empty() || trim(line)[0] == '#')
      continue;
    std::vector<std::string> fields;
    std::istringstream ls(line);
    for (std::string field; std::getline(ls, field, ';');)
      fields.push_back(trim(field));
    REQUIRE(fields.size() == 8);
    CAPTURE(fields[0]);
    const PointDiagram a{parse_finite(fields[1]), parse_essential(fields[2])};
    const PointDiagram b{parse_finite(fields[3]), parse_essential(fields[4])};
    WassersteinOptions options;
    options.p = std::stod(fields[5]);
    CHECK(bottleneck_distance(a, b).total == std::stod(fields[6]));
    CHECK(bottleneck_distance(b, a).total == std::stod(fields[6]));
    CHECK(close(wasserstein_distance(a, b, options).total, std::stod(fields[7]), 1e-15));
    CHECK(close(wasserstein_distance(b, a, options).total, std::stod(fields[7]), 1e-15));
    ++rows;
  }
  CHECK(rows > 0);
}

TEST_CASE("Essential parts are reported apart and can be ignored when their counts differ") {
  const PointDiagram a{{{0, 4}}, {0, 2}};
  const PointDiagram b{{{1, 4}}, {5}};
  const DistanceResult d = bottleneck_distance(a, b);
  CHECK(d.finite == 1);
  CHECK(std::isinf(d.essential));
  CHECK(d.essential_count_a == 2);
  CHECK(d.essential_count_b == 1);
  CHECK(std::isinf(d.total));
  CHECK(bottleneck_distance(a, b, true).total == 1);
  WassersteinOptions options;
  options.ignore_essential = true;
  const DistanceResult w = wasserstein_distance(a, b, options);
  CHECK(w.total == 1);
  CHECK(std::isinf(w.essential));
  CHECK(w.exact);
}

TEST_CASE("Large diagrams use the certified auction and report its error bound") {
  const unsigned seed = 8101;
  CAPTURE(seed);
  std::mt19937 rng(seed);
  const PointDiagram a{random_points(rng, 150, false), {}};
  const PointDiagram b{random_points(rng, 150, false), {}};
  WassersteinOptions options;
  options.exact_limit = 100;
  options.delta = 0.01;
  const DistanceResult approx = wasserstein_distance(a, b, options);
  options.exact_limit = 1000;
  const DistanceResult exact = wasserstein_distance(a, b, options);
  CHECK(exact.exact);
  CHECK(exact.relative_error == 0);
  CHECK_FALSE(approx.exact);
  CHECK(approx.relative_error <= 0.01);
  CHECK(approx.total >= exact.total * (1 - 1e-12));
  CHECK(approx.total <= exact.total * 1.01 * (1 + 1e-12));
  const double db = bottleneck_distance(a, b).total;
  CHECK(bottleneck_finite(a.finite, b.finite, 16) == db);
  CHECK(bottleneck_finite(b.finite, a.finite, 1) == db);
}

TEST_CASE("Invalid points and orders are input errors") {
  const PointDiagram good{{{0, 1}}, {}};
  const PointDiagram reversed{{{2, 1}}, {}};
  const PointDiagram nan_point{{{0, std::nan("")}}, {}};
  CHECK_THROWS_AS(bottleneck_distance(good, reversed), InputError);
  CHECK_THROWS_AS(wasserstein_distance(nan_point, good), InputError);
  WassersteinOptions options;
  options.p = 0.5;
  CHECK_THROWS_AS(wasserstein_distance(good, good, options), InputError);
  CHECK_THROWS_AS(wasserstein_finite_auction(good.finite, good.finite, 1, 0), InputError);
}

TEST_CASE("The exact Wasserstein distance agrees with Hera on diagrams of a hundred points and more") {
  // Sizes where the Hungarian method starts from its greedy matching on tight edges and still has
  // many augmentations to do; grid points give ties, where that matching has choices.
  const unsigned seed = 9101;
  CAPTURE(seed);
  std::mt19937 rng(seed);
  TempDir dir("distances-large");
  std::vector<std::pair<std::vector<Point>, std::vector<Point>>> pairs;
  {
    std::FILE* out = std::fopen(dir.file("cases.txt").c_str(), "w");
    REQUIRE(out);
    for (int k = 0; k < 8; ++k) {
      const auto a = random_points(rng, 80 + rng() % 100, k % 2 == 0);
      const auto b = random_points(rng, 80 + rng() % 100, k % 2 == 0);
      std::fprintf(out, "case %d %g\n", k, k < 4 ? 1.0 : 2.0);
      for (const Point& x : a)
        std::fprintf(out, "a %.17g %.17g\n", x.birth, x.death);
      for (const Point& y : b)
        std::fprintf(out, "b %.17g %.17g\n", y.birth, y.death);
      pairs.emplace_back(a, b);
    }
    std::fclose(out);
  }
  run(python() + " " + data_path("persistence/distance_oracle.py") + " " + dir.file("cases.txt") + " " +
      dir.file("out.txt"));
  std::istringstream in(read_text(dir.file("out.txt")));
  std::size_t checked = 0;
  for (std::string id, bs, ws; in >> id >> bs >> ws;) {
    const std::size_t k = std::stoul(id);
    const auto& [a, b] = pairs.at(k);
    const double p = k < 4 ? 1.0 : 2.0;
    CAPTURE(k, p, a.size(), b.size());
    CHECK(close(wasserstein_finite_exact(a, b, p), std::stod(ws), 1e-8));
    CHECK(close(wasserstein_finite_exact(b, a, p), std::stod(ws), 1e-8));
    ++checked;
  }
  CHECK(checked == pairs.size());
}
