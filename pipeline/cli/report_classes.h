// The classes section of `medusa report`: per cell type and degree the longest-lived classes of the
// forward diagram with the CompuCell3D cells of their representatives (docs/MATH.md §7.11), and the
// cells' positions at the frames for the page's 3D view.
#pragma once

#include "medusa/medusa/medusa.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <map>
#include <string>

namespace medusa::cli {

// {top, periodic_lengths, cells: {cc3d, type}, frames: {times, frame_count, positions}, sections: [...]}.
// periodic_lengths: per axis the period in lattice units, 0 for an axis that is not periodic.
// cells: per trajectory (index = vertex id) its CC3D id and type. frames: the positions (lattice units,
// to 1e-3) of every trajectory at each embedded frame as a flat [x, y, z, ...] with null for a
// trajectory absent there; every frame unless the run is large, then every k-th and the last.
// sections: per type (all cells first) and degree 0..2 {label, name, dim, total, classes}, the `top`
// classes in the order of `medusa classes --sort seen`, each {id, birth,
// death (null if essential), birth_kind, death_kind, ring (essential loops and cavities: {state, broke_at},
// ring_fate.h; null otherwise), birth_cells, death_cells, cells (CC3D ids as
// `medusa classes` lists them), vertices, edges, triangles, birth_simplex, death_simplex (vertex ids)}.
// The classes are those stored under /persistence (computed when the store has none).
// seen: filled with, per type (persistence::all_types for all cells) and birth cell of a class of
// positive length, the time it was seen in the tissue (time_seen, ring_fate.h).
using TimesSeen = std::map<int, std::map<medusa::CellId, double>>;
nlohmann::ordered_json report_classes(const std::string& store, const medusa::Medusa& medusa, std::size_t top,
                                      TimesSeen& seen);

} // namespace medusa::cli
