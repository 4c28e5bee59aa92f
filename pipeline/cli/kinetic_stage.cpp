#include "kinetic_stage.h"

#include "interrupt.h"

#include "medusa/kinetic/kinetic_alpha_complex.h"
#include "medusa/medusa/medusa_builder.h"

#include <algorithm>

namespace medusa::cli {

void EndAfterLastBatch::initial(const kinetic::EventTime& t0, const std::vector<kinetic::Simplex>& complex) {
  last_batch_ = t0.batch;
  next_.initial(t0, complex);
}

void EndAfterLastBatch::batch(const kinetic::EventTime& time, const std::vector<kinetic::Step>& steps) {
  check_interrupted();
  last_batch_ = std::max(last_batch_, time.batch);
  next_.batch(time, steps);
}

void EndAfterLastBatch::frame(std::size_t k, const kinetic::EventTime& time) {
  check_interrupted();
  next_.frame(k, time);
}

void EndAfterLastBatch::finish(const kinetic::EventTime& t_end) {
  kinetic::EventTime end = t_end;
  end.batch = std::max(end.batch, last_batch_ + 1);
  next_.finish(end);
}

void build_medusa(const kinetic::Trajectories& trajectories, const medusa::RunInfo& info,
                  medusa::CellSink& sink) {
  kinetic::KineticOptions options;
  options.rho2 = kinetic::squared_radius_from_decimal(info.radius_text, trajectories.scale);
  kinetic::KineticAlphaComplex engine(trajectories, options);
  medusa::MedusaBuilder builder(sink);
  builder.set_run(info, trajectories);
  EndAfterLastBatch observer(builder);
  engine.run(observer);
}

} // namespace medusa::cli
