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

// Writes lists as datasets <name>_offset and <name> of a classes group.
void write_lists(hid_t group, const std::string& name, const CellLists& lists, const std::string& path) {
  h5::write_column(group, name + "_offset", lists.offsets(), path);
  h5::SizedColumn<std::uint64_t> ids(group, name, lists.offsets().back(), path);
  lists.for_each_id([&](medusa::CellId id) { ids.push(id); });
  ids.finish();
}

// The lists `name` of classes group `at`, one per row (datasets <name>_offset and <name>).
CellLists read_lists(hid_t group, const std::string& at, const std::string& name, std::size_t rows,
                     const std::string& path) {
  CellLists lists = CellLists::from_offsets(
      h5::read_column<std::uint64_t>(group, at.substr(1), name + "_offset", path),
      h5::read_column<medusa::CellId>(group, at.substr(1), name, path), path, at + "/" + name);
  check(lists.size() == rows, path, at + "/" + name + " offsets do not match its rows and values");
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
  h5::write_column_of<std::uint64_t>(
      group.get(), "row", classes.rows.size(), [&](std::size_t i) { return classes.rows[i]; }, path);
  write_lists(group.get(), "cycle", classes.cycles, path);
  write_lists(group.get(), "cluster", classes.clusters, path);
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
  classes.cycles = read_lists(group.get(), at, "cycle", rows.size(), store_path);
  classes.clusters = read_lists(group.get(), at, "cluster", rows.size(), store_path);
  return classes;
}

} // namespace medusa::persistence
