// Forward against reverse on a time-symmetric run (frames A B C B A): the reverse diagram is the
// forward diagram mirrored by t -> t_0 + t_end - t (docs/MATH.md §7.2, §7.3).
//
// It holds exactly for the pairs of non-zero length and the essential classes, as batch indices;
// zero-length pairs depend on tie-breaking inside a batch and double times agree only up to
// rounding (docs/MATH.md §7.9).
#include "../kinetic/kinetic_test_support.h"
#include "kinetic_run.h"
#include "medusa/medusa/store_reader.h"
#include "medusa/persistence/diagram.h"
#include "medusa/persistence/filtration.h"
#include "medusa_fixtures.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>

using namespace medusa;
using namespace medusa::test;

namespace {

using Key = std::tuple<int, std::uint64_t, std::uint64_t>; // degree, birth batch, death batch

kinetic::Trajectories symmetric_walk(std::uint64_t seed, int n) {
  const int box = static_cast<int>(2000 * std::cbrt(static_cast<double>(n)));
  kinetic::Trajectories t = kinetic::testing::random_walk(seed, n, 3, box, 600);
  t.frame_times = {0, 100, 200, 300, 400};
  for (kinetic::Trajectory& c : t.cells) {
    const kinetic::GridPoint a = c.positions[0], b = c.positions[1];
    c.positions.push_back(b);
    c.positions.push_back(a);
  }
  return t;
}

// Off-diagonal pairs and essential classes by batch index (essential: death batch 0).
std::map<Key, int> forward_keys(const persistence::Diagram& d) {
  std::map<Key, int> out;
  for (const persistence::PersistencePair& p : d.pairs)
    if (!p.zero_length)
      ++out[Key{p.dim, p.birth_time.batch, p.essential ? 0 : p.death_time.batch}];
  return out;
}

// The reverse pairs mirrored: batch b -> N - b.
std::map<Key, int> mirrored_reverse_keys(const persistence::Diagram& d, std::uint64_t n) {
  std::map<Key, int> out;
  for (const persistence::PersistencePair& p : d.pairs)
    if (!p.zero_length)
      ++out[Key{p.dim, n - p.birth_time.batch, p.essential ? 0 : n - p.death_time.batch}];
  return out;
}

} // namespace

TEST_CASE("the reverse diagram of a time-symmetric run is the forward diagram mirrored in time",
          "[medusa][kinetic][persistence][symmetric]") {
  const std::uint64_t seed = GENERATE(31u, 32u, 33u);
  const int n = 30;
  CAPTURE(seed, n);
  const kinetic::Trajectories t = symmetric_walk(seed, n);
  kinetic::SquaredRadius rho2;
  rho2.num = 1200 * 1200;
  const std::string store = temp_path("symmetric-" + std::to_string(seed) + ".h5");
  const KineticRun run = run_into_store(t, "1200", rho2, store, 5);
  std::remove(store.c_str());
  CAPTURE(run.statistics.flips23, run.statistics.flips32, run.statistics.radius_events);
  REQUIRE(run.statistics.flips23 + run.statistics.flips32 > 0);
  REQUIRE(run.statistics.radius_events > 0);
  const medusa::Medusa& m = run.collected;
  const std::uint64_t n_end = m.end.batch;
  const double t0 = 0, t_end = 400;

  // The batches themselves are mirrored: batch i <-> N - i (batch N is t_end).
  REQUIRE(m.batches.size() == n_end);
  for (std::size_t i = 1; i < m.batches.size(); ++i) {
    const medusa::BatchRecord& a = m.batches[i];
    const medusa::BatchRecord& b = m.batches[n_end - i];
    CAPTURE(i, a.time, b.time);
    CHECK(a.at_frame == b.at_frame);
    CHECK(std::abs(a.time - (t0 + t_end - b.time)) <= 1e-9 * t_end);
  }

  for (bool whole : {true, false}) {
    std::vector<int> vertex_type;
    for (const kinetic::Trajectory& c : m.input.cells)
      vertex_type.push_back(c.type);
    const auto filtration = [&](persistence::Direction d) {
      return whole ? persistence::make_filtration(m.cells, d)
                   : persistence::make_type_filtration(m.cells, vertex_type, 1, d);
    };
    const persistence::Filtration ff = filtration(persistence::Direction::forward);
    const persistence::Filtration rf = filtration(persistence::Direction::reverse);
    const persistence::Diagram forward = persistence::compute_diagram(m.cells, ff);
    const persistence::Diagram reverse = persistence::compute_diagram(m.cells, rf);
    const auto fk = forward_keys(forward);
    const auto rk = mirrored_reverse_keys(reverse, n_end);
    CAPTURE(whole, fk.size(), rk.size());
    CHECK(fk == rk);
    std::size_t finite = 0, essential = 0;
    for (const persistence::PersistencePair& p : forward.pairs) {
      finite += !p.essential && !p.zero_length;
      essential += p.essential;
    }
    CHECK(essential > 0);
    if (whole)
      CHECK(finite > 0);

    // The double times agree up to rounding: sorted mirrored values match point by point.
    const auto values = [&](const persistence::Diagram& d, bool mirror) {
      std::vector<std::tuple<int, double, double>> v;
      for (const persistence::PersistencePair& p : d.pairs)
        if (!p.zero_length)
          v.emplace_back(p.dim, mirror ? t0 + t_end - p.birth : p.birth,
                         p.essential ? INFINITY : (mirror ? t0 + t_end - p.death : p.death));
      std::sort(v.begin(), v.end());
      return v;
    };
    const auto fv = values(forward, false), rv = values(reverse, true);
    REQUIRE(fv.size() == rv.size());
    for (std::size_t i = 0; i < fv.size(); ++i) {
      CAPTURE(i, std::get<1>(fv[i]), std::get<1>(rv[i]), std::get<2>(fv[i]), std::get<2>(rv[i]));
      CHECK(std::get<0>(fv[i]) == std::get<0>(rv[i]));
      CHECK(std::abs(std::get<1>(fv[i]) - std::get<1>(rv[i])) <= 1e-9 * t_end);
      if (std::isinf(std::get<2>(fv[i])))
        CHECK(std::isinf(std::get<2>(rv[i])));
      else
        CHECK(std::abs(std::get<2>(fv[i]) - std::get<2>(rv[i])) <= 1e-9 * t_end);
    }
  }
}
