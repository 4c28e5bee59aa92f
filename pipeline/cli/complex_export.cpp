#include "complex_export.h"

#include "complex_fields.h"

#include "medusa/core/error.h"

#include <algorithm>
#include <string>

namespace medusa::cli {
namespace {

template <class Values>
void scalars(std::ostream& out, const char* name, const char* type, const Values& values) {
  out << "SCALARS " << name << ' ' << type << " 1\nLOOKUP_TABLE default\n";
  for (const auto& v : values)
    out << v << '\n';
}

} // namespace

std::vector<std::optional<std::array<double, 3>>> positions_at_time(const kinetic::Trajectories& input,
                                                                    double t) {
  const std::vector<std::int64_t>& times = input.frame_times;
  if (times.empty() || !(t >= static_cast<double>(times.front()) && t <= static_cast<double>(times.back())))
    throw InputError("time " + vtk_number(t) + " is outside the run (MCS " +
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
  const ComplexFields f = complex_fields(medusa, cells, positions, marks);
  std::size_t size = 0;
  for (const auto& points : f.cell_points)
    size += points.size() + 1;

  out << "# vtk DataFile Version 3.0\n" << title << "\nASCII\nDATASET UNSTRUCTURED_GRID\n";
  out << "POINTS " << f.points.size() << " double\n";
  for (const std::array<double, 3>& x : f.points)
    out << vtk_number(x[0]) << ' ' << vtk_number(x[1]) << ' ' << vtk_number(x[2]) << '\n';
  out << "CELLS " << f.cell_points.size() << ' ' << size << '\n';
  for (const auto& points : f.cell_points) {
    out << points.size();
    for (std::size_t p : points)
      out << ' ' << p;
    out << '\n';
  }
  out << "CELL_TYPES " << f.vtk_type.size() << '\n';
  for (int t : f.vtk_type)
    out << t << '\n';
  out << "CELL_DATA " << f.cell_points.size() << '\n';
  scalars(out, "cell_type", "int", f.cell_type);
  scalars(out, "dimension", "int", f.cell_dimension);
  if (marks != nullptr) {
    scalars(out, "in_class", "int", membership(f.cell_class));
    scalars(out, "class_id", "long", f.cell_class);
  }
  out << "POINT_DATA " << f.points.size() << '\n';
  scalars(out, "cell_id", "long", f.point_cell_id);
  scalars(out, "cell_type", "int", f.point_type);
  if (marks != nullptr) {
    scalars(out, "in_class", "int", membership(f.point_class));
    scalars(out, "class_id", "long", f.point_class);
  }
  if (!f.point_beyond_seam.empty())
    scalars(out, "beyond_seam", "int", f.point_beyond_seam);
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
