#include "class_store.h"

#include "medusa/core/error.h"
#include "medusa/persistence/class_store.h"

#include <algorithm>
#include <cstdint>
#include <utility>

namespace medusa::persistence {
namespace {

constexpr const char* classes_name = "classes";
constexpr std::int64_t classes_format_version = 1;
constexpr hsize_t chunk_rows = 8192; // about 64 KiB of 8-byte values, as the rest of the store

// Owns one HDF5 identifier.
class Handle {
public:
  using Closer = herr_t (*)(hid_t);
  Handle(hid_t id, Closer closer) : id_(id), closer_(closer) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() { close(); }
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  bool close() {
    const bool ok = id_ < 0 || closer_(id_) >= 0;
    id_ = -1;
    return ok;
  }

private:
  hid_t id_;
  Closer closer_;
};

// Silences HDF5's error printing while in scope; failures become StoreError.
class Quiet {
public:
  Quiet() {
    H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~Quiet() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }
  Quiet(const Quiet&) = delete;
  Quiet& operator=(const Quiet&) = delete;

private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

void check(bool ok, const std::string& path, const std::string& what) {
  if (!ok)
    throw StoreError("store " + path + ": " + what);
}

void write_int(hid_t object, const char* name, std::int64_t value, const std::string& path) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attribute(H5Acreate2(object, name, H5T_STD_I64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  check(attribute.valid() && H5Awrite(attribute.get(), H5T_NATIVE_INT64, &value) >= 0, path,
        std::string("cannot write attribute ") + name);
}

std::int64_t read_int(hid_t object, const char* name, const std::string& path, const std::string& where) {
  check(H5Aexists(object, name) > 0, path, "missing attribute " + where + "@" + name);
  Handle attribute(H5Aopen(object, name, H5P_DEFAULT), H5Aclose);
  std::int64_t value = 0;
  check(attribute.valid() && H5Aread(attribute.get(), H5T_NATIVE_INT64, &value) >= 0, path,
        "cannot read attribute " + where + "@" + name);
  return value;
}

// A chunked, shuffled, deflated, fletcher32-checksummed uint64 dataset (docs/FORMAT.md), written whole.
void write_column(hid_t group, const char* name, const std::vector<std::uint64_t>& values,
                  const std::string& path) {
  const hsize_t size = values.size();
  const hsize_t max_size = H5S_UNLIMITED;
  const hsize_t chunk = std::max<hsize_t>(1, std::min(size, chunk_rows));
  Handle space(H5Screate_simple(1, &size, &max_size), H5Sclose);
  Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  check(space.valid() && dcpl.valid() && H5Pset_chunk(dcpl.get(), 1, &chunk) >= 0 &&
            H5Pset_shuffle(dcpl.get()) >= 0 && H5Pset_deflate(dcpl.get(), 6) >= 0 &&
            H5Pset_fletcher32(dcpl.get()) >= 0 && H5Pset_obj_track_times(dcpl.get(), 0) >= 0,
        path, std::string("cannot set up dataset ") + name);
  Handle dataset(H5Dcreate2(group, name, H5T_STD_U64LE, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
                 H5Dclose);
  check(dataset.valid(), path, std::string("cannot create dataset ") + name);
  if (size > 0)
    check(H5Dwrite(dataset.get(), H5T_NATIVE_UINT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0, path,
          std::string("cannot write dataset ") + name);
}

std::vector<std::uint64_t> read_column(hid_t group, const char* name, const std::string& path,
                                       const std::string& where) {
  check(H5Lexists(group, name, H5P_DEFAULT) > 0, path, "missing dataset " + where + "/" + name);
  Handle dataset(H5Dopen2(group, name, H5P_DEFAULT), H5Dclose);
  Handle space(H5Dget_space(dataset.get()), H5Sclose);
  check(dataset.valid() && space.valid() && H5Sget_simple_extent_ndims(space.get()) == 1, path,
        "dataset " + where + "/" + name + " is not one-dimensional");
  hsize_t size = 0;
  H5Sget_simple_extent_dims(space.get(), &size, nullptr);
  std::vector<std::uint64_t> values(static_cast<std::size_t>(size));
  if (size > 0)
    check(H5Dread(dataset.get(), H5T_NATIVE_UINT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0, path,
          "cannot read dataset " + where + "/" + name + " (corrupted?)");
  return values;
}

// Offsets and concatenated values of a list of lists.
void flatten(const std::vector<std::vector<medusa::CellId>>& lists, std::vector<std::uint64_t>& offsets,
             std::vector<std::uint64_t>& values) {
  offsets.assign(1, 0);
  for (const auto& list : lists) {
    values.insert(values.end(), list.begin(), list.end());
    offsets.push_back(values.size());
  }
}

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
  Handle gcpl(H5Pcreate(H5P_GROUP_CREATE), H5Pclose);
  check(gcpl.valid() && H5Pset_obj_track_times(gcpl.get(), 0) >= 0, path, "cannot set up group classes");
  Handle group(H5Gcreate2(parent, classes_name, H5P_DEFAULT, gcpl.get(), H5P_DEFAULT), H5Gclose);
  check(group.valid(), path, "cannot create group classes");
  write_int(group.get(), "format_version", classes_format_version, path);
  write_int(group.get(), "max_dimension", classes.options.max_dim, path);
  write_int(group.get(), "zero_length", classes.options.zero_length ? 1 : 0, path);
  write_int(group.get(), "shortened", classes.options.shorten ? 1 : 0, path);
  write_column(group.get(), "row", std::vector<std::uint64_t>(classes.rows.begin(), classes.rows.end()),
               path);
  std::vector<std::uint64_t> offsets, values;
  flatten(classes.cycles, offsets, values);
  write_column(group.get(), "cycle_offset", offsets, path);
  write_column(group.get(), "cycle", values, path);
  values.clear();
  flatten(classes.clusters, offsets, values);
  write_column(group.get(), "cluster_offset", offsets, path);
  write_column(group.get(), "cluster", values, path);
  check(group.close(), path, "cannot close group classes");
}

} // namespace detail

std::optional<ClassRepresentatives> read_classes(const std::string& store_path,
                                                 const std::string& diagram_name) {
  const Quiet quiet;
  Handle file(H5Fopen(store_path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  check(file.valid(), store_path, "cannot open as HDF5");
  const std::string where = "/persistence/" + diagram_name;
  if (H5Lexists(file.get(), "persistence", H5P_DEFAULT) <= 0 ||
      H5Lexists(file.get(), where.c_str(), H5P_DEFAULT) <= 0)
    return std::nullopt;
  Handle diagram(H5Gopen2(file.get(), where.c_str(), H5P_DEFAULT), H5Gclose);
  check(diagram.valid(), store_path, "cannot open group " + where);
  if (H5Lexists(diagram.get(), classes_name, H5P_DEFAULT) <= 0)
    return std::nullopt;
  const std::string at = where + "/" + classes_name;
  Handle group(H5Gopen2(diagram.get(), classes_name, H5P_DEFAULT), H5Gclose);
  check(group.valid(), store_path, "cannot open group " + at);
  const std::int64_t version = read_int(group.get(), "format_version", store_path, at);
  check(version == classes_format_version, store_path,
        at + " has format version " + std::to_string(version) + ", expected " +
            std::to_string(classes_format_version));
  // The diagram's length bounds the rows.
  Handle birth(H5Dopen2(diagram.get(), "birth", H5P_DEFAULT), H5Dclose);
  Handle space(H5Dget_space(birth.get()), H5Sclose);
  hsize_t points = 0;
  check(birth.valid() && space.valid() && H5Sget_simple_extent_dims(space.get(), &points, nullptr) == 1,
        store_path, "dataset " + where + "/birth is not one-dimensional");

  ClassRepresentatives classes;
  classes.options.max_dim = static_cast<int>(read_int(group.get(), "max_dimension", store_path, at));
  classes.options.zero_length = read_int(group.get(), "zero_length", store_path, at) != 0;
  // Stores written before shortening existed hold the unshortened cycles and no attribute.
  classes.options.shorten =
      H5Aexists(group.get(), "shortened") > 0 && read_int(group.get(), "shortened", store_path, at) != 0;
  const auto rows = read_column(group.get(), "row", store_path, at);
  for (std::size_t i = 0; i < rows.size(); ++i)
    check(rows[i] < points && (i == 0 || rows[i - 1] < rows[i]), store_path,
          at + "/row " + std::to_string(i) + " is outside the diagram or out of order");
  classes.rows.assign(rows.begin(), rows.end());
  classes.cycles =
      unflatten(read_column(group.get(), "cycle_offset", store_path, at),
                read_column(group.get(), "cycle", store_path, at), rows.size(), store_path, at + "/cycle");
  classes.clusters = unflatten(read_column(group.get(), "cluster_offset", store_path, at),
                               read_column(group.get(), "cluster", store_path, at), rows.size(), store_path,
                               at + "/cluster");
  return classes;
}

} // namespace medusa::persistence
