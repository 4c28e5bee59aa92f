#include "medusa/io/run_reader.h"

#include "frame_series.h"
#include "medusa/core/error.h"
#include "medusa/core/grid_text.h"
#include "medusa/io/periodic_unwrap.h"
#include "medusa/io/trajectory_assembly.h"
#include "medusa/io/vtk_reader.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <unistd.h>

namespace medusa::io {

namespace fs = std::filesystem;

namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool is_csv_name(const std::string& name) { return ends_with(name, ".csv") || ends_with(name, ".csv.gz"); }

// The run's CC3DML: the first Simulation/*.xml (by name) that has <Dimensions>.
std::optional<Cc3dSimulation> find_simulation(const fs::path& run, std::vector<std::string>& warnings) {
  const fs::path folder = run / "Simulation";
  std::vector<std::string> xmls;
  std::error_code ec;
  if (fs::is_directory(folder, ec))
    for (const auto& entry : fs::directory_iterator(folder))
      if (entry.is_regular_file() && entry.path().extension() == ".xml")
        xmls.push_back(entry.path().string());
  std::sort(xmls.begin(), xmls.end());
  for (const std::string& xml : xmls) {
    try {
      return read_cc3d_xml(xml);
    } catch (const NotASimulation& e) {
      warnings.push_back(std::string("skipping ") + e.what());
    }
  }
  warnings.push_back("no CC3DML file with <Dimensions> in " + folder.string() +
                     ": lattice size and boundary conditions unknown (assumed non-periodic)");
  return std::nullopt;
}

// The LatticeData snapshots by name. One that cannot be read (a dangling link, a FIFO, a folder, no
// read permission) is an error naming it, or with skip_unreadable_frames a warning: a frame left out
// silently would join its neighbours by straight motion the cells never made.
std::vector<std::string> list_snapshots(const fs::path& folder, const RunOptions& options,
                                        std::vector<std::string>& warnings) {
  std::vector<std::string> vtks;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (!is_vtk_step_name(name))
      continue;
    std::error_code ec;
    std::string problem;
    if (!fs::exists(entry.path(), ec))
      problem = "is a symbolic link to nothing";
    else if (fs::is_directory(entry.path(), ec))
      problem = "is a folder";
    else if (!fs::is_regular_file(entry.path(), ec))
      problem = "is not a regular file (a FIFO, socket or device)";
    else if (::access(entry.path().c_str(), R_OK) != 0)
      problem = "cannot be read (permission denied)";
    if (problem.empty()) {
      vtks.push_back(entry.path().string());
      continue;
    }
    if (!options.skip_unreadable_frames)
      throw InputError(entry.path().string() + ": snapshot " + problem + " (rerun with " +
                       options.spellings.skip_unreadable_frames + " to leave it out)");
    warnings.push_back(entry.path().string() + ": snapshot " + problem + "; left out");
  }
  return vtks;
}

// A snapshot missing from the middle of an evenly saved series (MCS gaps that are multiples of the
// usual step) is an error, or with skip_unreadable_frames a warning.
void check_series(const std::vector<std::pair<std::int64_t, std::string>>& by_mcs, const RunOptions& options,
                  std::vector<std::string>& warnings) {
  std::vector<std::int64_t> mcs;
  for (const auto& snapshot : by_mcs)
    mcs.push_back(snapshot.first);
  for (const internal::SeriesGap& g : internal::series_gaps(mcs)) {
    const std::size_t k = g.k;
    const std::int64_t step = g.step;
    const std::string what =
        "the snapshot of MCS " + std::to_string(by_mcs[k - 1].first + step) +
        " is missing: the series goes from " + fs::path(by_mcs[k - 1].second).filename().string() + " to " +
        fs::path(by_mcs[k].second).filename().string() + ", every " + std::to_string(step) + " MCS elsewhere";
    if (!options.skip_unreadable_frames)
      throw InputError(fs::path(by_mcs[k].second).parent_path().string() + ": " + what + " (rerun with " +
                       options.spellings.skip_unreadable_frames + " to go on without it)");
    warnings.push_back(fs::path(by_mcs[k].second).parent_path().string() + ": " + what);
  }
}

