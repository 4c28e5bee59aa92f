#include "medusa/medusa/store_reader.h"

#include "medusa/medusa/internal/hdf5_attributes.h"
#include "medusa/medusa/internal/hdf5_errors.h"
#include "medusa/medusa/internal/hdf5_handle.h"
#include "medusa/medusa/internal/hdf5_read.h"
#include "store_layout.h"

#include "medusa/core/error.h"
#include "medusa/medusa/store_writer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <sys/stat.h>

namespace medusa {

namespace L = layout;
using h5::Handle;

namespace {

[[noreturn]] void corrupt(const std::string& path, const std::string& what) {
  throw StoreError("store " + path + ": " + what);
}

bool has_attribute(hid_t object, const char* name, const std::string& path) {
  const htri_t exists = H5Aexists(object, name);
  if (exists < 0)
    h5::fail(path, "cannot read the root group");
  return exists > 0;
}

Handle open_group(hid_t file, const char* name, const std::string& path) {
  if (H5Lexists(file, name, H5P_DEFAULT) <= 0)
    corrupt(path, std::string("group /") + name + " is missing");
  Handle g = h5::group_handle(H5Gopen2(file, name, H5P_DEFAULT));
  if (!g.valid())
    h5::fail(path, std::string("cannot open group /") + name);
  return g;
}

// Offsets of a flattened dataset: n + 1 entries, starting at 0, non-decreasing, ending at `total`.
void check_offsets(const std::vector<std::uint64_t>& offsets, std::size_t n, std::size_t total,
                   const std::string& name, const std::string& path) {
  if (offsets.size() != n + 1 || offsets.front() != 0 || offsets.back() != total)
    corrupt(path, "dataset " + name + " does not match the sizes of the store");
  for (std::size_t i = 0; i < n; ++i)
    if (offsets[i] > offsets[i + 1])
      corrupt(path, "dataset " + name + " decreases at entry " + std::to_string(i));
}

void read_input(hid_t file, Medusa& m, const std::string& path) {
  Handle g = open_group(file, L::input, path);
  const std::string gn = L::input;
  m.input.type_names = h5::read_strings_attribute(g.get(), L::type_names, path);
  const auto ids = h5::read_column<std::int64_t>(g.get(), gn, L::input_cell_id, path);
  const auto types = h5::read_column<std::int32_t>(g.get(), gn, L::input_cell_type, path);
  const auto first = h5::read_column<std::uint64_t>(g.get(), gn, L::input_first_frame, path);
  const auto offsets = h5::read_column<std::uint64_t>(g.get(), gn, L::input_position_offset, path);
  const auto positions = h5::read_column<std::int64_t>(g.get(), gn, L::input_positions, path, 3);
  m.input.frame_times = h5::read_column<std::int64_t>(g.get(), gn, L::input_frame_times, path);
  const std::size_t n = ids.size();
  if (types.size() != n || first.size() != n)
    corrupt(path, "the datasets of /input have different lengths");
  check_offsets(offsets, n, positions.size() / 3, "/input/position_offset", path);
  m.input.cells.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    kinetic::Trajectory& t = m.input.cells[i];
    t.cell_id = ids[i];
    t.type = types[i];
    t.first_frame = first[i];
    t.positions.reserve(offsets[i + 1] - offsets[i]);
    for (std::uint64_t r = offsets[i]; r < offsets[i + 1]; ++r)
      t.positions.push_back({positions[3 * r], positions[3 * r + 1], positions[3 * r + 2]});
  }
}

// Returns the number of batch records in the store; all of them are kept, or with every_batch false
// those frame_batch reads (StoreReadOptions::every_batch), one column at a time.
std::size_t read_events(hid_t file, Medusa& m, bool every_batch, const std::string& path) {
  Handle g = open_group(file, L::events, path);
  const std::string gn = L::events;
  const auto slab = h5::read_column<std::uint64_t>(g.get(), gn, L::batch_slab, path);
  const auto at_frame = h5::read_column<std::uint8_t>(g.get(), gn, L::batch_at_frame, path);
  const std::size_t nb = slab.size();
  if (at_frame.size() != nb)
    corrupt(path, "the batch datasets of /events have different lengths");
  std::vector<std::size_t> kept;
  if (!every_batch)
    for (std::size_t i = 0; i < nb; ++i)
      if (at_frame[i] != 0 || i + 1 == nb || slab[i + 1] != slab[i])
        kept.push_back(i);
  const std::size_t n = every_batch ? nb : kept.size();
  const auto row = [&](std::size_t k) { return every_batch ? k : kept[k]; };
  // Sized at once: a million-cell run has some 45 million batches, and a vector doubling its way
  // there would hold up to twice their 1.8 GB, and three times while it moves.
  const std::size_t first = m.batches.size();
  m.batches.resize(first + n);
  const auto fill = [&](const char* name, auto value, auto set) {
    const auto column = h5::read_column<decltype(value)>(g.get(), gn, name, path);
    if (column.size() != nb)
      corrupt(path, "the batch datasets of /events have different lengths");
    for (std::size_t k = 0; k < n; ++k)
      set(m.batches[first + k], column[row(k)]);
  };
  fill(L::batch_index, std::uint64_t{}, [](BatchRecord& b, std::uint64_t v) { b.batch = v; });
  fill(L::batch_u, double{}, [](BatchRecord& b, double v) { b.u = v; });
  fill(L::batch_time, double{}, [](BatchRecord& b, double v) { b.time = v; });
  fill(L::batch_ranks, std::uint32_t{}, [](BatchRecord& b, std::uint32_t v) { b.ranks = v; });
  for (std::size_t k = 0; k < n; ++k) {
    m.batches[first + k].slab = slab[row(k)];
    m.batches[first + k].at_frame = at_frame[row(k)] != 0;
  }
  const auto frame = h5::read_column<std::uint64_t>(g.get(), gn, L::frame_index, path);
  const auto frame_batch = h5::read_column<std::uint64_t>(g.get(), gn, L::frame_batch, path);
  const auto frame_time = h5::read_column<double>(g.get(), gn, L::frame_time, path);
  if (frame_batch.size() != frame.size() || frame_time.size() != frame.size())
    corrupt(path, "the frame datasets of /events have different lengths");
  m.frames.reserve(m.frames.size() + frame.size());
  for (std::size_t i = 0; i < frame.size(); ++i)
    m.frames.push_back({frame[i], frame_batch[i], frame_time[i]});
  return nb;
}

void read_cells(hid_t file, Medusa& m, std::uint64_t count, const std::string& path) {
  Handle g = open_group(file, L::cells, path);
  const std::string gn = L::cells;
  const auto id = h5::read_column<std::uint64_t>(g.get(), gn, L::cell_id, path);
  const std::size_t n = id.size();
  if (n != count)
    corrupt(path,
            "/cells/id has " + std::to_string(n) + " entries but cell_count is " + std::to_string(count));
  if (n > max_cell_count)
    corrupt(path, "/cells/id has " + std::to_string(n) + " entries, more than the " +
                      std::to_string(max_cell_count) + " cells a medusa holds");
  const auto kind = h5::read_column<std::uint8_t>(g.get(), gn, L::kind, path);
  const auto bb = h5::read_column<std::uint64_t>(g.get(), gn, L::birth_batch, path);
  const auto br = h5::read_column<std::uint32_t>(g.get(), gn, L::birth_rank, path);
  const auto bt = h5::read_column<double>(g.get(), gn, L::birth_time, path);
  const auto db = h5::read_column<std::uint64_t>(g.get(), gn, L::death_batch, path);
  const auto dr = h5::read_column<std::uint32_t>(g.get(), gn, L::death_rank, path);
  const auto dt = h5::read_column<double>(g.get(), gn, L::death_time, path);
  const auto voff = h5::read_column<std::uint64_t>(g.get(), gn, L::vertex_offset, path);
  const auto vertices = h5::read_column<std::int32_t>(g.get(), gn, L::vertices, path);
  const auto foff = h5::read_column<std::uint64_t>(g.get(), gn, L::facet_offset, path);
  const auto facets = h5::read_column<std::uint64_t>(g.get(), gn, L::facets, path);
  if (kind.size() != n || bb.size() != n || br.size() != n || bt.size() != n || db.size() != n ||
      dr.size() != n || dt.size() != n)
    corrupt(path, "the datasets of /cells have different lengths");
  check_offsets(voff, n, vertices.size(), "/cells/vertex_offset", path);
  check_offsets(foff, n, facets.size(), "/cells/facet_offset", path);
  for (std::size_t j = 0; j < facets.size(); ++j)
    if (facets[j] >= n)
      corrupt(path, "/cells/facets entry " + std::to_string(j) + " names cell " + std::to_string(facets[j]) +
                        ", but the store has " + std::to_string(n) + " cells");
  m.cells.assign(n, Cell{});
  std::vector<char> seen(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (id[i] >= n || seen[id[i]])
      corrupt(path, "cell ids are not 0.." + std::to_string(n - 1) + " (entry " + std::to_string(i) + ")");
    seen[id[i]] = 1;
    if (kind[i] > static_cast<std::uint8_t>(CellKind::repair))
      corrupt(path, "cell " + std::to_string(id[i]) + " has an unknown kind " + std::to_string(kind[i]));
    Cell& c = m.cells[id[i]];
    c.id = id[i];
    c.kind = static_cast<CellKind>(kind[i]);
    if (bb[i] > max_batch || db[i] > max_batch)
      corrupt(path,
              "cell " + std::to_string(id[i]) + " has a batch index above " + std::to_string(max_batch));
    c.birth = VirtualTime{static_cast<std::uint32_t>(bb[i]), br[i], bt[i]};
    c.death = VirtualTime{static_cast<std::uint32_t>(db[i]), dr[i], dt[i]};
    c.vertices.assign(vertices.begin() + static_cast<std::ptrdiff_t>(voff[i]),
                      vertices.begin() + static_cast<std::ptrdiff_t>(voff[i + 1]));
    c.facets.assign(facets.begin() + static_cast<std::ptrdiff_t>(foff[i]),
                    facets.begin() + static_cast<std::ptrdiff_t>(foff[i + 1]));
  }
}

// Reads every dataset outside the groups read above (the diagrams of /persistence, and anything a
// later writer added) whole, so that HDF5 checks each chunk's fletcher32 checksum as h5py would: a
// flipped bit there is a store error too, not data passed on.
struct VisitState {
  bool events_read = true;
  std::string failed; // the first dataset that could not be read
};

herr_t verify_object(hid_t root, const char* name, const H5O_info_t* info, void* data) {
  auto& state = *static_cast<VisitState*>(data);
  if (info->type != H5O_TYPE_DATASET || !state.failed.empty())
    return 0;
  const std::string full = std::string("/") + name;
  const auto under = [&](const char* group) { return full.rfind(std::string("/") + group + "/", 0) == 0; };
  if (under(L::input) || under(L::cells) || (state.events_read && under(L::events)))
    return 0;
  Handle dataset = h5::dataset_handle(H5Dopen2(root, name, H5P_DEFAULT));
  Handle file_type = h5::type_handle(dataset.valid() ? H5Dget_type(dataset.get()) : -1);
  Handle memory_type =
      h5::type_handle(file_type.valid() ? H5Tget_native_type(file_type.get(), H5T_DIR_ASCEND) : -1);
  Handle space = h5::space_handle(dataset.valid() ? H5Dget_space(dataset.get()) : -1);
  const hssize_t points = space.valid() ? H5Sget_simple_extent_npoints(space.get()) : -1;
  const std::size_t width = memory_type.valid() ? H5Tget_size(memory_type.get()) : 0;
  if (points < 0 || width == 0) {
    state.failed = full;
    return 1;
  }
  std::vector<unsigned char> bytes(static_cast<std::size_t>(points) * width);
  if (points > 0 &&
      H5Dread(dataset.get(), memory_type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data()) < 0) {
    state.failed = full;
    return 1;
  }
  return 0;
}

void verify_other_datasets(hid_t file, bool events_read, const std::string& path) {
  VisitState state;
  state.events_read = events_read;
  const herr_t visited =
      H5Ovisit2(file, H5_INDEX_NAME, H5_ITER_NATIVE, verify_object, &state, H5O_INFO_BASIC);
  if (!state.failed.empty())
    h5::fail(path, "dataset " + state.failed + " is corrupted (checksum or structure)");
  if (visited < 0)
    h5::fail(path, "cannot list its objects (corrupted?)");
}

// The run facts a correct writer cannot produce otherwise (docs/FORMAT.md): checked before anything
// is computed from them, so an edited or damaged store with valid checksums is refused, naming the
// first impossible value.
void validate_run_facts(const Medusa& m, const std::string& path) {
  try {
    m.input.validate();
  } catch (const InputError& e) {
    corrupt(path, e.what());
  }
  const std::vector<std::int64_t>& times = m.input.frame_times;
  const std::size_t frames = times.size();
  if (!std::isfinite(m.run.radius) || m.run.radius <= 0)
    corrupt(path, "radius " + std::to_string(m.run.radius) + " is not a positive number");
  for (const kinetic::Trajectory& t : m.input.cells) {
    if (t.type < 0)
      corrupt(path, "cell " + std::to_string(t.cell_id) + " has the negative type " + std::to_string(t.type));
    if (t.first_frame >= frames || t.positions.size() > frames - t.first_frame)
      corrupt(path, "cell " + std::to_string(t.cell_id) + " has first_frame " +
                        std::to_string(t.first_frame) + " outside the run's " + std::to_string(frames) +
                        " frames");
  }
  // The builder kills every cell alive at the end at end_time (docs/MATH.md §6.2), and nothing
  // happens after it.
  if (!std::isfinite(m.end.time))
    corrupt(path, "end_time is not a finite number");
  double last_death = -std::numeric_limits<double>::infinity();
  for (const Cell& c : m.cells) {
    if (!std::isfinite(c.birth.time) || !std::isfinite(c.death.time) || c.death.time > m.end.time)
      corrupt(path, "cell " + std::to_string(c.id) + " is born or dies at a time outside the run");
    last_death = std::max(last_death, c.death.time);
  }
  if (!m.cells.empty() && last_death != m.end.time)
    corrupt(path, "end_time " + std::to_string(m.end.time) + " is not the time the last cells die (" +
                      std::to_string(last_death) + ")");
  for (const BatchRecord& b : m.batches)
    if (!std::isfinite(b.time) || b.time > m.end.time)
      corrupt(path, "batch " + std::to_string(b.batch) + " has a time outside the run");
  for (const FrameRecord& f : m.frames)
    if (f.frame >= frames || !std::isfinite(f.time))
      corrupt(path, "frame record " + std::to_string(f.frame) + " is outside the run's " +
                        std::to_string(frames) + " frames");
  if (!m.run.run_id.empty() &&
      (m.run.run_id.size() != 32 || m.run.run_id.find_first_not_of("0123456789abcdef") != std::string::npos))
    corrupt(path, "run_id '" + m.run.run_id + "' is not 32 hexadecimal digits");
}

// One plain sentence for a path that cannot be a store at all (HDF5 would say more, and less clearly).
void check_is_file(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    corrupt(path, errno == ENOENT ? "no such file" : "cannot be read");
  if (S_ISDIR(st.st_mode))
    corrupt(path, "is a folder, not a store file (a CC3D run folder is read by `medusa run " + path +
                      " -o run.h5`, which writes the store the other commands read)");
  if (!S_ISREG(st.st_mode))
    corrupt(path, "is not a regular file");
}

} // namespace

