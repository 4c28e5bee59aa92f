#include "medusa_in_memory.h"

#include "kinetic_stage.h"

namespace medusa::cli {

medusa::Medusa medusa_in_memory(const kinetic::Trajectories& trajectories, const medusa::RunInfo& info) {
  medusa::MedusaCollector collector;
  build_medusa(trajectories, info, collector);
  return collector.take();
}

} // namespace medusa::cli
