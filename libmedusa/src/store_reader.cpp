#include "medusa/medusa/store_reader.h"

#include "hdf5_attributes.h"
#include "hdf5_errors.h"
#include "hdf5_handle.h"
#include "hdf5_read.h"
#include "store_layout.h"

#include "medusa/core/error.h"
#include "medusa/medusa/store_writer.h"

#include <string>

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
    for (std::uint64_t r = offsets[i]; r < offsets[i + 1]; ++r)
      t.positions.push_back({positions[3 * r], positions[3 * r + 1], positions[3 * r + 2]});
  }
}

void read_events(hid_t file, Medusa& m, const std::string& path) {
  Handle g = open_group(file, L::events, path);
  const std::string gn = L::events;
  const auto index = h5::read_column<std::uint64_t>(g.get(), gn, L::batch_index, path);
  const auto slab = h5::read_column<std::uint64_t>(g.get(), gn, L::batch_slab, path);
  const auto u = h5::read_column<double>(g.get(), gn, L::batch_u, path);
  const auto time = h5::read_column<double>(g.get(), gn, L::batch_time, path);
  const auto at_frame = h5::read_column<std::uint8_t>(g.get(), gn, L::batch_at_frame, path);
  const auto ranks = h5::read_column<std::uint32_t>(g.get(), gn, L::batch_ranks, path);
  const std::size_t nb = index.size();
  if (slab.size() != nb || u.size() != nb || time.size() != nb || at_frame.size() != nb || ranks.size() != nb)
    corrupt(path, "the batch datasets of /events have different lengths");
  for (std::size_t i = 0; i < nb; ++i)
    m.batches.push_back({index[i], slab[i], u[i], time[i], at_frame[i] != 0, ranks[i]});
  const auto frame = h5::read_column<std::uint64_t>(g.get(), gn, L::frame_index, path);
  const auto frame_batch = h5::read_column<std::uint64_t>(g.get(), gn, L::frame_batch, path);
  const auto frame_time = h5::read_column<double>(g.get(), gn, L::frame_time, path);
  if (frame_batch.size() != frame.size() || frame_time.size() != frame.size())
    corrupt(path, "the frame datasets of /events have different lengths");
  for (std::size_t i = 0; i < frame.size(); ++i)
    m.frames.push_back({frame[i], frame_batch[i], frame_time[i]});
}

void read_cells(hid_t file, Medusa& m, std::uint64_t count, const std::string& path) {
  Handle g = open_group(file, L::cells, path);
  const std::string gn = L::cells;
  const auto id = h5::read_column<std::uint64_t>(g.get(), gn, L::cell_id, path);
  const std::size_t n = id.size();
  if (n != count)
    corrupt(path,
            "/cells/id has " + std::to_string(n) + " entries but cell_count is " + std::to_string(count));
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
    c.birth = VirtualTime{bb[i], br[i], bt[i]};
    c.death = VirtualTime{db[i], dr[i], dt[i]};
    c.vertices.assign(vertices.begin() + static_cast<std::ptrdiff_t>(voff[i]),
                      vertices.begin() + static_cast<std::ptrdiff_t>(voff[i + 1]));
    c.facets.assign(facets.begin() + static_cast<std::ptrdiff_t>(foff[i]),
                    facets.begin() + static_cast<std::ptrdiff_t>(foff[i + 1]));
  }
}

} // namespace

Medusa read_store(const std::string& path, const StoreReadOptions& options) {
  h5::Quiet quiet;
  Handle file = h5::file_handle(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  if (!file.valid())
    h5::fail(path, "cannot open it (missing, not an HDF5 file, truncated or corrupt)");
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
  m.input.scale = h5::read_int_attribute(f, L::grid_scale, path);
  m.input.dimension = static_cast<int>(h5::read_int_attribute(f, L::dimension, path));
  m.end.batch = h5::read_uint_attribute(f, L::end_batch, path);
  m.end.rank = static_cast<std::uint32_t>(h5::read_uint_attribute(f, L::end_rank, path));
  m.end.time = h5::read_double_attribute(f, L::end_time, path);
  read_input(f, m, path);
  if (options.events) {
    read_events(f, m, path);
    if (m.batches.size() != h5::read_uint_attribute(f, L::batch_count, path) ||
        m.frames.size() != h5::read_uint_attribute(f, L::frame_count, path))
      corrupt(path, "batch_count or frame_count does not match /events");
  }
  read_cells(f, m, h5::read_uint_attribute(f, L::cell_count, path), path);
  if (!file.reset())
    h5::fail(path, "cannot close it");
  validate_medusa(m, path);
  return m;
}

} // namespace medusa