void check_periodic(const std::optional<Cc3dSimulation>& sim, const RunOptions& options, RunData& run,
                    const std::string& consequence) {
  if (!sim)
    return;
  const std::string axes = periodic_axes(*sim);
  if (axes.empty() || options.read_periodic)
    return;
  if (!options.allow_periodic_as_open)
    throw InputError(sim->path + ": the run is periodic along " + axes +
                     "; medusa needs open boundaries (rerun with " + options.spellings.periodic_as_open +
                     " to treat them as open)");
  run.warnings.push_back("periodic boundaries along " + axes + " (" + sim->path +
                         ") treated as open: " + consequence);
}

const char* const as_open_consequence =
    "each cell is followed across the boundaries (docs/MATH.md §8.2) but contacts across them are not seen";

// CC3D's centres lie on the lattice of its CC3DML: anything outside is a corrupt row (a typo, or a CSV of
// another run), which would read as a cell jumping there and back. Along a periodic axis they lie in
// [0, L] (L itself after rounding), L the same point as 0, and are wrapped into [0, L) (docs/MATH.md §8.1).
void place_csv_centres(std::vector<CellSample>& samples, const Cc3dSimulation& simulation,
                       const PeriodicDomain& domain, std::int64_t scale, const std::string& path,
                       const CsvColumns& columns) {
  const std::string* names[3] = {&columns.x, &columns.y, &columns.z};
  for (CellSample& s : samples)
    for (std::size_t a = 0; a < 3; ++a) {
      const bool periodic = domain.periodic[a];
      const std::int64_t x = s.position[a], lo = periodic ? domain.origin[a] : 0;
      const std::int64_t hi = periodic ? lo + domain.period[a] : simulation.dimensions[a] * scale;
      if (x < lo || x > hi)
        throw InputError(path + ":" + std::to_string(s.line) + ": MCS " + std::to_string(s.mcs) + ", cell " +
                         std::to_string(s.cell_id) + ": " + *names[a] + " " + grid_coordinate_text(x, scale) +
                         " lies outside [0, " +
                         std::to_string(periodic ? domain.lattice[a] : simulation.dimensions[a]) + "], the " +
                         (periodic ? "periodic " : "") + "lattice along " + char('x' + a) + " of " +
                         simulation.path);
      if (periodic)
        s.position[a] = wrap_coordinate(x, lo, domain.period[a]);
    }
}

void name_types(RunData& run, const std::vector<std::string>& from_source) {
  std::vector<std::string>& names = run.trajectories.type_names;
  names = from_source;
  if (run.simulation) {
    const std::vector<std::string>& xml = run.simulation->type_names;
    if (names.size() < xml.size())
      names.resize(xml.size());
    for (std::size_t t = 0; t < xml.size(); ++t)
      if (names[t].empty())
        names[t] = xml[t];
  }
}

void take_assembly(RunData& run, AssembledRun&& assembled) {
  run.trajectories = std::move(assembled.trajectories);
  run.volumes = std::move(assembled.volumes);
  run.warnings.insert(run.warnings.end(), assembled.warnings.begin(), assembled.warnings.end());
}

std::string grid_name(std::int64_t scale) {
  int digits = 0;
  std::int64_t power = 1;
  while (power < scale && power <= std::numeric_limits<std::int64_t>::max() / 10) {
    power *= 10;
    ++digits;
  }
  return power == scale ? "10^-" + std::to_string(digits) : "1/" + std::to_string(scale);
}

// One line on what policy R did (docs/MATH.md §1.2, §1.3): the user's results are exact for the moved
// positions, which differ from the read ones by at most half a grid unit per coordinate.
std::string policy_r_note(const SnapReport& report, std::int64_t scale, const std::string& what,
                          const std::string& moved, const std::string& reference) {
  const double grid_units = report.max_displacement();
  char figures[160];
  std::snprintf(figures, sizeof figures,
                ": %lld of %lld positions moved, the largest by %.2g grid units (%.2g lattice units); ",
                static_cast<long long>(report.moved), static_cast<long long>(report.positions), grid_units,
                grid_units / static_cast<double>(scale));
  return what + " to the " + grid_name(scale) + " grid" + figures + "exact results are for the " + moved +
         " positions (" + reference + ")";
}

