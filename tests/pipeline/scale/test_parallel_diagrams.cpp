// compute_medusa_diagrams on worker threads, and its two phases, give exactly the diagrams of the
// sequential computation (libpersistence/include/medusa/persistence/medusa_diagrams.h), on the
// medusa of a real run: the first 3 frames of examples/sorting_3d at radius 3.
#include "medusa/core/error.h"
#include "medusa/io/run_reader.h"
#include "medusa/kinetic/kinetic_alpha_complex.h"
#include "medusa/medusa/medusa.h"
#include "medusa/medusa/medusa_builder.h"
#include "medusa/persistence/diagram_text.h"
#include "medusa/persistence/medusa_diagrams.h"

#include <catch2/catch.hpp>

#include <sstream>
#include <string>
#include <vector>

using namespace medusa;

namespace {

struct RunMedusa {
  medusa::Medusa medusa;
  std::vector<int> vertex_type;
};

const RunMedusa& sorting_3frames() {
  static const RunMedusa run = [] {
    const io::RunData data = io::read_run(std::string(MEDUSA_TEST_DATA) + "/cli/cells_3frames.csv.gz");
    kinetic::KineticOptions options;
    options.rho2 = kinetic::squared_radius_from_decimal("3", data.trajectories.scale);
    kinetic::KineticAlphaComplex engine(data.trajectories, options);
    medusa::MedusaCollector collector;
    medusa::MedusaBuilder builder(collector);
    medusa::RunInfo info;
    info.radius = 3;
    info.radius_text = "3";
    builder.set_run(info, data.trajectories);
    engine.run(builder);
    RunMedusa r{collector.take(), {}};
    for (const kinetic::Trajectory& c : data.trajectories.cells)
      r.vertex_type.push_back(c.type);
    return r;
  }();
  return run;
}

std::string text(const std::vector<persistence::Diagram>& diagrams) {
  std::ostringstream out;
  for (const persistence::Diagram& d : diagrams)
    persistence::write_diagram_text(out, d, sorting_3frames().medusa.cells);
  return out.str();
}

} // namespace

TEST_CASE("Diagrams on one, two, three or eight threads are identical", "[cli][threads]") {
  const RunMedusa& run = sorting_3frames();
  const std::vector<int> types = {1, 2};
  const std::vector<persistence::Diagram> diagrams =
      persistence::compute_medusa_diagrams(run.medusa.cells, run.vertex_type, types);
  // Six diagrams (whole, type 1, type 2; forward and reverse), each with pairs: enough work for every
  // thread count below to split.
  REQUIRE(diagrams.size() == 6);
  for (const persistence::Diagram& d : diagrams)
    REQUIRE_FALSE(d.pairs.empty());
  const std::string sequential = text(diagrams);
  for (unsigned threads : {2u, 3u, 8u}) {
    CAPTURE(threads);
    CHECK(text(persistence::compute_medusa_diagrams(run.medusa.cells, run.vertex_type, types,
                                                    persistence::DiagramRunOptions::on_threads(threads))) ==
          sequential);
  }
}

TEST_CASE("A filtration error on a worker thread reaches the caller", "[cli][threads]") {
  const RunMedusa& run = sorting_3frames();
  // A vertex-type table too short for the cells: make_type_filtration throws InputError.
  const std::vector<int> short_table(run.vertex_type.begin(), run.vertex_type.begin() + 10);
  const std::vector<int> types = {1, 2};
  CHECK_THROWS_AS(persistence::compute_medusa_diagrams(run.medusa.cells, short_table, types,
                                                       persistence::DiagramRunOptions::on_threads(2)),
                  InputError);
}
