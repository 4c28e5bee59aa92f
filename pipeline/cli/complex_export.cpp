#include "complex_export.h"

#include "medusa/core/error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

namespace medusa::cli {
namespace {

std::string coordinate(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", x);
  return buffer;
}

// The common type of a simplex's vertices, or 0 (never a cell type: 0 is CC3D's medium).
int common_type(const kinetic::Trajectories& input, const medusa::Cell& c) {
  const int first = input.cells[static_cast<std::size_t>(c.vertices.front())].type;
  for (kinetic::VertexId v : c.vertices)
    if (input.cells[static_cast<std::size_t>(v)].type != first)
      return 0;
  return first;
}

} // namespace

std::vector<std::optional<std::array<double, 3>>> positions_at_time(const kinetic::Trajectories& input,
                                                                    double t) {
  const std::vector<std::int64_t>& times = input.frame_times;
  if (times.empty() || !(t >= static_cast<double>(times.front()) && t <= static_cast<double>(times.back())))
    throw InputError("time " + coordinate(t) + " is outside the run (MCS " +
                     (times.empty() ? std::string("none")
                                    : std::to_string(times.front()) + " to " + std::to_string(times.back())) +
                     ")");
  // Slab k: t_k <= t <= t_{k+1}; a single-frame run has only frame 0.
  std::size_t k = 0;
  while (k + 2 < times.size() && static_cast<double>(times[k + 1]) <= t)
    ++k;
  const std::size_t next = std::min(k + 1, times.size() - 1);
  const double span = static_cast<double>(times[next] - times[k]);
  const double u = span > 0 ? (t - static_cast<double>(times[k])) / span : 0.0;
  const double scale = static_cast<double>(input.scale);

  std::vector<std::optional<std::array<double, 3>>> positions(input.cells.size());
  for (std::size_t v = 0; v < input.cells.size(); ++v) {
    const kinetic::Trajectory& c = input.cells[v];
    const bool here = c.present(k), there = c.present(next);
    if (!here && !there)
      continue;
    const kinetic::GridPoint& a = here ? c.at(k) : c.at(next);
    const kinetic::GridPoint& b = there ? c.at(next) : c.at(k);
    std::array<double, 3> x{};
    for (std::size_t i = 0; i < 3; ++i)
      x[i] = (static_cast<double>(a[i]) + u * static_cast<double>(b[i] - a[i])) / scale;
    positions[v] = x;
  }
  return positions;
}

void write_complex_vtk(std::ostream& out, const medusa::Medusa& medusa,
                       const std::vector<medusa::CellId>& cells,
                       const std::vector<std::optional<std::array<double, 3>>>& positions,
                       const std::string& title, const ClassMarks* marks) {
  const kinetic::Trajectories& input = medusa.input;
  // Points: the vertices of the complex in increasing vertex id, numbered from 0.
  std::map<kinetic::VertexId, std::size_t> point_of;
  for (medusa::CellId id : cells)
    for (kinetic::VertexId v : medusa.cell(id).vertices)
      point_of.emplace(v, 0);
  std::size_t next = 0;
  for (auto& [v, index] : point_of) {
    index = next++;
    if (static_cast<std::size_t>(v) >= positions.size() || !positions[static_cast<std::size_t>(v)])
      throw InternalError("medusa at: vertex " + std::to_string(v) + " (CC3D cell " +
                          std::to_string(input.cells.at(static_cast<std::size_t>(v)).cell_id) +
                          ") is in K_t but has no position at that time");
  }
  std::size_t size = 0;
  for (medusa::CellId id : cells)
    size += medusa.cell(id).vertices.size() + 1;

  out << "# vtk DataFile Version 3.0\n" << title << "\nASCII\nDATASET UNSTRUCTURED_GRID\n";
  out << "POINTS " << point_of.size() << " double\n";
  for (const auto& [v, index] : point_of) {
    const std::array<double, 3>& x = *positions[static_cast<std::size_t>(v)];
    out << coordinate(x[0]) << ' ' << coordinate(x[1]) << ' ' << coordinate(x[2]) << '\n';
  }
  out << "CELLS " << cells.size() << ' ' << size << '\n';
  for (medusa::CellId id : cells) {
    const medusa::Cell& c = medusa.cell(id);
    out << c.vertices.size();
    for (kinetic::VertexId v : c.vertices)
      out << ' ' << point_of.at(v);
    out << '\n';
  }
  // VTK_VERTEX, VTK_LINE, VTK_TRIANGLE, VTK_TETRA.
  constexpr int vtk_type[] = {1, 3, 5, 10};
  out << "CELL_TYPES " << cells.size() << '\n';
  for (medusa::CellId id : cells) {
    const int d = medusa.cell(id).dim();
    if (d < 0 || d > 3)
      throw InternalError("medusa at: cell " + std::to_string(id) + " of dimension " + std::to_string(d) +
                          " in K_t");
    out << vtk_type[d] << '\n';
  }
  out << "CELL_DATA " << cells.size() << "\nSCALARS cell_type int 1\nLOOKUP_TABLE default\n";
  for (medusa::CellId id : cells)
    out << common_type(input, medusa.cell(id)) << '\n';
  out << "SCALARS dimension int 1\nLOOKUP_TABLE default\n";
  for (medusa::CellId id : cells)
    out << medusa.cell(id).dim() << '\n';
  if (marks != nullptr) {
    out << "SCALARS in_class int 1\nLOOKUP_TABLE default\n";
    for (std::int64_t c : marks->cell_class)
      out << (c >= 0 ? 1 : 0) << '\n';
    out << "SCALARS class_id long 1\nLOOKUP_TABLE default\n";
    for (std::int64_t c : marks->cell_class)
      out << c << '\n';
  }
  out << "POINT_DATA " << point_of.size() << "\nSCALARS cell_id long 1\nLOOKUP_TABLE default\n";
  for (const auto& entry : point_of)
    out << input.cells[static_cast<std::size_t>(entry.first)].cell_id << '\n';
  out << "SCALARS cell_type int 1\nLOOKUP_TABLE default\n";
  for (const auto& entry : point_of)
    out << input.cells[static_cast<std::size_t>(entry.first)].type << '\n';
  if (marks != nullptr) {
    out << "SCALARS in_class int 1\nLOOKUP_TABLE default\n";
    for (const auto& entry : point_of)
      out << (marks->vertex_class.count(entry.first) != 0 ? 1 : 0) << '\n';
    out << "SCALARS class_id long 1\nLOOKUP_TABLE default\n";
    for (const auto& entry : point_of) {
      const auto it = marks->vertex_class.find(entry.first);
      out << (it == marks->vertex_class.end() ? -1 : it->second) << '\n';
    }
  }
}

void write_complex_csv(std::ostream& out, const medusa::Medusa& medusa,
                       const std::vector<medusa::CellId>& cells) {
  std::vector<std::vector<std::int64_t>> rows;
  rows.reserve(cells.size());
  for (medusa::CellId id : cells) {
    const medusa::Cell& c = medusa.cell(id);
    std::vector<std::int64_t> row{c.dim()};
    for (kinetic::VertexId v : c.vertices)
      row.push_back(medusa.input.cells.at(static_cast<std::size_t>(v)).cell_id);
    std::sort(row.begin() + 1, row.end());
    rows.push_back(std::move(row));
  }
  std::sort(rows.begin(), rows.end());
  out << "dimension,v0,v1,v2,v3\n";
  for (const std::vector<std::int64_t>& row : rows) {
    out << row.front();
    for (std::size_t i = 1; i < 5; ++i) {
      out << ',';
      if (i < row.size())
        out << row[i];
    }
    out << '\n';
  }
}

} // namespace medusa::cli