std::string snap_note(const SnapReport& report, std::int64_t scale) {
  return policy_r_note(report, scale, "VTK centroids snapped", "snapped",
                       "docs/MATH.md §1.3; --exact-vtk refuses off-grid centroids instead");
}

std::string rounding_note(const SnapReport& report, std::int64_t scale) {
  return policy_r_note(report, scale, "CSV centres rounded", "rounded",
                       "docs/MATH.md §1.2; without --round-csv they are refused");
}

// A series that stops at least one frame spacing before the simulation's last MCS is missing its later
// frames (a run still going, files not copied): said, since the analysis then covers less of the run.
void warn_if_cut_short(RunData& run, const std::optional<Cc3dSimulation>& simulation) {
  const std::vector<std::int64_t>& times = run.trajectories.frame_times;
  if (!simulation || simulation->steps <= 0 || times.size() < 2)
    return;
  const std::int64_t last = times.back(), spacing = last - times[times.size() - 2];
  const std::int64_t end = simulation->steps - 1;
  if (end - last >= spacing)
    run.warnings.push_back((run.sources.empty() ? std::string("input") : run.sources.back()) +
                           ": the last frame read is MCS " + std::to_string(last) + ", but " +
                           simulation->path + " runs to MCS " + std::to_string(end) + " (<Steps>" +
                           std::to_string(simulation->steps) + "</Steps>) with frames every " +
                           std::to_string(spacing) +
                           " MCS: its later frames are missing (a run still going, or files not copied), "
                           "and the analysis covers MCS " +
                           std::to_string(times.front()) + " to " + std::to_string(last) + " only");
}

// A user pointing at the snapshots' own folder instead of the run's (`run/LatticeData/` for `run/`):
// the folder to give instead, or nothing.
std::optional<fs::path> run_folder_of_lattice_data(const fs::path& p) {
  std::error_code ec;
  fs::path normal = fs::absolute(p, ec).lexically_normal();
  if (normal.filename().empty())
    normal = normal.parent_path();
  if (normal.filename() != "LatticeData")
    return std::nullopt;
  return normal.parent_path();
}

} // namespace

