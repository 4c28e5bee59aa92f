// Hand-written kinetic event streams for the medusa tests: a recorded stream that can be played into
// any observer, and the complexes it implies (the replay oracle).
#pragma once

#include "medusa/kinetic/observer.h"
#include "medusa/kinetic/trajectories.h"

#include <cstdint>
#include <map>
#include <set>
#include <vector>

namespace medusa::test {

using kinetic::EventTime;
using kinetic::Simplex;
using kinetic::Step;
using kinetic::VertexId;

struct RecordedBatch {
  EventTime time;
  std::vector<Step> steps;
  std::vector<std::size_t> frames_after; // frames reported right after this batch
};

struct Stream {
  EventTime t0;
  std::vector<Simplex> initial;
  std::vector<std::size_t> frames_after_initial;
  std::vector<RecordedBatch> batches;
  EventTime t_end;

  void play(kinetic::Observer& observer) const {
    play_events(observer);
    observer.finish(t_end);
  }

  // Everything but the final finish() (a run stopped, or a test that finishes on its own).
  void play_events(kinetic::Observer& observer) const {
    observer.initial(t0, initial);
    for (std::size_t k : frames_after_initial)
      observer.frame(k, t0);
    for (const RecordedBatch& b : batches) {
      observer.batch(b.time, b.steps);
      for (std::size_t k : b.frames_after)
        observer.frame(k, b.time);
    }
  }
};

inline EventTime event_time(std::size_t batch, double time, std::size_t slab = 0, double u = 0.0,
                            bool at_frame = false) {
  EventTime t;
  t.batch = batch;
  t.time = time;
  t.slab = slab;
  t.u = u;
  t.at_frame = at_frame;
  return t;
}

using SimplexSet = std::set<std::vector<VertexId>>;

inline std::vector<VertexId> tuple(const Simplex& s) { return std::vector<VertexId>(s.begin(), s.end()); }

// K after every batch (key: batch index), obtained by applying entered/left literally; K(b-) is the
// value of the previous batch.
inline std::map<std::uint64_t, SimplexSet> replay(const Stream& stream) {
  std::map<std::uint64_t, SimplexSet> out;
  SimplexSet k;
  for (const Simplex& s : stream.initial)
    k.insert(tuple(s));
  out[stream.t0.batch] = k;
  for (const RecordedBatch& b : stream.batches) {
    for (const Step& st : b.steps) {
      for (const Simplex& s : st.left)
        k.erase(tuple(s));
      for (const Simplex& s : st.entered)
        k.insert(tuple(s));
    }
    out[b.time.batch] = k;
  }
  return out;
}

// All faces of the given simplices (closure), in canonical order.
inline std::vector<Simplex> closure(const std::vector<Simplex>& top) {
  std::set<Simplex> all;
  for (const Simplex& s : top) {
    const std::size_t n = s.size();
    for (std::uint32_t mask = 1; mask < (1u << n); ++mask) {
      std::vector<VertexId> v;
      for (std::size_t i = 0; i < n; ++i)
        if (mask & (1u << i))
          v.push_back(s[i]);
      all.insert(Simplex::from_range(v.begin(), v.end()));
    }
  }
  return std::vector<Simplex>(all.begin(), all.end());
}

// Trajectories with `vertices` cells of the given types (type 1 when empty) and `frames` frames
// 0, 10, 20, ... MCS; positions are placeholders (the medusa never reads them).
inline kinetic::Trajectories dummy_input(std::size_t vertices, std::size_t frames,
                                         std::vector<int> types = {}) {
  kinetic::Trajectories t;
  t.scale = 1000;
  for (std::size_t k = 0; k < frames; ++k)
    t.frame_times.push_back(static_cast<std::int64_t>(10 * k));
  for (std::size_t v = 0; v < vertices; ++v) {
    kinetic::Trajectory tr;
    tr.cell_id = static_cast<std::int64_t>(100 + v);
    tr.type = types.empty() ? 1 : types[v];
    tr.first_frame = 0;
    for (std::size_t k = 0; k < frames; ++k)
      tr.positions.push_back(
          {static_cast<std::int64_t>(v), static_cast<std::int64_t>(k), -static_cast<std::int64_t>(v)});
    t.cells.push_back(tr);
  }
  t.type_names = {"Medium", "Condensing", "NonCondensing"};
  return t;
}

} // namespace medusa::test
