// Export of one time slice K_t of the alpha complex (docs/MATH.md §6.6): vertex positions interpolated along
// the piecewise-linear trajectories (docs/MATH.md §2.1), as legacy VTK or as a CSV list of simplices.
#pragma once

#include "medusa/medusa/medusa.h"

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <ostream>
#include <vector>

namespace medusa::cli {

// Physical position of every trajectory at time t (index = vertex id), linear between the frames
// around t (x = X / scale, docs/MATH.md §1.1); empty for trajectories absent on both frames of t's slab.
// Throws InputError when t is outside [t_0, t_end].
std::vector<std::optional<std::array<double, 3>>> positions_at_time(const kinetic::Trajectories& input,
                                                                    double t);

// Which exported cells and vertices belong to a persistence class's representative (docs/MATH.md §7.11):
// the class id (its row in the diagram, as `medusa classes` lists it) or -1 for context.
struct ClassMarks {
  std::vector<std::int64_t> cell_class;                   // one per entry of the exported cells
  std::map<kinetic::VertexId, std::int64_t> vertex_class; // vertices of a representative
};

// Legacy ASCII VTK UNSTRUCTURED_GRID: the vertices of `cells` as points, every cell as VTK_VERTEX,
// VTK_LINE, VTK_TRIANGLE or VTK_TETRA; CELL_DATA "cell_type" (the common CC3D type of its vertices, or
// 0 when they differ) and "dimension"; POINT_DATA "cell_id" and "cell_type". With `marks`, also
// "in_class" (1 or 0) and "class_id" (-1 for context) as cell and point data. InternalError when a
// vertex has no position.
void write_complex_vtk(std::ostream& out, const medusa::Medusa& medusa,
                       const std::vector<medusa::CellId>& cells,
                       const std::vector<std::optional<std::array<double, 3>>>& positions,
                       const std::string& title, const ClassMarks* marks = nullptr);

// The same as an XML VTK UnstructuredGrid (.vtu, ASCII), the format ParaView's .pvd collections read.
void write_complex_vtu(std::ostream& out, const medusa::Medusa& medusa,
                       const std::vector<medusa::CellId>& cells,
                       const std::vector<std::optional<std::array<double, 3>>>& positions,
                       const ClassMarks* marks = nullptr);

// CSV `dimension,v0,v1,v2,v3`: one simplex per row, its vertices as CC3D cell ids in increasing order
// (trailing fields empty), rows sorted by dimension then ids.
void write_complex_csv(std::ostream& out, const medusa::Medusa& medusa,
                       const std::vector<medusa::CellId>& cells);

} // namespace medusa::cli
