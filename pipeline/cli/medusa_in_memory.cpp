#include "medusa_in_memory.h"

#include "kinetic_stage.h"

namespace medusa::cli {

medusa::Medusa medusa_in_memory(const kinetic::Trajectories& trajectories, const medusa::RunInfo& info,
                                const io::PeriodicDomain& domain) {
  medusa::MedusaCollector collector;
  build_medusa(trajectories, info, collector, domain);
  return collector.take();
}

} // namespace medusa::cli
