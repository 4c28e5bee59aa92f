#include "python_run.h"

#include "medusa/core/error.h"
#include "medusa/core/version.h"
#include "medusa/io/cell_volumes.h"
#include "medusa/io/run_reader.h"
#include "medusa/kinetic/kinetic_alpha_complex.h"
#include "medusa/medusa/medusa_builder.h"
#include "medusa/medusa/store_reader.h"
#include "medusa/medusa/store_writer.h"
#include "medusa/persistence/diagram_store.h"
#include "medusa/persistence/medusa_diagrams.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <thread>

namespace medusa::python {
namespace {

namespace fs = std::filesystem;

// libkinetic reports t_end with the batch of the last event, while the builder wants the end after
// every batch (docs/MATH.md §6.2): the end gets the next batch index, as in `medusa run`.
class EndAfterLastBatch : public kinetic::Observer {
public:
  explicit EndAfterLastBatch(kinetic::Observer& next) : next_(next) {}
  void initial(const kinetic::EventTime& t0, const std::vector<kinetic::Simplex>& complex) override {
    last_batch_ = t0.batch;
    next_.initial(t0, complex);
  }
  void batch(const kinetic::EventTime& time, const std::vector<kinetic::Step>& steps) override {
    last_batch_ = std::max(last_batch_, time.batch);
    next_.batch(time, steps);
  }
  void frame(std::size_t k, const kinetic::EventTime& time) override { next_.frame(k, time); }
  void finish(const kinetic::EventTime& t_end) override {
    kinetic::EventTime end = t_end;
    end.batch = std::max(end.batch, last_batch_ + 1);
    next_.finish(end);
  }

private:
  kinetic::Observer& next_;
  std::size_t last_batch_ = 0;
};

io::RunSource source_of(const RunRequest& request) {
  if (request.source == "csv")
    return io::RunSource::csv;
  if (request.source == "vtk")
    return io::RunSource::vtk;
  if (!request.source.empty())
    throw InputError("source '" + request.source + "' is neither 'csv' nor 'vtk'");
  // CC3D's own centres (cells.csv.gz) lie on the 10^-6 grid, the VTK centroids do not (docs/MATH.md §1.2).
  std::error_code ec;
  const fs::path folder(request.input);
  if (fs::is_directory(folder, ec) &&
      (fs::exists(folder / "cells.csv.gz", ec) || fs::exists(folder / "cells.csv", ec)))
    return io::RunSource::csv;
  return io::RunSource::automatic;
}

std::string default_output(const std::string& input) {
  fs::path p = fs::path(input).lexically_normal();
  if (p.filename().empty())
    p = p.parent_path();
  std::string name = p.filename().string();
  for (const std::string suffix : {".gz", ".csv"})
    if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
      name.erase(name.size() - suffix.size());
  return (name.empty() || name == "." ? "run" : name) + ".h5";
}

} // namespace

std::string run_pipeline(const RunRequest& request, const std::string& command_line) {
  std::error_code ec;
  if (!fs::exists(request.input, ec))
    throw InputError("input " + request.input + " does not exist");
  io::RunOptions options;
  options.source = source_of(request);
  options.snap = request.snap;
  const io::RunData data = io::read_run(request.input, options);

  std::string radius = request.radius;
  if (radius == "auto") {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.6f",
                  io::equivalent_radius(io::median_cell_volume(data.volumes), data.trajectories.dimension));
    radius = buffer;
  }
  kinetic::KineticOptions kinetic_options;
  kinetic_options.rho2 = kinetic::squared_radius_from_decimal(radius, data.trajectories.scale);
  const std::string output = request.output.empty() ? default_output(request.input) : request.output;
  if (!request.force && fs::exists(output, ec))
    throw InputError("store " + output + " exists; pass force=True to replace it");

  medusa::RunInfo info;
  info.radius = std::stod(radius);
  info.radius_text = radius;
  info.source_files = data.sources;
  info.command_line = command_line;
  info.software_version = medusa::version;
  {
    kinetic::KineticAlphaComplex engine(data.trajectories, kinetic_options);
    medusa::StoreWriter writer(output);
    medusa::MedusaBuilder builder(writer);
    builder.set_run(info, data.trajectories);
    EndAfterLastBatch observer(builder);
    engine.run(observer);
  }

  medusa::StoreReadOptions cells_only;
  cells_only.events = false;
  const medusa::Medusa medusa = medusa::read_store(output, cells_only);
  std::vector<int> vertex_type;
  for (const kinetic::Trajectory& t : medusa.input.cells)
    vertex_type.push_back(t.type);
  std::vector<int> types = vertex_type;
  std::sort(types.begin(), types.end());
  types.erase(std::unique(types.begin(), types.end()), types.end());
  const unsigned threads =
      request.threads > 0 ? request.threads : std::max(1u, std::thread::hardware_concurrency());
  std::vector<persistence::ClassRepresentatives> classes;
  const std::vector<persistence::Diagram> diagrams =
      persistence::compute_medusa_diagrams(medusa.cells, vertex_type, types, threads, nullptr, &classes);
  std::vector<const persistence::ClassRepresentatives*> stored;
  for (std::size_t i = 0; i < diagrams.size(); ++i)
    stored.push_back(diagrams[i].direction == persistence::Direction::forward ? &classes[i] : nullptr);
  persistence::write_diagrams(output, diagrams, stored);
  return output;
}

} // namespace medusa::python
