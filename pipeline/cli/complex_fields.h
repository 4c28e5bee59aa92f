// What both VTK forms of a K_t export write (complex_export.h): the points, the cells as point indices, and
// their data, gathered once so that the legacy and the XML writer only format them.
#pragma once

#include "complex_export.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace medusa::cli {

struct ComplexFields {
  // Points: the vertices of the exported cells in increasing vertex id, numbered from 0.
  std::vector<std::array<double, 3>> points;
  std::vector<std::int64_t> point_cell_id; // CompuCell3D cell id
  std::vector<int> point_type;             // CompuCell3D cell type
  std::vector<std::int64_t> point_class;   // class id or -1 (empty without marks)
  // On a periodic run: 1 for a copy of a cell drawn beyond a seam, as a vertex of a simplex that
  // crosses it, 0 for the cells in the lattice (empty on an open run).
  std::vector<int> point_beyond_seam;
  std::vector<std::vector<std::size_t>> cell_points;
  std::vector<int> cell_dimension;
  std::vector<int> cell_type;           // the common type of the cell's vertices, or 0 when they differ
  std::vector<std::int64_t> cell_class; // class id or -1 (empty without marks)
  std::vector<int> vtk_type;            // VTK_VERTEX, VTK_LINE, VTK_TRIANGLE or VTK_TETRA
};

// On a periodic run `positions` are wrapped into the lattice; a simplex whose vertices lie on both
// sides of a seam is drawn whole, at the lift where its cell of smallest CompuCell3D id lies in the
// lattice: its other vertices are then copies of their cells beyond the seam, extra points
// (docs/FORMAT.md, `medusa at`). InternalError when a vertex has no position or a cell is above
// dimension 3.
ComplexFields complex_fields(const medusa::Medusa& medusa, const std::vector<medusa::CellId>& cells,
                             const std::vector<std::optional<std::array<double, 3>>>& positions,
                             const ClassMarks* marks);

// 1 where a class id is set, 0 where it is -1 (the "in_class" arrays).
std::vector<int> membership(const std::vector<std::int64_t>& class_ids);

// A coordinate as both forms print it (%.9g: the lattice's grid is far coarser).
std::string vtk_number(double x);

} // namespace medusa::cli
