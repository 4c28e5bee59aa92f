#include "complex_fields.h"

#include "medusa/core/error.h"

#include <algorithm>
#include <cstdio>
#include <map>

namespace medusa::cli {
namespace {

int common_type(const kinetic::Trajectories& input, const medusa::Cell& c) {
  const int first = input.cells[static_cast<std::size_t>(c.vertices.front())].type;
  for (kinetic::VertexId v : c.vertices)
    if (input.cells[static_cast<std::size_t>(v)].type != first)
      return 0; // never a cell type: 0 is CompuCell3D's medium
  return first;
}

} // namespace

std::string vtk_number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", x);
  return buffer;
}

std::vector<int> membership(const std::vector<std::int64_t>& class_ids) {
  std::vector<int> in;
  for (std::int64_t c : class_ids)
    in.push_back(c >= 0 ? 1 : 0);
  return in;
}

ComplexFields complex_fields(const medusa::Medusa& medusa, const std::vector<medusa::CellId>& cells,
                             const std::vector<std::optional<std::array<double, 3>>>& positions,
                             const ClassMarks* marks) {
  const kinetic::Trajectories& input = medusa.input;
  std::map<kinetic::VertexId, std::size_t> point_of;
  for (medusa::CellId id : cells)
    for (kinetic::VertexId v : medusa.cell(id).vertices)
      point_of.emplace(v, 0);
  ComplexFields f;
  for (auto& [v, index] : point_of) {
    const auto i = static_cast<std::size_t>(v);
    if (i >= positions.size() || !positions[i])
      throw InternalError("medusa at: vertex " + std::to_string(v) + " (CC3D cell " +
                          std::to_string(input.cells.at(i).cell_id) +
                          ") is exported but has no position at that time");
    index = f.points.size();
    f.points.push_back(*positions[i]);
    f.point_cell_id.push_back(input.cells[i].cell_id);
    f.point_type.push_back(input.cells[i].type);
    if (marks != nullptr) {
      const auto it = marks->vertex_class.find(v);
      f.point_class.push_back(it == marks->vertex_class.end() ? -1 : it->second);
    }
  }
  // Periods in lattice units, 0 on open axes.
  std::array<double, 3> period{};
  bool periodic = false;
  for (std::size_t a = 0; a < 3; ++a)
    if (medusa.run.periodic_lengths[a] > 0) {
      period[a] = static_cast<double>(medusa.run.periodic_lengths[a]) / static_cast<double>(input.scale);
      periodic = true;
    }
  if (periodic)
    f.point_beyond_seam.assign(f.points.size(), 0);
  // Copies beyond a seam, by (vertex, whole periods added along each axis).
  std::map<std::pair<kinetic::VertexId, std::array<int, 3>>, std::size_t> copy_of;
  const auto point_for = [&](kinetic::VertexId v, kinetic::VertexId anchor) {
    std::array<int, 3> shift{};
    bool shifted = false;
    const std::array<double, 3>&x = f.points[point_of.at(v)], &o = f.points[point_of.at(anchor)];
    for (std::size_t a = 0; a < 3; ++a)
      if (period[a] > 0) {
        // Simplices are shorter than 2 rho < L/2 (docs/MATH.md §8.3): the nearest image is the one.
        const double d = x[a] - o[a];
        shift[a] = d > period[a] / 2 ? -1 : (d < -period[a] / 2 ? 1 : 0);
        shifted = shifted || shift[a] != 0;
      }
    if (!shifted)
      return point_of.at(v);
    auto [it, fresh] = copy_of.try_emplace({v, shift}, f.points.size());
    if (fresh) {
      const std::size_t from = point_of.at(v);
      std::array<double, 3> y = x;
      for (std::size_t a = 0; a < 3; ++a)
        y[a] += shift[a] * period[a];
      f.points.push_back(y);
      f.point_cell_id.push_back(f.point_cell_id[from]);
      f.point_type.push_back(f.point_type[from]);
      if (marks != nullptr)
        f.point_class.push_back(f.point_class[from]);
      f.point_beyond_seam.push_back(1);
    }
    return it->second;
  };
  constexpr int vtk_type[] = {1, 3, 5, 10};
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const medusa::Cell& c = medusa.cell(cells[i]);
    if (c.dim() < 0 || c.dim() > 3)
      throw InternalError("medusa at: cell " + std::to_string(cells[i]) + " of dimension " +
                          std::to_string(c.dim()) + " exported");
    const kinetic::VertexId anchor = *std::min_element(
        c.vertices.begin(), c.vertices.end(), [&](kinetic::VertexId a, kinetic::VertexId b) {
          return input.cells[static_cast<std::size_t>(a)].cell_id <
                 input.cells[static_cast<std::size_t>(b)].cell_id;
        });
    std::vector<std::size_t> indices;
    for (kinetic::VertexId v : c.vertices)
      indices.push_back(periodic ? point_for(v, anchor) : point_of.at(v));
    f.cell_points.push_back(std::move(indices));
    f.cell_dimension.push_back(c.dim());
    f.cell_type.push_back(common_type(input, c));
    f.vtk_type.push_back(vtk_type[c.dim()]);
    if (marks != nullptr)
      f.cell_class.push_back(marks->cell_class.at(i));
  }
  return f;
}

} // namespace medusa::cli
