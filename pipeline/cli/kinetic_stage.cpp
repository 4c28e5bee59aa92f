#include "kinetic_stage.h"

#include "interrupt.h"

#include "medusa/kinetic/kinetic_alpha_complex.h"
#include "medusa/medusa/medusa_builder.h"
#include "medusa/periodic/canonical_filter.h"
#include "medusa/periodic/periodic_cover.h"

#include <algorithm>
#include <optional>

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
                  medusa::CellSink& sink, const io::PeriodicDomain& domain) {
  kinetic::KineticOptions options;
  options.rho2 = kinetic::squared_radius_from_decimal(info.radius_text, trajectories.scale);
  // As in `medusa run`: a periodic run goes through the covering space and the canonical filter.
  std::optional<periodic::PeriodicCover> cover;
  if (domain.any())
    cover = periodic::cover_trajectories(trajectories, domain, options.rho2);
  kinetic::KineticAlphaComplex engine(cover ? cover->trajectories : trajectories, options);
  medusa::MedusaBuilder builder(sink);
  medusa::RunInfo run = info;
  if (cover) {
    run.periodic_axes = domain.axes();
    run.periodic_lengths = domain.period;
  }
  builder.set_run(run, trajectories);
  EndAfterLastBatch observer(builder);
  std::optional<periodic::CanonicalFilter> torus;
  if (cover)
    torus.emplace(*cover, observer);
  engine.run(torus ? static_cast<kinetic::Observer&>(*torus) : observer);
}

} // namespace medusa::cli
