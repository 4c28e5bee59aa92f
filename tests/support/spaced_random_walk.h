// Seeded random walks of cells with CC3D-like spacing, and cell turnover on them: the synthetic runs
// of bench/kinetic_bench.cpp and of the engine contract (tests/kinetic/test_engine_contract.cpp).
// The contract records digests of these walks, so their random streams must not change. It lives
// among the tests' helpers; kinetic_bench adds tests/ to its include path (bench/CMakeLists.txt).
#pragma once

#include "medusa/kinetic/trajectories.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>

namespace medusa::test {

// n cells on the 10^-6 grid in a cube (square) of side 5 n^(1/d) lattice units, so that cells are ~5
// units apart as CC3D cells of volume 125 are, each coordinate stepping by a normal of standard
// deviation step_sd units per frame (0.7: ~1 unit per 100 MCS); dimension 2 keeps z = 0.
inline kinetic::Trajectories spaced_random_walk(std::uint64_t seed, int dimension, int n, int frames,
                                                double step_sd = 0.7) {
  const std::int64_t unit = 1000000;
  std::mt19937_64 rng(seed);
  const double side = 5.0 * (dimension == 3 ? std::cbrt(double(n)) : std::sqrt(double(n)));
  std::uniform_real_distribution<double> start(0, side * unit);
  std::normal_distribution<double> step(0, step_sd * unit);
  kinetic::Trajectories t;
  t.dimension = dimension;
  for (int k = 0; k < frames; ++k)
    t.frame_times.push_back(100 * k);
  for (int i = 0; i < n; ++i) {
    kinetic::Trajectory c;
    c.cell_id = i + 1;
    c.type = 1 + i % 2;
    kinetic::GridPoint p{0, 0, 0};
    for (int j = 0; j < dimension; ++j)
      p[j] = std::int64_t(start(rng));
    for (int k = 0; k < frames; ++k) {
      c.positions.push_back(p);
      for (int j = 0; j < dimension; ++j)
        p[j] += std::int64_t(step(rng));
    }
    t.cells.push_back(c);
  }
  return t;
}

// Cell turnover, as in a growing CompuCell3D tissue: each cell is, with probability `fraction`, born
// at a random later frame (its earlier positions dropped), and with the same probability dies after
// a random earlier frame, so that about fraction * n / (frames - 1) cells appear and as many vanish
// per frame: insertions and deletions at every frame (docs/MATH.md §5.6).
inline void add_turnover(kinetic::Trajectories& t, double fraction, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coin(0, 1);
  const std::size_t frames = t.frame_times.size();
  for (kinetic::Trajectory& c : t.cells) {
    const double r = coin(rng);
    if (r < fraction) {
      c.first_frame = 1 + rng() % (frames - 1);
      c.positions.erase(c.positions.begin(), c.positions.begin() + std::ptrdiff_t(c.first_frame));
    } else if (r < 2 * fraction) {
      c.positions.resize(1 + rng() % (frames - 1));
    }
  }
}

} // namespace medusa::test
