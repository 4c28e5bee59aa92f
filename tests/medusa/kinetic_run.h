// Runs the kinetic engine into a medusa (HDF5 store and in-memory collector at once) while recording
// the engine's own complex at every frame, for the differential tests of libmedusa against libkinetic.
#pragma once

#include "medusa/kinetic/kinetic_alpha_complex.h"
#include "medusa/medusa/medusa.h"
#include "medusa/medusa/medusa_builder.h"
#include "medusa/medusa/store_writer.h"
#include "stream.h"

#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace medusa::test {

// What the engine itself reported: K(t_0+) (as passed to initial() and as current_complex()), its
// current_complex() at every frame callback, and K(t_end-) at finish().
struct EngineRecord {
  SimplexSet initial_argument, initial_state, after_t0, at_end;
  std::map<std::size_t, SimplexSet> at_frame;
  bool finished = false;
};

inline SimplexSet as_set(const std::vector<kinetic::Simplex>& complex) {
  SimplexSet out;
  for (const kinetic::Simplex& s : complex)
    out.insert(std::vector<kinetic::VertexId>(s.begin(), s.end()));
  return out;
}

// Forwards the stream to `next` (the medusa builder) and records the engine's complex.
class RecordingObserver : public kinetic::Observer {
public:
  RecordingObserver(const kinetic::KineticAlphaComplex& engine, kinetic::Observer& next, EngineRecord& record)
      : engine_(engine), next_(next), record_(record) {}

  void initial(const kinetic::EventTime& t0, const std::vector<kinetic::Simplex>& complex) override {
    next_.initial(t0, complex);
    record_.initial_argument = as_set(complex);
    record_.initial_state = as_set(engine_.current_complex());
    record_.after_t0 = record_.initial_state;
  }
  void batch(const kinetic::EventTime& time, const std::vector<kinetic::Step>& steps) override {
    next_.batch(time, steps);
    // A batch at t_0 deletes the cells present at t_0 only: K(t_0+) is the state after it.
    if (time.slab == 0 && time.at_frame)
      record_.after_t0 = as_set(engine_.current_complex());
  }
  void frame(std::size_t k, const kinetic::EventTime& time) override {
    next_.frame(k, time);
    record_.at_frame[k] = as_set(engine_.current_complex());
  }
  void finish(const kinetic::EventTime& t_end) override {
    next_.finish(t_end);
    record_.at_end = as_set(engine_.current_complex());
    record_.finished = true;
  }

private:
  const kinetic::KineticAlphaComplex& engine_;
  kinetic::Observer& next_;
  EngineRecord& record_;
};

struct KineticRun {
  medusa::Medusa collected; // what the builder sent to the in-memory collector
  EngineRecord engine;
  kinetic::KineticStatistics statistics;
};

// Runs the audited engine over `input`; the builder feeds both a StoreWriter at `store_path` and a
// collector.
inline KineticRun run_into_store(const kinetic::Trajectories& input, const std::string& radius_text,
                                 const kinetic::SquaredRadius& rho2, const std::string& store_path,
                                 std::size_t audit_stride) {
  kinetic::KineticOptions options;
  options.rho2 = rho2;
  options.audit = true;
  options.audit_stride = audit_stride;
  medusa::RunInfo info;
  info.radius_text = radius_text;
  // rho = sqrt(rho_g^2) / S (docs/MATH.md §1.1): a store's radius is positive (read_store checks it).
  info.radius = std::sqrt(rho2.num.get_d() / rho2.den.get_d()) / static_cast<double>(input.scale);
  info.command_line = "test_medusa_from_kinetic";
  info.software_version = "test";
  KineticRun out;
  kinetic::KineticAlphaComplex engine(input, options);
  medusa::MedusaCollector collector;
  {
    medusa::StoreWriter writer(store_path);
    medusa::TeeSink tee({&writer, &collector});
    medusa::MedusaBuilder builder(tee);
    builder.set_run(info, input);
    RecordingObserver observer(engine, builder, out.engine);
    engine.run(observer);
  }
  out.collected = collector.take();
  out.statistics = engine.statistics();
  return out;
}

// The first `frames` frames of a run: later frame times dropped, cells born later removed, positions
// cut (vertex ids are re-numbered consecutively in the original order).
inline kinetic::Trajectories first_frames(const kinetic::Trajectories& t, std::size_t frames) {
  kinetic::Trajectories out = t;
  out.frame_times.resize(std::min(frames, t.frame_times.size()));
  out.cells.clear();
  for (const kinetic::Trajectory& c : t.cells) {
    if (c.first_frame >= out.frame_times.size())
      continue;
    kinetic::Trajectory cut = c;
    cut.positions.resize(std::min(c.positions.size(), out.frame_times.size() - c.first_frame));
    out.cells.push_back(cut);
  }
  return out;
}

} // namespace medusa::test
