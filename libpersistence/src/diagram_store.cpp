#include "medusa/persistence/diagram_store.h"

#include "medusa/core/error.h"

#include <hdf5.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <set>
#include <unistd.h>
#include <utility>

namespace medusa::persistence {

namespace {

namespace fs = std::filesystem;

constexpr const char* group_name = "persistence";
constexpr std::int64_t persistence_format_version = 1;
// About 64 KiB per chunk for 8-byte values, as the rest of the store (docs/FORMAT.md).
constexpr hsize_t chunk_rows = 8192;

// Owns one HDF5 identifier.
class Id {
public:
  using Closer = herr_t (*)(hid_t);
  Id(hid_t id, Closer closer) : id_(id), closer_(closer) {}
  Id(const Id&) = delete;
  Id& operator=(const Id&) = delete;
  Id(Id&& other) noexcept : id_(std::exchange(other.id_, -1)), closer_(other.closer_) {}
  Id& operator=(Id&&) = delete;
  ~Id() { close(); }
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

// Silences HDF5's error printing while in scope; failures are reported as StoreError instead.
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

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw StoreError("store " + path + ": " + what);
}

void check(bool ok, const std::string& path, const std::string& what) {
  if (!ok)
    fail(path, what);
}

Id open_file(const std::string& path, unsigned flags) {
  Id fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  check(fapl.valid() && H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_V110, H5F_LIBVER_V110) >= 0, path,
        "cannot set up file access");
  Id file(H5Fopen(path.c_str(), flags, fapl.get()), H5Fclose);
  check(file.valid(), path, "cannot open as HDF5");
  return file;
}

void write_string_attribute(hid_t object, const char* name, const std::string& value,
                            const std::string& path) {
  Id type(H5Tcopy(H5T_C_S1), H5Tclose);
  Id space(H5Screate(H5S_SCALAR), H5Sclose);
  check(type.valid() && space.valid() &&
            H5Tset_size(type.get(), std::max<std::size_t>(1, value.size())) >= 0 &&
            H5Tset_strpad(type.get(), H5T_STR_NULLPAD) >= 0 && H5Tset_cset(type.get(), H5T_CSET_UTF8) >= 0,
        path, std::string("cannot set up attribute ") + name);
  Id attribute(H5Acreate2(object, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  const std::string padded = value.empty() ? std::string(1, '\0') : value;
  check(attribute.valid() && H5Awrite(attribute.get(), type.get(), padded.data()) >= 0, path,
        std::string("cannot write attribute ") + name);
}

void write_int_attribute(hid_t object, const char* name, std::int64_t value, const std::string& path) {
  Id space(H5Screate(H5S_SCALAR), H5Sclose);
  Id attribute(H5Acreate2(object, name, H5T_STD_I64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  check(attribute.valid() && H5Awrite(attribute.get(), H5T_NATIVE_INT64, &value) >= 0, path,
        std::string("cannot write attribute ") + name);
}

std::string read_string_attribute(hid_t object, const char* name, const std::string& path) {
  check(H5Aexists(object, name) > 0, path, std::string("missing attribute ") + name);
  Id attribute(H5Aopen(object, name, H5P_DEFAULT), H5Aclose);
  Id type(H5Aget_type(attribute.get()), H5Tclose);
  check(type.valid() && H5Tget_class(type.get()) == H5T_STRING && H5Tis_variable_str(type.get()) == 0, path,
        std::string("attribute ") + name + " is not a fixed-length string");
  std::string value(H5Tget_size(type.get()), '\0');
  Id memory(H5Tcopy(type.get()), H5Tclose);
  check(H5Aread(attribute.get(), memory.get(), value.data()) >= 0, path,
        std::string("cannot read attribute ") + name);
  value.erase(std::find(value.begin(), value.end(), '\0'), value.end());
  return value;
}

std::int64_t read_int_attribute(hid_t object, const char* name, const std::string& path) {
  check(H5Aexists(object, name) > 0, path, std::string("missing attribute ") + name);
  Id attribute(H5Aopen(object, name, H5P_DEFAULT), H5Aclose);
  std::int64_t value = 0;
  check(attribute.valid() && H5Aread(attribute.get(), H5T_NATIVE_INT64, &value) >= 0, path,
        std::string("cannot read attribute ") + name);
  return value;
}

// A chunked, shuffled, deflated, fletcher32-checksummed 1-D dataset (docs/FORMAT.md), written whole.
template <class T>
void write_column(hid_t group, const char* name, hid_t file_type, hid_t memory_type,
                  const std::vector<T>& values, const std::string& path) {
  const hsize_t size = values.size();
  const hsize_t max_size = H5S_UNLIMITED;
  const hsize_t chunk = std::max<hsize_t>(1, std::min(size, chunk_rows));
  Id space(H5Screate_simple(1, &size, &max_size), H5Sclose);
  Id dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  // No object timestamps, so the same diagrams give byte-identical objects.
  check(space.valid() && dcpl.valid() && H5Pset_chunk(dcpl.get(), 1, &chunk) >= 0 &&
            H5Pset_shuffle(dcpl.get()) >= 0 && H5Pset_deflate(dcpl.get(), 6) >= 0 &&
            H5Pset_fletcher32(dcpl.get()) >= 0 && H5Pset_obj_track_times(dcpl.get(), 0) >= 0,
        path, std::string("cannot set up dataset ") + name);
  Id dataset(H5Dcreate2(group, name, file_type, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT), H5Dclose);
  check(dataset.valid(), path, std::string("cannot create dataset ") + name);
  if (size > 0)
    check(H5Dwrite(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0, path,
          std::string("cannot write dataset ") + name);
}

template <class T>
std::vector<T> read_column(hid_t group, const char* name, hid_t memory_type, std::size_t expected,
                           const std::string& path, const std::string& where) {
  check(H5Lexists(group, name, H5P_DEFAULT) > 0, path, "missing dataset " + where + "/" + name);
  Id dataset(H5Dopen2(group, name, H5P_DEFAULT), H5Dclose);
  Id space(H5Dget_space(dataset.get()), H5Sclose);
  check(dataset.valid() && space.valid() && H5Sget_simple_extent_ndims(space.get()) == 1, path,
        "dataset " + where + "/" + name + " is not one-dimensional");
  hsize_t size = 0;
  H5Sget_simple_extent_dims(space.get(), &size, nullptr);
  check(size == expected, path, "dataset " + where + "/" + name + " has the wrong length");
  std::vector<T> values(static_cast<std::size_t>(size));
  if (size > 0)
    check(H5Dread(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0, path,
          "cannot read dataset " + where + "/" + name + " (corrupted?)");
  return values;
}

Id create_group(hid_t parent, const std::string& name, const std::string& path) {
  Id gcpl(H5Pcreate(H5P_GROUP_CREATE), H5Pclose);
  check(gcpl.valid() && H5Pset_obj_track_times(gcpl.get(), 0) >= 0, path, "cannot set up group " + name);
  Id group(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, gcpl.get(), H5P_DEFAULT), H5Gclose);
  check(group.valid(), path, "cannot create group " + name);
  return group;
}

void write_diagram(hid_t parent, const Diagram& d, const std::string& path) {
  const std::string name = diagram_group_name(d);
  Id group = create_group(parent, name, path);
  write_string_attribute(group.get(), "direction", d.direction == Direction::forward ? "forward" : "reverse",
                         path);
  write_int_attribute(group.get(), "type", d.cell_type, path);
  std::vector<double> birth, death;
  std::vector<std::int32_t> dimension;
  std::vector<std::uint64_t> birth_cell, death_cell;
  std::vector<std::uint8_t> essential, zero_length;
  for (const PersistencePair& p : d.pairs) {
    birth.push_back(p.birth);
    death.push_back(p.death);
    dimension.push_back(p.dim);
    birth_cell.push_back(p.birth_cell);
    death_cell.push_back(p.death_cell);
    essential.push_back(p.essential ? 1 : 0);
    zero_length.push_back(p.zero_length ? 1 : 0);
  }
  write_column(group.get(), "birth", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, birth, path);
  write_column(group.get(), "death", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, death, path);
  write_column(group.get(), "dimension", H5T_STD_I32LE, H5T_NATIVE_INT32, dimension, path);
  write_column(group.get(), "birth_cell", H5T_STD_U64LE, H5T_NATIVE_UINT64, birth_cell, path);
  write_column(group.get(), "death_cell", H5T_STD_U64LE, H5T_NATIVE_UINT64, death_cell, path);
  write_column(group.get(), "essential", H5T_STD_U8LE, H5T_NATIVE_UINT8, essential, path);
  write_column(group.get(), "zero_length", H5T_STD_U8LE, H5T_NATIVE_UINT8, zero_length, path);
  check(group.close(), path, "cannot close group " + name);
}

// Every diagram into `/persistence` of the open file (replacing an older group).
void write_group(hid_t file, const std::vector<Diagram>& diagrams, const std::string& path) {
  check(H5Aexists(file, "complete") > 0, path, "not a complete medusa store (no attribute complete)");
  check(H5Aexists(file, "format") > 0 && read_string_attribute(file, "format", path) == "medusa-store", path,
        "not a medusa store");
  if (H5Lexists(file, group_name, H5P_DEFAULT) > 0)
    check(H5Ldelete(file, group_name, H5P_DEFAULT) >= 0, path, "cannot replace group /persistence");
  Id group = create_group(file, group_name, path);
  write_string_attribute(group.get(), "format", "medusa-persistence", path);
  write_int_attribute(group.get(), "format_version", persistence_format_version, path);
  write_int_attribute(group.get(), "diagram_count", static_cast<std::int64_t>(diagrams.size()), path);
  // Creation order is tracked nowhere else, so the order of the diagrams is an attribute too.
  std::string order;
  for (const Diagram& d : diagrams)
    order += (order.empty() ? "" : ",") + diagram_group_name(d);
  write_string_attribute(group.get(), "diagram_order", order, path);
  for (const Diagram& d : diagrams)
    write_diagram(group.get(), d, path);
  check(group.close(), path, "cannot close group /persistence");
}

} // namespace

std::string diagram_group_name(const Diagram& diagram) {
  const std::string direction = diagram.direction == Direction::forward ? "forward" : "reverse";
  return direction + "_" +
         (diagram.cell_type == all_types ? "all" : "type" + std::to_string(diagram.cell_type));
}

namespace {

void check_names(const std::string& store_path, const std::vector<Diagram>& diagrams) {
  std::set<std::string> names;
  for (const Diagram& d : diagrams)
    check(names.insert(diagram_group_name(d)).second, store_path,
          "two diagrams named " + diagram_group_name(d));
}

} // namespace

void write_diagrams_in_place(const std::string& store_path, const std::vector<Diagram>& diagrams) {
  check_names(store_path, diagrams);
  const Quiet quiet;
  Id file = open_file(store_path, H5F_ACC_RDWR);
  write_group(file.get(), diagrams, store_path);
  check(H5Fflush(file.get(), H5F_SCOPE_GLOBAL) >= 0 && file.close(), store_path,
        "cannot write the diagrams (disk full?)");
}

void write_diagrams(const std::string& store_path, const std::vector<Diagram>& diagrams) {
  check_names(store_path, diagrams);
  const std::string temporary = store_path + ".tmp-" + std::to_string(static_cast<long long>(::getpid()));
  std::error_code ec;
  if (!fs::copy_file(store_path, temporary, fs::copy_options::overwrite_existing, ec))
    fail(store_path, "cannot copy to " + temporary + (ec ? " (" + ec.message() + ")" : ""));
  try {
    const Quiet quiet;
    Id file = open_file(temporary, H5F_ACC_RDWR);
    write_group(file.get(), diagrams, store_path);
    check(H5Fflush(file.get(), H5F_SCOPE_GLOBAL) >= 0 && file.close(), store_path,
          "cannot write " + temporary + " (disk full?)");
  } catch (...) {
    fs::remove(temporary, ec);
    throw;
  }
  fs::rename(temporary, store_path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    fail(store_path, "cannot rename " + temporary + " (" + ec.message() + ")");
  }
}

std::vector<Diagram> read_diagrams(const std::string& store_path) {
  const Quiet quiet;
  Id file = open_file(store_path, H5F_ACC_RDONLY);
  check(H5Lexists(file.get(), group_name, H5P_DEFAULT) > 0, store_path, "no group /persistence");
  Id group(H5Gopen2(file.get(), group_name, H5P_DEFAULT), H5Gclose);
  check(group.valid(), store_path, "cannot open group /persistence");
  check(read_string_attribute(group.get(), "format", store_path) == "medusa-persistence", store_path,
        "/persistence is not a medusa-persistence group");
  const std::int64_t version = read_int_attribute(group.get(), "format_version", store_path);
  check(version == persistence_format_version, store_path,
        "/persistence has format version " + std::to_string(version) + ", expected " +
            std::to_string(persistence_format_version));
  const std::int64_t count = read_int_attribute(group.get(), "diagram_count", store_path);
  const std::string order = read_string_attribute(group.get(), "diagram_order", store_path);
  std::vector<std::string> names;
  for (std::size_t start = 0; start < order.size();) {
    const std::size_t comma = std::min(order.find(',', start), order.size());
    names.push_back(order.substr(start, comma - start));
    start = comma + 1;
  }
  check(static_cast<std::int64_t>(names.size()) == count, store_path,
        "/persistence lists " + std::to_string(names.size()) + " diagrams, diagram_count is " +
            std::to_string(count));
  std::vector<Diagram> out;
  for (const std::string& name : names) {
    const std::string where = "/persistence/" + name;
    check(H5Lexists(group.get(), name.c_str(), H5P_DEFAULT) > 0, store_path, "missing group " + where);
    Id g(H5Gopen2(group.get(), name.c_str(), H5P_DEFAULT), H5Gclose);
    check(g.valid(), store_path, "cannot open group " + where);
    Diagram d;
    const std::string direction = read_string_attribute(g.get(), "direction", store_path);
    check(direction == "forward" || direction == "reverse", store_path,
          where + " has direction " + direction);
    d.direction = direction == "forward" ? Direction::forward : Direction::reverse;
    d.cell_type = static_cast<int>(read_int_attribute(g.get(), "type", store_path));
    check(diagram_group_name(d) == name, store_path, where + " does not match its attributes");
    Id birth_set(H5Dopen2(g.get(), "birth", H5P_DEFAULT), H5Dclose);
    check(birth_set.valid(), store_path, "missing dataset " + where + "/birth");
    Id space(H5Dget_space(birth_set.get()), H5Sclose);
    hsize_t n = 0;
    check(space.valid() && H5Sget_simple_extent_ndims(space.get()) == 1 &&
              H5Sget_simple_extent_dims(space.get(), &n, nullptr) == 1,
          store_path, "dataset " + where + "/birth is not one-dimensional");
    const std::size_t size = static_cast<std::size_t>(n);
    const auto birth = read_column<double>(g.get(), "birth", H5T_NATIVE_DOUBLE, size, store_path, where);
    const auto death = read_column<double>(g.get(), "death", H5T_NATIVE_DOUBLE, size, store_path, where);
    const auto dimension =
        read_column<std::int32_t>(g.get(), "dimension", H5T_NATIVE_INT32, size, store_path, where);
    const auto birth_cell =
        read_column<std::uint64_t>(g.get(), "birth_cell", H5T_NATIVE_UINT64, size, store_path, where);
    const auto death_cell =
        read_column<std::uint64_t>(g.get(), "death_cell", H5T_NATIVE_UINT64, size, store_path, where);
    const auto essential =
        read_column<std::uint8_t>(g.get(), "essential", H5T_NATIVE_UINT8, size, store_path, where);
    const auto zero_length =
        read_column<std::uint8_t>(g.get(), "zero_length", H5T_NATIVE_UINT8, size, store_path, where);
    for (std::size_t i = 0; i < size; ++i) {
      PersistencePair p;
      p.dim = dimension[i];
      p.birth = birth[i];
      p.death = death[i];
      p.birth_cell = birth_cell[i];
      p.death_cell = death_cell[i];
      p.essential = essential[i] != 0;
      p.zero_length = zero_length[i] != 0;
      // An essential class never dies: +inf forward, -inf reverse (docs/MATH.md §7.3, §7.5).
      const double never = d.direction == Direction::forward ? std::numeric_limits<double>::infinity()
                                                             : -std::numeric_limits<double>::infinity();
      check(p.essential == (p.death == never), store_path,
            where + " row " + std::to_string(i) + ": essential flag and death disagree");
      d.pairs.push_back(std::move(p));
    }
    out.push_back(std::move(d));
  }
  return out;
}

} // namespace medusa::persistence