RunData read_vtk_run(const std::vector<std::string>& files, const RunOptions& options,
                     const std::optional<Cc3dSimulation>& simulation) {
  RunData run;
  run.used = RunSource::vtk;
  run.simulation = simulation;
  run.position_convention = "vtk-centroids-voxel-corner";
  run.snap.snapped = options.snap;
  check_periodic(simulation, options, run, as_open_consequence);
  std::array<bool, 3> periodic{};
  if (simulation)
    periodic = simulation->periodic;
  if (files.empty())
    throw InputError("no VTK snapshots to read");
  std::vector<std::pair<std::int64_t, std::string>> by_mcs;
  for (const std::string& f : files)
    by_mcs.emplace_back(vtk_step_mcs(f), f);
  std::sort(by_mcs.begin(), by_mcs.end());
  for (std::size_t k = 1; k < by_mcs.size(); ++k)
    if (by_mcs[k].first == by_mcs[k - 1].first)
      throw InputError(by_mcs[k].second + ": same MCS " + std::to_string(by_mcs[k].first) + " as " +
                       by_mcs[k - 1].second);
  check_series(by_mcs, options, run.warnings);

  std::vector<CellSample> samples;
  std::vector<std::int64_t> frame_times;
  std::array<std::int64_t, 3> dims{};
  for (std::size_t k = 0; k < by_mcs.size(); ++k) {
    const auto& [mcs, file] = by_mcs[k];
    VtkSnapshot snap;
    try {
      snap = read_vtk_snapshot(file, options.scale, periodic);
    } catch (const InputError& e) {
      // A snapshot cut short or corrupt (a copy interrupted, a disk full) is unreadable like a
      // missing one: left out with a warning when asked, named otherwise.
      if (!options.skip_unreadable_frames)
        throw InputError(std::string(e.what()) + " (rerun with " + options.spellings.skip_unreadable_frames +
                         " to leave this snapshot out)");
      run.warnings.push_back(std::string(e.what()) + "; snapshot left out");
      continue;
    }
    const std::size_t source = run.sources.size();
    if (source == 0) {
      dims = snap.dimensions;
      if (simulation)
        run.domain = periodic_domain(*simulation, snap.origin, snap.spacing);
      if (simulation && simulation->dimensions != dims)
        throw InputError(file + ": DIMENSIONS " + std::to_string(dims[0]) + " " + std::to_string(dims[1]) +
                         " " + std::to_string(dims[2]) + " differ from the lattice of " + simulation->path);
    } else if (snap.dimensions != dims) {
      throw InputError(file + ": DIMENSIONS differ from those of " + run.sources.front());
    }
    run.sources.push_back(file);
    frame_times.push_back(mcs);
    if (snap.cells.empty())
      run.warnings.push_back(file + ": no cells (all medium)");
    for (const VtkCell& c : snap.cells) {
      CellSample s;
      s.mcs = mcs;
      s.cell_id = c.id;
      s.type = c.type;
      s.volume = c.voxels;
      s.source = source;
      ++run.snap.positions;
      if (centroid_on_grid(c.scaled_sum, c.voxels)) {
        for (int a = 0; a < 3; ++a)
          s.position[a] = c.scaled_sum[a] / c.voxels;
      } else if (options.snap) {
        s.position = snap_centroid(c.scaled_sum, c.voxels, run.snap);
      } else {
        throw InputError(file + ": cell " + std::to_string(c.id) + ": its voxel centroid (" +
                         std::to_string(c.voxels) + " voxels) is not on the grid of scale " +
                         std::to_string(options.scale) + " and exact VTK positions were asked for (" +
                         options.spellings.exact_vtk +
                         "); without it centroids are "
                         "snapped to the nearest grid point (docs/MATH.md §1.3)");
      }
      samples.push_back(s);
    }
  }
  if (run.sources.empty())
    throw InputError(by_mcs.front().second + ": no snapshot of the run could be read");
  const std::int64_t z_extent = options.z_extent.value_or(dims[2]);
  if (z_extent != dims[2])
    throw InputError(run.sources.front() + ": z extent " + std::to_string(dims[2]) + " but the caller says " +
                     std::to_string(z_extent));
  take_assembly(run, assemble_trajectories(std::move(samples), run.sources, options.scale,
                                           dims[2] == 1 ? 2 : 3, frame_times));
  unwrap_trajectories(run.trajectories, run.domain, run.sources);
  name_types(run, {});
  warn_if_cut_short(run, simulation);
  if (run.snap.moved > 0)
    run.notes.push_back(snap_note(run.snap, options.scale));
  run.trajectories.validate();
  return run;
}

RunData read_csv_run(const std::string& path, const RunOptions& options,
                     const std::optional<Cc3dSimulation>& simulation) {
  RunData run;
  run.used = RunSource::csv;
  run.simulation = simulation;
  run.position_convention = "csv-centres";
  check_periodic(simulation, options, run, as_open_consequence);
  CsvContents csv = read_csv(
      path, CsvOptions{options.csv_columns, options.scale, options.round_csv, options.spellings.round_csv});
  run.sources.push_back(path);
  internal::check_csv_frames(csv.samples, path, options, run.warnings);
  run.snap = csv.rounding;
  if (options.round_csv)
    run.notes.push_back(rounding_note(run.snap, options.scale));
  if (simulation) {
    run.domain = periodic_domain(*simulation, {0, 0, 0}, {options.scale, options.scale, options.scale});
    place_csv_centres(csv.samples, *simulation, run.domain, options.scale, path, options.csv_columns);
  }

  std::optional<std::int64_t> z_extent = options.z_extent;
  if (!z_extent && simulation)
    z_extent = simulation->dimensions[2];
  const CellSample& first = csv.samples.front();
  const auto differing = std::find_if(csv.samples.begin(), csv.samples.end(), [&](const CellSample& s) {
    return s.position[2] != first.position[2];
  });
  int dimension = 3;
  if (z_extent && *z_extent == 1) {
    if (differing != csv.samples.end())
      throw InputError(
          path + ":" + std::to_string(differing->line) + ": MCS " + std::to_string(differing->mcs) +
          ", cell " + std::to_string(differing->cell_id) + ": " + options.csv_columns.z + " " +
          grid_coordinate_text(differing->position[2], options.scale) + " differs from " +
          grid_coordinate_text(first.position[2], options.scale) + " at line " + std::to_string(first.line) +
          ", but the lattice's z extent is 1: a planar run has one z on every row");
    dimension = 2;
  } else if (differing == csv.samples.end()) {
    // Every centre in one plane z = const is a planar run whatever the lattice says (a 3D alpha
    // complex of coplanar points has no tetrahedra, docs/MATH.md §5.7): run it in 2D, and say so.
    dimension = 2;
    run.warnings.push_back(path + ": every z is equal but the lattice z extent is " +
                           (z_extent ? std::to_string(*z_extent) : std::string("unknown")) +
                           "; read as a planar (2D) run");
  }
  take_assembly(run, assemble_trajectories(std::move(csv.samples), run.sources, options.scale, dimension));
  unwrap_trajectories(run.trajectories, run.domain, run.sources);
  name_types(run, csv.type_names);
  warn_if_cut_short(run, simulation);
  run.trajectories.validate();
  return run;
}

