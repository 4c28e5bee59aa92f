// The XML form of a K_t export (complex_export.h): ParaView's .pvd collections read XML VTK files only.
#include "complex_export.h"
#include "complex_fields.h"

#include "medusa/core/error.h"

#include <string>

namespace medusa::cli {
namespace {

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
  const ComplexFields f = complex_fields(medusa, cells, positions, marks);
  std::vector<std::size_t> connectivity, offsets;
  for (const auto& points : f.cell_points) {
    connectivity.insert(connectivity.end(), points.begin(), points.end());
    offsets.push_back(connectivity.size());
  }

  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << " <UnstructuredGrid>\n  <Piece NumberOfPoints=\"" << f.points.size() << "\" NumberOfCells=\""
      << f.cell_points.size() << "\">\n";
  out << "   <PointData Scalars=\"cell_id\">\n";
  data_array(out, "Int64", "cell_id", f.point_cell_id);
  data_array(out, "Int32", "cell_type", f.point_type);
  if (marks != nullptr) {
    data_array(out, "Int32", "in_class", membership(f.point_class));
    data_array(out, "Int64", "class_id", f.point_class);
  }
  if (!f.point_beyond_seam.empty())
    data_array(out, "Int32", "beyond_seam", f.point_beyond_seam);
  out << "   </PointData>\n   <CellData Scalars=\"cell_type\">\n";
  data_array(out, "Int32", "cell_type", f.cell_type);
  data_array(out, "Int32", "dimension", f.cell_dimension);
  if (marks != nullptr) {
    data_array(out, "Int32", "in_class", membership(f.cell_class));
    data_array(out, "Int64", "class_id", f.cell_class);
  }
  out << "   </CellData>\n   <Points>\n"
      << "    <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const std::array<double, 3>& x : f.points)
    out << vtk_number(x[0]) << ' ' << vtk_number(x[1]) << ' ' << vtk_number(x[2]) << '\n';
  out << "    </DataArray>\n   </Points>\n   <Cells>\n";
  data_array(out, "Int64", "connectivity", connectivity);
  data_array(out, "Int64", "offsets", offsets);
  data_array(out, "UInt8", "types", f.vtk_type);
  out << "   </Cells>\n  </Piece>\n </UnstructuredGrid>\n</VTKFile>\n";
}

} // namespace medusa::cli
