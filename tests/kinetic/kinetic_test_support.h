// Helpers for the kinetic engine tests: trajectories by hand and at random, and an observer that
// replays the event stream and checks it against the engine's own complex after every batch.
#pragma once

#include "medusa/kinetic/kinetic_alpha_complex.h"

#include <algorithm>
#include <random>
#include <set>
#include <vector>

namespace medusa::kinetic::testing {

// Replays the stream: K(t0+) then entered/left of every step. After each batch the replayed complex
// must equal the engine's (the stream is complete, issue "libmedusa will be built on this stream").
class ReplayObserver : public Observer {
public:
  explicit ReplayObserver(const KineticAlphaComplex& engine) : engine_(engine) {}

  void initial(const EventTime&, const std::vector<Simplex>& complex) override {
    k_.insert(complex.begin(), complex.end());
  }
  void batch(const EventTime& time, const std::vector<Step>& steps) override {
    times.push_back(time.time);
    for (const Step& s : steps) {
      ++step_counts[static_cast<int>(s.kind)];
      if (s.flip && s.flip->in_alpha)
        ++flips_in_alpha;
      for (const Simplex& x : s.left)
        if (k_.erase(x) != 1)
          ++inconsistencies; // left but was not in K
      for (const Simplex& x : s.entered)
        if (!k_.insert(x).second)
          ++inconsistencies; // entered but was in K already
    }
    std::vector<Simplex> engine = engine_.current_complex();
    if (std::vector<Simplex>(k_.begin(), k_.end()) != engine)
      ++mismatches;
    for (const Simplex& x : k_)
      if (x.size() > 1)
        for (std::size_t i = 0; i < x.size(); ++i)
          if (!k_.count(x.facet(i)))
            ++not_closed;
  }

  std::vector<double> times;
  int step_counts[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  int flips_in_alpha = 0, inconsistencies = 0, mismatches = 0, not_closed = 0;
  const std::set<Simplex>& complex() const { return k_; }

private:
  const KineticAlphaComplex& engine_;
  std::set<Simplex> k_;
};

// n cells doing independent random walks on the integer grid, over `frames` frames.
inline Trajectories random_walk(std::uint64_t seed, int n, int frames, int box, int step) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> start(0, box), d(-step, step);
  Trajectories t;
  t.scale = 1;
  for (int k = 0; k < frames; ++k)
    t.frame_times.push_back(100 * k);
  std::set<GridPoint> used;
  for (int i = 0; i < n; ++i) {
    Trajectory c;
    c.cell_id = i + 1;
    c.type = 1 + i % 2;
    GridPoint p;
    do
      p = {start(rng), start(rng), start(rng)};
    while (!used.insert(p).second);
    for (int k = 0; k < frames; ++k) {
      c.positions.push_back(p);
      for (auto& x : p)
        x += d(rng);
    }
    t.cells.push_back(c);
  }
  return t;
}

} // namespace medusa::kinetic::testing
