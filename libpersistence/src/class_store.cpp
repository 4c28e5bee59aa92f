#include "class_store.h"

#include "medusa/core/error.h"
#include "medusa/medusa/internal/hdf5_attributes.h"
#include "medusa/medusa/internal/hdf5_column.h"
#include "medusa/medusa/internal/hdf5_errors.h"
#include "medusa/medusa/internal/hdf5_handle.h"
#include "medusa/medusa/internal/hdf5_read.h"
#include "medusa/persistence/class_store.h"

#include <algorithm>
#include <cstdint>
#include <utility>

namespace medusa::persistence {
namespace {

constexpr const char* classes_name = "classes";
constexpr std::int64_t classes_format_version = 1;

using h5::Handle;

void check(bool ok, const std::string& path, const std::string& what) {
  if (!ok)
    h5::fail(path, what);
}

// Offsets and concatenated values of a list of lists. Reserved exactly: the representatives of a
// million-cell run are about a gigabyte, and a doubling vector would hold up to twice that.
std::vector<std::vector<medusa::CellId>> unflatten(const std::vector<std::uint64_t>& offsets,
                                                   const std::vector<std::uint64_t>& values, std::size_t rows,
                                                   const std::string& path, const std::string& what) {
  check(offsets.size() == rows + 1 && offsets.front() == 0 && offsets.back() == values.size() &&
            std::is_sorted(offsets.begin(), offsets.end()),
        path, what + " offsets do not match its rows and values");
  std::vector<std::vector<medusa::CellId>> lists(rows);
  for (std::size_t i = 0; i < rows; ++i)
    lists[i].assign(values.begin() + static_cast<std::ptrdiff_t>(offsets[i]),
                    values.begin() + static_cast<std::ptrdiff_t>(offsets[i + 1]));
  return lists;
}

} // namespace

namespace detail {

void write_classes(hid_t parent, const ClassRepresentatives& classes, std::size_t points,
                   const std::string& path) {
  check(classes.cycles.size() == classes.rows.size() && classes.clusters.size() == classes.rows.size() &&
            std::is_sorted(classes.rows.begin(), classes.rows.end()) &&
            (classes.rows.empty() || classes.rows.back() < points),
        path, "class representatives do not match their diagram");
  Handle group = h5::create_group(parent, classes_name, path);
  h5::write_attribute(group.get(), "format_version", classes_format_version, path);
  h5::write_attribute(group.get(), "max_dimension", std::int64_t{classes.options.max_dim}, path);
  h5::write_attribute(group.get(), "zero_length", std::int64_t{classes.options.zero_length ? 1 : 0}, path);
  h5::write_attribute(group.get(), "shortened", std::int64_t{classes.options.shorten ? 1 : 0}, path);
  h5::write_column(group.get(), "row", std::vector<std::uint64_t>(classes.rows.begin(), classes.rows.end()),
                   path);
  // The chains go to the store a chunk at a time: gathered into one array first, they would be held
  // twice beside the largest diagram.
  h5::write_list_columns<std::uint64_t>(group.get(), "cycle_offset", "cycle", classes.cycles, path);
  h5::write_list_columns<std::uint64_t>(group.get(), "cluster_offset", "cluster", classes.clusters, path);
  check(group.reset(), path, "cannot close group classes");
}

} // namespace detail

std::optional<ClassRepresentatives> read_classes(const std::string& store_path,
                                                 const std::string& diagram_name) {
  const h5::Quiet quiet;
  Handle file = h5::file_handle(H5Fopen(store_path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  check(file.valid(), store_path, "cannot open as HDF5");
  const std::string where = "/persistence/" + diagram_name;
  if (H5Lexists(file.get(), "persistence", H5P_DEFAULT) <= 0 ||
      H5Lexists(file.get(), where.c_str(), H5P_DEFAULT) <= 0)
    return std::nullopt;
  Handle diagram = h5::group_handle(H5Gopen2(file.get(), where.c_str(), H5P_DEFAULT));
  check(diagram.valid(), store_path, "cannot open group " + where);
  if (H5Lexists(diagram.get(), classes_name, H5P_DEFAULT) <= 0)
    return std::nullopt;
  const std::string at = where + "/" + classes_name;
  Handle group = h5::group_handle(H5Gopen2(diagram.get(), classes_name, H5P_DEFAULT));
  check(group.valid(), store_path, "cannot open group " + at);
  const std::int64_t version = h5::read_int_attribute(group.get(), "format_version", store_path);
  check(version == classes_format_version, store_path,
        at + " has format version " + std::to_string(version) + ", expected " +
            std::to_string(classes_format_version));
  // The diagram's length bounds the rows.
  Handle birth = h5::dataset_handle(H5Dopen2(diagram.get(), "birth", H5P_DEFAULT));
  Handle space = h5::space_handle(H5Dget_space(birth.get()));
  hsize_t points = 0;
  check(birth.valid() && space.valid() && H5Sget_simple_extent_dims(space.get(), &points, nullptr) == 1,
        store_path, "dataset " + where + "/birth is not one-dimensional");

  ClassRepresentatives classes;
  classes.options.max_dim =
      static_cast<int>(h5::read_int_attribute(group.get(), "max_dimension", store_path));
  classes.options.zero_length = h5::read_int_attribute(group.get(), "zero_length", store_path) != 0;
  // Stores written before shortening existed hold the unshortened cycles and no attribute.
  classes.options.shorten = H5Aexists(group.get(), "shortened") > 0 &&
                            h5::read_int_attribute(group.get(), "shortened", store_path) != 0;
  const auto rows = h5::read_column<std::uint64_t>(group.get(), at.substr(1), "row", store_path);
  for (std::size_t i = 0; i < rows.size(); ++i)
    check(rows[i] < points && (i == 0 || rows[i - 1] < rows[i]), store_path,
          at + "/row " + std::to_string(i) + " is outside the diagram or out of order");
  classes.rows.assign(rows.begin(), rows.end());
  classes.cycles =
      unflatten(h5::read_column<std::uint64_t>(group.get(), at.substr(1), "cycle_offset", store_path),
                h5::read_column<std::uint64_t>(group.get(), at.substr(1), "cycle", store_path), rows.size(),
                store_path, at + "/cycle");
  classes.clusters =
      unflatten(h5::read_column<std::uint64_t>(group.get(), at.substr(1), "cluster_offset", store_path),
                h5::read_column<std::uint64_t>(group.get(), at.substr(1), "cluster", store_path), rows.size(),
                store_path, at + "/cluster");
  return classes;
}

} // namespace medusa::persistence
