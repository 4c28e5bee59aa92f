// Reader of CompuCell3D lattice snapshots: legacy VTK STRUCTURED_POINTS with FIELD point data
// CellType / CellId (/ ClusterId), ASCII or BINARY (big-endian), plain or gzip (docs/MATH.md §1.3).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace medusa::io {

// One cell of a snapshot: all voxels with its id, wherever they are (split cells included).
struct VtkCell {
  std::int64_t id = 0;
  int type = 0;
  std::int64_t voxels = 0; // n = volume
  // X = sum over the voxels of S * (origin + spacing * (i, j, k)): the exact centroid is X / n in grid
  // units. Convention "voxel corner index": voxel (i,j,k) sits at origin + spacing * (i,j,k), the
  // coordinates CompuCell3D's CenterOfMass plugin uses (docs/MATH.md §1.3).
  std::array<std::int64_t, 3> scaled_sum{};
};

struct VtkSnapshot {
  std::string path;
  std::array<std::int64_t, 3> dimensions{}; // nx, ny, nz
  std::array<std::int64_t, 3> origin{};     // S * origin (grid integers)
  std::array<std::int64_t, 3> spacing{};    // S * spacing (grid integers)
  bool binary = false;
  std::vector<VtkCell> cells; // sorted by id; medium (id 0) excluded
};

// Reads one snapshot; `scale` is the grid scale S. Throws InputError naming the file (and cell or
// line) for an unreadable/truncated file, a header that is not STRUCTURED_POINTS, POINT_DATA that does
// not match DIMENSIONS, a missing CellType/CellId array, too few values, a bad token, a cell whose
// voxels carry different types, or medium/cell id inconsistencies. Along the `periodic` axes a cell's
// centroid is its periodic mean, in [origin, origin + period) (docs/MATH.md §8.1).
VtkSnapshot read_vtk_snapshot(const std::string& path, std::int64_t scale,
                              const std::array<bool, 3>& periodic = {});

// The MCS in a CompuCell3D snapshot name "Step_<MCS>.vtk" or "Step_<MCS>.vtk.gz" (integer between the
// last '_' and ".vtk"). Throws InputError for any other name.
std::int64_t vtk_step_mcs(const std::string& path);

// True if the file name has the form Step_<digits>.vtk or Step_<digits>.vtk.gz.
bool is_vtk_step_name(const std::string& filename);

} // namespace medusa::io
