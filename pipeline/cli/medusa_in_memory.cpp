#include "medusa_in_memory.h"

#include "interrupt.h"

#include "medusa/kinetic/kinetic_alpha_complex.h"
#include "medusa/medusa/medusa_builder.h"
#include "medusa/periodic/canonical_filter.h"
#include "medusa/periodic/periodic_cover.h"

#include <algorithm>
#include <optional>

namespace medusa::cli {
namespace {

// Forwards the event stream to the builder and polls for interrupts. As in `medusa run`, the end is
// given the batch index after the last event batch: libkinetic reports t_end with the index of the
// last batch, while the builder wants the end strictly after every batch (docs/MATH.md §6.2).
class ForwardingObserver : public kinetic::Observer {
public:
  explicit ForwardingObserver(kinetic::Observer& next) : next_(next) {}
  void initial(const kinetic::EventTime& t0, const std::vector<kinetic::Simplex>& complex) override {
    last_batch_ = t0.batch;
    next_.initial(t0, complex);
  }
  void batch(const kinetic::EventTime& time, const std::vector<kinetic::Step>& steps) override {
    check_interrupted();
    last_batch_ = std::max(last_batch_, time.batch);
    next_.batch(time, steps);
  }
  void frame(std::size_t k, const kinetic::EventTime& time) override {
    check_interrupted();
    next_.frame(k, time);
  }
  void finish(const kinetic::EventTime& t_end) override {
    kinetic::EventTime end = t_end;
    end.batch = std::max(end.batch, last_batch_ + 1);
    next_.finish(end);
  }

private:
  kinetic::Observer& next_;
  std::size_t last_batch_ = 0;
};

} // namespace

medusa::Medusa medusa_in_memory(const kinetic::Trajectories& trajectories, const medusa::RunInfo& info,
                                const io::PeriodicDomain& domain) {
  kinetic::KineticOptions options;
  options.rho2 = kinetic::squared_radius_from_decimal(info.radius_text, trajectories.scale);
  medusa::MedusaCollector collector;
  {
    // As in `medusa run`: a periodic run goes through the covering space and the canonical filter.
    std::optional<periodic::PeriodicCover> cover;
    if (domain.any())
      cover = periodic::cover_trajectories(trajectories, domain, options.rho2);
    kinetic::KineticAlphaComplex engine(cover ? cover->trajectories : trajectories, options);
    medusa::MedusaBuilder builder(collector);
    medusa::RunInfo run = info;
    if (cover) {
      run.periodic_axes = domain.axes();
      run.periodic_lengths = domain.period;
    }
    builder.set_run(run, trajectories);
    ForwardingObserver observer(builder);
    std::optional<periodic::CanonicalFilter> torus;
    if (cover)
      torus.emplace(*cover, observer);
    engine.run(torus ? static_cast<kinetic::Observer&>(*torus) : observer);
  }
  return collector.take();
}

} // namespace medusa::cli