Medusa read_store(const std::string& path, const StoreReadOptions& options) {
  check_is_file(path);
  h5::Quiet quiet;
  Handle file = h5::file_handle(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  if (!file.valid())
    h5::fail(path, "cannot open it (not an HDF5 file, or truncated or corrupt)");
  const hid_t f = file.get();
  const htri_t has_format = H5Aexists(f, L::format);
  if (has_format < 0)
    h5::fail(path, "cannot read the root group");
  if (has_format == 0 || h5::read_string_attribute(f, L::format, path) != L::format_name)
    corrupt(path, "not a medusa store (no format attribute \"medusa-store\")");
  const std::int64_t version = h5::read_int_attribute(f, L::format_version, path);
  if (version != store_format_version)
    corrupt(path, "format version " + std::to_string(version) + " is not supported (expected " +
                      std::to_string(store_format_version) + ")");
  const htri_t has_complete = H5Aexists(f, L::complete);
  if (has_complete < 0)
    h5::fail(path, "cannot read the root group");
  if (has_complete == 0 || h5::read_int_attribute(f, L::complete, path) != 1)
    corrupt(path, "incomplete (the writer did not finish)");

  Medusa m;
  m.run.radius = h5::read_double_attribute(f, L::radius, path);
  m.run.radius_text = h5::read_string_attribute(f, L::radius_text, path);
  m.run.source_files = h5::read_strings_attribute(f, L::source_files, path);
  if (has_attribute(f, L::input_warnings, path)) // absent from stores written before it existed
    m.run.input_warnings = h5::read_strings_attribute(f, L::input_warnings, path);
  m.run.command_line = h5::read_string_attribute(f, L::command_line, path);
  m.run.software_version = h5::read_string_attribute(f, L::software_version, path);
  // Absent from stores written before periodic runs were supported: those are open runs.
  if (has_attribute(f, L::periodic_axes, path)) {
    m.run.periodic_axes = h5::read_string_attribute(f, L::periodic_axes, path);
    for (std::size_t a = 0; a < 3; ++a)
      m.run.periodic_lengths[a] = h5::read_int_attribute(f, L::periodic_length[a], path);
  }
  // Stores written before these attributes existed leave them unknown.
  if (has_attribute(f, L::position_source, path)) {
    m.run.position_source = h5::read_string_attribute(f, L::position_source, path);
    m.run.snap_policy = h5::read_string_attribute(f, L::snap_policy, path);
    m.run.snapped_positions = h5::read_uint_attribute(f, L::snapped_positions, path);
    m.run.snap_max_displacement = h5::read_double_attribute(f, L::snap_max_displacement, path);
  }
  if (H5Aexists(f, L::run_id) > 0)
    m.run.run_id = h5::read_string_attribute(f, L::run_id, path);
  m.input.scale = h5::read_int_attribute(f, L::grid_scale, path);
  m.input.dimension = static_cast<int>(h5::read_int_attribute(f, L::dimension, path));
  const std::uint64_t end_batch = h5::read_uint_attribute(f, L::end_batch, path);
  if (end_batch > max_batch)
    corrupt(path, "end_batch " + std::to_string(end_batch) + " is above " + std::to_string(max_batch));
  m.end.batch = static_cast<std::uint32_t>(end_batch);
  m.end.rank = static_cast<std::uint32_t>(h5::read_uint_attribute(f, L::end_rank, path));
  m.end.time = h5::read_double_attribute(f, L::end_time, path);
  read_input(f, m, path);
  if (options.events) {
    const std::size_t batches = read_events(f, m, options.every_batch, path);
    if (batches != h5::read_uint_attribute(f, L::batch_count, path) ||
        m.frames.size() != h5::read_uint_attribute(f, L::frame_count, path))
      corrupt(path, "batch_count or frame_count does not match /events");
  }
  read_cells(f, m, h5::read_uint_attribute(f, L::cell_count, path), path);
  verify_other_datasets(f, options.events, path);
  if (!file.reset())
    h5::fail(path, "cannot close it");
  validate_run_facts(m, path);
  validate_medusa(m, path);
  return m;
}

} // namespace medusa