RunData read_run(const std::string& path, const RunOptions& options) {
  const fs::path p(path);
  std::error_code ec;
  std::vector<std::string> warnings;
  RunData run;
  if (fs::is_regular_file(p, ec)) {
    if (!is_csv_name(p.filename().string()))
      throw InputError(path + ": expected a CC3D output folder or a .csv/.csv.gz file of cell centres" +
                       (p.parent_path().filename() == "LatticeData"
                            ? "; for the run's snapshots give the folder that holds LatticeData/ (" +
                                  p.parent_path().parent_path().string() + ")"
                            : std::string()));
    if (options.source == RunSource::vtk)
      throw InputError(path + ": VTK snapshots requested but the input is a CSV file");
    std::optional<Cc3dSimulation> sim;
    if (fs::is_directory(p.parent_path() / "Simulation", ec))
      sim = find_simulation(p.parent_path(), warnings);
    run = read_csv_run(path, options, sim);
  } else if (fs::is_directory(p, ec)) {
    const std::optional<Cc3dSimulation> sim = find_simulation(p, warnings);
    std::vector<std::string> vtks;
    if (fs::is_directory(p / "LatticeData", ec))
      vtks = list_snapshots(p / "LatticeData", options, warnings);
    std::string csv;
    for (const char* name : {"cells.csv.gz", "cells.csv"})
      if (csv.empty() && fs::is_regular_file(p / name, ec))
        csv = (p / name).string();
    const bool use_vtk =
        options.source == RunSource::vtk || (options.source == RunSource::automatic && !vtks.empty());
    if (use_vtk) {
      if (vtks.empty())
        throw InputError(path + ": no LatticeData/Step_<MCS>.vtk(.gz) snapshots");
      run = read_vtk_run(vtks, options, sim);
    } else {
      if (csv.empty()) {
        const std::optional<fs::path> run_folder = run_folder_of_lattice_data(p);
        throw InputError(
            path +
            (options.source == RunSource::csv
                 ? ": no cells.csv.gz or cells.csv"
                 : ": neither LatticeData/Step_<MCS>.vtk(.gz) snapshots nor cells.csv(.gz)") +
            (run_folder ? "; this is a LatticeData folder: give the CC3D output folder that holds it (" +
                              run_folder->string() + ")"
                        : std::string()));
      }
      run = read_csv_run(csv, options, sim);
    }
  } else {
    throw InputError(path + ": no such file or folder");
  }
  run.warnings.insert(run.warnings.begin(), warnings.begin(), warnings.end());
  // Not an error (a frame's complex is still a complex), but no sorting can show in it.
  if (run.trajectories.frames() == 1)
    run.warnings.push_back(path + " has one frame (MCS " +
                           std::to_string(run.trajectories.frame_times.front()) +
                           "): no cell moves, so nothing joins or fills; the diagrams are those of that "
                           "frame's complex");
  return run;
}

} // namespace medusa::io
