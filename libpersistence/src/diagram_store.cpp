#include "medusa/persistence/diagram_store.h"

#include "class_store.h"

#include "medusa/core/error.h"
#include "medusa/medusa/internal/hdf5_attributes.h"
#include "medusa/medusa/internal/hdf5_column.h"
#include "medusa/medusa/internal/hdf5_errors.h"
#include "medusa/medusa/internal/hdf5_handle.h"
#include "medusa/medusa/internal/hdf5_read.h"

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

using Id = h5::Handle;
using h5::fail;

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

template <class T>
std::vector<T> read_column(hid_t group, const std::string& where, const char* name, std::size_t expected,
                           const std::string& path) {
  std::vector<T> values = h5::read_column<T>(group, where.substr(1), name, path);
  check(values.size() == expected, path, "dataset " + where + "/" + name + " has the wrong length");
  return values;
}

void write_diagram(hid_t parent, const Diagram& d, const ClassRepresentatives* classes,
                   const std::string& path) {
  const std::string name = diagram_group_name(d);
  Id group = h5::create_group(parent, name, path);
  h5::write_attribute(group.get(), "direction",
                      std::string(d.direction == Direction::forward ? "forward" : "reverse"), path);
  h5::write_attribute(group.get(), "type", std::int64_t{d.cell_type}, path);
  // One column at a time, a chunk at a time: the diagram holds one pair per cell of the filtration,
  // and a whole column beside it would add 8 bytes a pair.
  const auto write = [&](const char* column, auto value) {
    using T = decltype(value(std::declval<const PersistencePair&>()));
    h5::write_column_of<T>(
        group.get(), column, d.pairs.size(), [&](std::size_t i) { return value(d.pairs[i]); }, path);
  };
  write("birth", [](const PersistencePair& p) { return p.birth; });
  write("death", [](const PersistencePair& p) { return p.death; });
  write("dimension", [](const PersistencePair& p) { return std::int32_t{p.dim}; });
  write("birth_cell", [](const PersistencePair& p) { return std::uint64_t{p.birth_cell}; });
  write("death_cell", [](const PersistencePair& p) { return std::uint64_t{p.death_cell}; });
  write("essential", [](const PersistencePair& p) { return static_cast<std::uint8_t>(p.essential ? 1 : 0); });
  write("zero_length",
        [](const PersistencePair& p) { return static_cast<std::uint8_t>(p.zero_length ? 1 : 0); });
  if (classes != nullptr)
    detail::write_classes(group.get(), *classes, d.pairs.size(), path);
  check(group.reset(), path, "cannot close group " + name);
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

struct DiagramStoreWriter::Open {
  std::string path;
  std::vector<std::string> names;
  std::vector<char> written;
  Id file;
  Id group;
};

DiagramStoreWriter::DiagramStoreWriter(const std::string& store_path, const std::vector<std::string>& names)
    : open_(std::make_unique<Open>()) {
  Open& o = *open_;
  o.path = store_path;
  o.names = names;
  o.written.assign(names.size(), 0);
  check(std::set<std::string>(names.begin(), names.end()).size() == names.size(), store_path,
        "two diagrams have the same name");
  const h5::Quiet quiet;
  o.file = open_file(store_path, H5F_ACC_RDWR);
  const hid_t file = o.file.get();
  check(H5Aexists(file, "complete") > 0, store_path, "not a complete medusa store (no attribute complete)");
  check(H5Aexists(file, "format") > 0 &&
            h5::read_string_attribute(file, "format", store_path) == "medusa-store",
        store_path, "not a medusa store");
  if (H5Lexists(file, group_name, H5P_DEFAULT) > 0)
    check(H5Ldelete(file, group_name, H5P_DEFAULT) >= 0, store_path, "cannot replace group /persistence");
  o.group = h5::create_group(file, group_name, store_path);
  h5::write_attribute(o.group.get(), "format", std::string("medusa-persistence"), store_path);
  h5::write_attribute(o.group.get(), "format_version", persistence_format_version, store_path);
  h5::write_attribute(o.group.get(), "diagram_count", static_cast<std::int64_t>(names.size()), store_path);
  // Creation order is tracked nowhere else, so the order of the diagrams is an attribute too.
  std::string order;
  for (const std::string& name : names)
    order += (order.empty() ? "" : ",") + name;
  h5::write_attribute(o.group.get(), "diagram_order", order, store_path);
}

DiagramStoreWriter::~DiagramStoreWriter() {
  if (open_) {
    const h5::Quiet quiet;
    open_->group.reset();
    open_->file.reset();
  }
}

void DiagramStoreWriter::write(const Diagram& diagram, const ClassRepresentatives* classes) {
  if (!open_)
    throw InternalError("diagram store writer: write after close");
  Open& o = *open_;
  const std::string name = diagram_group_name(diagram);
  const auto at = std::find(o.names.begin(), o.names.end(), name);
  check(at != o.names.end(), o.path, "diagram " + name + " was not announced");
  char& done = o.written[static_cast<std::size_t>(at - o.names.begin())];
  check(!done, o.path, "diagram " + name + " written twice");
  const h5::Quiet quiet;
  write_diagram(o.group.get(), diagram, classes, o.path);
  done = 1;
}

void DiagramStoreWriter::close() {
  if (!open_)
    return;
  Open& o = *open_;
  for (std::size_t i = 0; i < o.names.size(); ++i)
    check(o.written[i], o.path, "diagram " + o.names[i] + " was not written");
  const h5::Quiet quiet;
  check(o.group.reset(), o.path, "cannot close group /persistence");
  check(H5Fflush(o.file.get(), H5F_SCOPE_GLOBAL) >= 0 && o.file.reset(), o.path,
        "cannot write the diagrams (disk full?)");
  open_.reset();
}

namespace {

// Every diagram into `/persistence` of the store at `path` (replacing an older group).
void write_all(const std::string& path, const std::vector<Diagram>& diagrams,
               const std::vector<const ClassRepresentatives*>& classes) {
  std::vector<std::string> names;
  for (const Diagram& d : diagrams)
    names.push_back(diagram_group_name(d));
  DiagramStoreWriter writer(path, names);
  for (std::size_t i = 0; i < diagrams.size(); ++i)
    writer.write(diagrams[i], i < classes.size() ? classes[i] : nullptr);
  writer.close();
}

} // namespace

void write_diagrams(const std::string& store_path, const std::vector<Diagram>& diagrams,
                    const std::vector<const ClassRepresentatives*>& classes) {
  check_names(store_path, diagrams);
  const std::string temporary = store_path + ".tmp-" + std::to_string(static_cast<long long>(::getpid()));
  std::error_code ec;
  if (!fs::copy_file(store_path, temporary, fs::copy_options::overwrite_existing, ec))
    fail(store_path, "cannot copy to " + temporary + (ec ? " (" + ec.message() + ")" : ""));
  try {
    write_all(temporary, diagrams, classes);
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

std::vector<Diagram> read_diagrams(const std::string& store_path, const std::string& only) {
  const h5::Quiet quiet;
  Id file = open_file(store_path, H5F_ACC_RDONLY);
  check(H5Lexists(file.get(), group_name, H5P_DEFAULT) > 0, store_path, "no group /persistence");
  Id group = h5::group_handle(H5Gopen2(file.get(), group_name, H5P_DEFAULT));
  check(group.valid(), store_path, "cannot open group /persistence");
  check(h5::read_string_attribute(group.get(), "format", store_path) == "medusa-persistence", store_path,
        "/persistence is not a medusa-persistence group");
  const std::int64_t version = h5::read_int_attribute(group.get(), "format_version", store_path);
  check(version == persistence_format_version, store_path,
        "/persistence has format version " + std::to_string(version) + ", expected " +
            std::to_string(persistence_format_version));
  const std::int64_t count = h5::read_int_attribute(group.get(), "diagram_count", store_path);
  const std::string order = h5::read_string_attribute(group.get(), "diagram_order", store_path);
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
    if (!only.empty() && name != only)
      continue;
    const std::string where = "/persistence/" + name;
    check(H5Lexists(group.get(), name.c_str(), H5P_DEFAULT) > 0, store_path, "missing group " + where);
    Id g = h5::group_handle(H5Gopen2(group.get(), name.c_str(), H5P_DEFAULT));
    check(g.valid(), store_path, "cannot open group " + where);
    Diagram d;
    const std::string direction = h5::read_string_attribute(g.get(), "direction", store_path);
    check(direction == "forward" || direction == "reverse", store_path,
          where + " has direction " + direction);
    d.direction = direction == "forward" ? Direction::forward : Direction::reverse;
    d.cell_type = static_cast<int>(h5::read_int_attribute(g.get(), "type", store_path));
    check(diagram_group_name(d) == name, store_path, where + " does not match its attributes");
    Id birth_set = h5::dataset_handle(H5Dopen2(g.get(), "birth", H5P_DEFAULT));
    check(birth_set.valid(), store_path, "missing dataset " + where + "/birth");
    Id space = h5::space_handle(H5Dget_space(birth_set.get()));
    hsize_t n = 0;
    check(space.valid() && H5Sget_simple_extent_ndims(space.get()) == 1 &&
              H5Sget_simple_extent_dims(space.get(), &n, nullptr) == 1,
          store_path, "dataset " + where + "/birth is not one-dimensional");
    const std::size_t size = static_cast<std::size_t>(n);
    const auto birth = read_column<double>(g.get(), where, "birth", size, store_path);
    const auto death = read_column<double>(g.get(), where, "death", size, store_path);
    const auto dimension = read_column<std::int32_t>(g.get(), where, "dimension", size, store_path);
    const auto birth_cell = read_column<std::uint64_t>(g.get(), where, "birth_cell", size, store_path);
    const auto death_cell = read_column<std::uint64_t>(g.get(), where, "death_cell", size, store_path);
    const auto essential = read_column<std::uint8_t>(g.get(), where, "essential", size, store_path);
    const auto zero_length = read_column<std::uint8_t>(g.get(), where, "zero_length", size, store_path);
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
