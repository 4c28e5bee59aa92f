// The XML form of a K_t export (complex_export.h): ParaView's .pvd collections read XML VTK files only.
#include "complex_export.h"

#include "medusa/core/error.h"

#include <cstdio>
#include <string>

namespace medusa::cli {
namespace {

std::string number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", x);
  return buffer;
}

int common_type(const kinetic::Trajectories& input, const medusa::Cell& c) {
  const int first = input.cells[static_cast<std::size_t>(c.vertices.front())].type;
  for (kinetic::VertexId v : c.vertices)
    if (input.cells[static_cast<std::size_t>(v)].type != first)
      return 0;
  return first;
}

template <class Values>
void data_array(std::ostream& out, const char* type, const char* name, const Values& values) {
  out << "    <DataArray type=\"" << type << "\" Name=\"" << name << "\" format=\"ascii\">\n";
  for (const auto& v : values)
    out << v << '\n';
  out << "    </DataArray>\n";
}

} // namespace

void write_complex_vtu(std::ostream& out, const medusa::Medusa& medusa,
                       const std::vector<medusa::CellId>& cells,
                       const std::vector<std::optional<std::array<double, 3>>>& positions,
                       const ClassMarks* marks) {
  const kinetic::Trajectories& input = medusa.input;
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
                          ") is exported but has no position at that time");
  }
  std::vector<std::int64_t> cell_id, point_class, point_in;
  std::vector<int> point_type;
  for (const auto& [v, index] : point_of) {
    cell_id.push_back(input.cells[static_cast<std::size_t>(v)].cell_id);
    point_type.push_back(input.cells[static_cast<std::size_t>(v)].type);
    if (marks != nullptr) {
      const auto it = marks->vertex_class.find(v);
      point_class.push_back(it == marks->vertex_class.end() ? -1 : it->second);
      point_in.push_back(it == marks->vertex_class.end() ? 0 : 1);
    }
  }
  std::vector<std::size_t> connectivity, offsets;
  std::vector<int> vtk_types, cell_types, dims;
  std::vector<std::int64_t> cell_class, cell_in;
  // VTK_VERTEX, VTK_LINE, VTK_TRIANGLE, VTK_TETRA.
  constexpr int vtk_type[] = {1, 3, 5, 10};
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const medusa::Cell& c = medusa.cell(cells[i]);
    if (c.dim() < 0 || c.dim() > 3)
      throw InternalError("medusa at: cell " + std::to_string(cells[i]) + " of dimension " +
                          std::to_string(c.dim()) + " exported");
    for (kinetic::VertexId v : c.vertices)
      connectivity.push_back(point_of.at(v));
    offsets.push_back(connectivity.size());
    vtk_types.push_back(vtk_type[c.dim()]);
    cell_types.push_back(common_type(input, c));
    dims.push_back(c.dim());
    if (marks != nullptr) {
      cell_class.push_back(marks->cell_class.at(i));
      cell_in.push_back(marks->cell_class.at(i) >= 0 ? 1 : 0);
    }
  }

  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << " <UnstructuredGrid>\n  <Piece NumberOfPoints=\"" << point_of.size() << "\" NumberOfCells=\""
      << cells.size() << "\">\n";
  out << "   <PointData Scalars=\"cell_id\">\n";
  data_array(out, "Int64", "cell_id", cell_id);
  data_array(out, "Int32", "cell_type", point_type);
  if (marks != nullptr) {
    data_array(out, "Int32", "in_class", point_in);
    data_array(out, "Int64", "class_id", point_class);
  }
  out << "   </PointData>\n   <CellData Scalars=\"cell_type\">\n";
  data_array(out, "Int32", "cell_type", cell_types);
  data_array(out, "Int32", "dimension", dims);
  if (marks != nullptr) {
    data_array(out, "Int32", "in_class", cell_in);
    data_array(out, "Int64", "class_id", cell_class);
  }
  out << "   </CellData>\n   <Points>\n"
      << "    <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const auto& [v, index] : point_of) {
    const std::array<double, 3>& x = *positions[static_cast<std::size_t>(v)];
    out << number(x[0]) << ' ' << number(x[1]) << ' ' << number(x[2]) << '\n';
  }
  out << "    </DataArray>\n   </Points>\n   <Cells>\n";
  data_array(out, "Int64", "connectivity", connectivity);
  data_array(out, "Int64", "offsets", offsets);
  data_array(out, "UInt8", "types", vtk_types);
  out << "   </Cells>\n  </Piece>\n </UnstructuredGrid>\n</VTKFile>\n";
}

} // namespace medusa::cli
