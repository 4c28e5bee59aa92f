// Cell volumes for `--radius auto`: the equivalent-sphere radius of the median cell volume.
#pragma once

#include <cstdint>
#include <vector>

namespace medusa::io {

// volumes[i][f]: volume (voxels) of trajectory i at its f-th frame (the layout of RunData::volumes).
using CellVolumes = std::vector<std::vector<std::int64_t>>;

// Median over every (cell, frame) volume; the mean of the two middle values for an even count.
// Throws InputError if there are no volumes (e.g. a CSV without a volume column).
double median_cell_volume(const CellVolumes& volumes);

// Radius of the ball (3D: r = cbrt(3V / (4 pi))) or disc (2D: r = sqrt(V / pi)) of volume V, in
// lattice units. An approximation for choosing rho, never used in a geometric decision.
double equivalent_radius(double volume, int dimension);

} // namespace medusa::io
