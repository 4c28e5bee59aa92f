#include "python_run.h"

#include "atomic_file.h"
#include "interrupt.h"
#include "kinetic_stage.h"
#include "run_input.h"
#include "run_outputs.h"

#include "medusa/core/error.h"
#include "medusa/io/run_reader.h"
#include "medusa/kinetic/kinetic_alpha_complex.h"
#include "medusa/medusa/store_reader.h"
#include "medusa/medusa/store_writer.h"
#include "medusa/periodic/periodic_cover.h"
#include "medusa/persistence/diagram_store.h"
#include "medusa/persistence/medusa_diagrams.h"

#include <algorithm>
#include <filesystem>
#include <thread>

namespace medusa::python {

std::string run_pipeline(const RunRequest& request, const std::string& command_line) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(request.input, ec))
    throw InputError("input " + request.input + " does not exist");
  if (!request.source.empty() && request.source != "csv" && request.source != "vtk")
    throw InputError("source '" + request.source + "' is neither 'csv' nor 'vtk'");
  const std::string output = request.output.empty() ? cli::input_stem(request.input) + ".h5" : request.output;
  cli::check_output_folder(output);
  if (!request.force && fs::exists(output, ec))
    throw InputError("store " + output + " exists; pass force=True to replace it");
  // As in `medusa run`: the store is written under a temporary name, with a lock beside it, and
  // renamed into place only once its diagrams are in it; an error or an interrupt removes it.
  cli::RunOutputs outputs(output, {}, request.input);
  io::RunOptions options;
  options.source = cli::choose_source(request.input, request.source);
  options.snap = request.snap;
  options.round_csv = request.round_csv;
  options.skip_unreadable_frames = request.skip_unreadable_frames;
  options.spellings = {"round_csv=True", "snap=False", "periodic_as_open=True",
                       "skip_unreadable_frames=True"};
  options.allow_periodic_as_open = request.periodic_as_open;
  options.read_periodic = !request.periodic_as_open;
  io::RunData data = io::read_run(request.input, options);
  outputs.check_not_read(data.sources);
  cli::check_interrupted();

  const std::string radius = cli::resolve_radius(request.radius, data).first;
  // As `medusa run`: a periodic run on the torus, the cells and their copies near the seams through the
  // canonical filter (docs/MATH.md §8); a radius too large for the period refused before any work.
  const io::PeriodicDomain domain = request.periodic_as_open ? io::PeriodicDomain{} : data.domain;
  if (domain.any())
    periodic::check_periodic_radius(
        domain, kinetic::squared_radius_from_decimal(radius, data.trajectories.scale), radius);
  {
    medusa::StoreWriter writer(outputs.final_name(0), medusa::StoreWriter::Publish::later);
    cli::build_medusa(data.trajectories, cli::run_info(data, radius, command_line), writer, domain);
  }
  cli::check_interrupted();

  medusa::StoreReadOptions cells_only;
  cells_only.events = false;
  const medusa::Medusa medusa = medusa::read_store(outputs.store_temporary(), cells_only);
  std::vector<int> vertex_type;
  for (const kinetic::Trajectory& t : medusa.input.cells)
    vertex_type.push_back(t.type);
  std::vector<int> types = vertex_type;
  std::sort(types.begin(), types.end());
  types.erase(std::unique(types.begin(), types.end()), types.end());
  const unsigned threads =
      request.threads > 0 ? request.threads : std::max(1u, std::thread::hardware_concurrency());
  // Each diagram goes into the store as soon as it is made, and nothing of it is kept: the caller
  // reads the store.
  std::vector<persistence::ClassRepresentatives> classes;
  persistence::DiagramStoreWriter writer(outputs.store_temporary(), persistence::medusa_diagram_names(types));
  persistence::DiagramRunOptions diagram_options;
  diagram_options.threads = threads;
  diagram_options.forward_classes = &classes;
  diagram_options.representatives.shorten = request.shorten_representatives;
  diagram_options.poll = cli::check_interrupted;
  diagram_options.zero_length = false;
  diagram_options.on_diagram = [&](std::size_t, persistence::Diagram& d,
                                   persistence::ClassRepresentatives* c) {
    writer.write(d, c);
    d.pairs = {};
  };
  persistence::compute_medusa_diagrams(medusa.cells, vertex_type, types, diagram_options);
  writer.close();
  cli::check_interrupted();
  outputs.publish();
  return outputs.final_name(0);
}

} // namespace medusa::python
