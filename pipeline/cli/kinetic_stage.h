// The kinetic stage of a run for one radius: the kinetic engine on the trajectories, its events fed
// to the medusa builder, the cells streamed into a sink (a store writer, or memory). Shared by
// `medusa sweep` (medusa_in_memory) and the Python module's `medusa.run`.
#pragma once

#include "medusa/io/periodic_domain.h"
#include "medusa/kinetic/observer.h"
#include "medusa/kinetic/trajectories.h"
#include "medusa/medusa/cell_sink.h"
#include "medusa/medusa/run_info.h"

#include <cstddef>

namespace medusa::cli {

// Forwards the event stream to `next` and polls for interrupts. libkinetic reports t_end with the
// batch index of the last event batch, while the builder wants the end strictly after every batch
// (docs/MATH.md §6.2: cells alive at t_end die at the final virtual time): the end is given the next
// batch index.
class EndAfterLastBatch : public kinetic::Observer {
public:
  explicit EndAfterLastBatch(kinetic::Observer& next) : next_(next) {}
  void initial(const kinetic::EventTime& t0, const std::vector<kinetic::Simplex>& complex) override;
  void batch(const kinetic::EventTime& time, const std::vector<kinetic::Step>& steps) override;
  void frame(std::size_t k, const kinetic::EventTime& time) override;
  void finish(const kinetic::EventTime& t_end) override;

private:
  kinetic::Observer& next_;
  std::size_t last_batch_ = 0;
};

// Runs the engine on `trajectories` at radius `info.radius_text` (decimal text, exact, docs/MATH.md
// §1) and streams the medusa into `sink`. Polls for interrupts (throws Interrupted). With periodic axes
// in `domain`, the complex on the torus (docs/MATH.md §8): the radius must pass
// periodic::check_periodic_radius.
void build_medusa(const kinetic::Trajectories& trajectories, const medusa::RunInfo& info,
                  medusa::CellSink& sink, const io::PeriodicDomain& domain = {});

} // namespace medusa::cli
