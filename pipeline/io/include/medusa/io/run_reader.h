// Reading a whole CompuCell3D run (output folder or CSV file) into trajectories (docs/MATH.md §1, §2).
#pragma once

#include "medusa/io/cc3d_xml.h"
#include "medusa/io/cell_volumes.h"
#include "medusa/io/centroid.h"
#include "medusa/io/csv_reader.h"
#include "medusa/io/periodic_domain.h"
#include "medusa/kinetic/trajectories.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace medusa::io {

enum class RunSource {
  automatic, // VTK snapshots if the folder has any, else cells.csv(.gz)
  vtk,       // LatticeData/Step_*.vtk(.gz): exact voxel centroids (docs/MATH.md §1.3)
  csv        // cells.csv(.gz): CC3D's centres rounded to 6 decimals (docs/MATH.md §1.2)
};

struct RunOptions {
  std::int64_t scale = 1000000; // grid scale S = 10^m (docs/MATH.md §1.1)
  RunSource source = RunSource::automatic;
  // VTK centroids off the grid are snapped to the nearest grid point (policy R, docs/MATH.md §1.3),
  // as CC3D's own centres in cells.csv are rounded; false refuses them (CLI: --exact-vtk).
  bool snap = true;
  // CSV centres with more decimals than the grid holds are rounded to it (policy R, docs/MATH.md
  // §1.2) and the rounding recorded in RunData::snap; false refuses them (CLI: --round-csv).
  bool round_csv = false;
  bool allow_periodic_as_open = false; // read a periodic run as if its boundaries were open
  // Read a periodic run as periodic (docs/MATH.md §8): no refusal and no warning; RunData::domain holds
  // its periodic axes for the caller to run it on the torus.
  bool read_periodic = false;
  // Leave out LatticeData snapshots that cannot be read, and go on past snapshots missing from the
  // series, with a warning each (CLI: --skip-unreadable-frames); otherwise each is an InputError.
  bool skip_unreadable_frames = false;
  CsvColumns csv_columns;
  // How the user turns on what a refusal points to: the command line's flags by default, medusa.run's
  // keyword arguments from Python.
  struct Spellings {
    std::string round_csv = "--round-csv";
    std::string exact_vtk = "--exact-vtk";
    std::string periodic_as_open = "--periodic-as-open";
    std::string skip_unreadable_frames = "--skip-unreadable-frames";
  } spellings;
  // Lattice z extent if the caller knows it; otherwise taken from Simulation/*.xml or the VTK header.
  // z extent 1 makes the run planar (dimension 2; z kept).
  std::optional<std::int64_t> z_extent;
};

struct RunData {
  kinetic::Trajectories trajectories;
  std::vector<std::string> warnings;
  // Facts about how the input was read that are not problems (e.g. the VTK centroids' snapping).
  std::vector<std::string> notes;
  CellVolumes volumes;              // volumes[i][f] of trajectory i at frame first_frame + f
  std::vector<std::string> sources; // files read, in order (VTK snapshots by MCS, or the CSV)
  RunSource used = RunSource::csv;  // vtk or csv
  SnapReport snap;                  // policy R bookkeeping (snapped: policy R was in force)
  // How positions were obtained, for output headers: "csv-centres" (CC3D's centres, 6 decimals) or
  // "vtk-centroids-voxel-corner" (exact voxel means, voxel (i,j,k) at origin + spacing*(i,j,k)).
  std::string position_convention;
  std::optional<Cc3dSimulation> simulation; // the run's CC3DML facts, when found
  // The lattice's periodic axes (none for an open run). Positions along them are unwrapped: continuous
  // between frames, each trajectory starting inside [origin, origin + period) (docs/MATH.md §8.2).
  PeriodicDomain domain;
};

// Reads a CC3D output folder (LatticeData/Step_*.vtk[.gz], Simulation/*.xml, cells.csv[.gz]) or a
// .csv/.csv.gz file (its folder's Simulation/*.xml is used when present). Throws InputError for a
// periodic run unless options.allow_periodic_as_open (then a warning is recorded and the positions are
// unwrapped, docs/MATH.md §8), for VTK centroids off the grid when !options.snap, and for every
// malformed input (naming file, line, cell).
RunData read_run(const std::string& path, const RunOptions& options = {});

// The pieces of read_run, for callers that already know their files.
RunData read_vtk_run(const std::vector<std::string>& files, const RunOptions& options,
                     const std::optional<Cc3dSimulation>& simulation = std::nullopt);
RunData read_csv_run(const std::string& path, const RunOptions& options,
                     const std::optional<Cc3dSimulation>& simulation = std::nullopt);

} // namespace medusa::io
