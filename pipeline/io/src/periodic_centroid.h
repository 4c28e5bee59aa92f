// Voxel centroids of cells on a periodic lattice: the periodic mean (docs/MATH.md §8.1).
#pragma once

#include "medusa/io/vtk_reader.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace medusa::io {

// Replaces, along every periodic axis, each cell's scaled_sum by that of its voxels unwrapped to the
// minimum image relative to the cell's first voxel (in file order), then reduced modulo the period so
// that the centroid lies in [origin, origin + period). `ids` is the CellId of every voxel, x fastest.
// Throws InputError naming the file and cell when the unwrapped voxels of a cell span half the
// lattice length or more along a periodic axis: its periodic mean is not well defined.
void periodic_centroids(VtkSnapshot& snap, const std::vector<std::int64_t>& ids,
                        const std::array<bool, 3>& periodic, std::int64_t scale);

} // namespace medusa::io
