#include "medusa/medusa/store_writer.h"

#include "medusa/medusa/internal/hdf5_attributes.h"
#include "medusa/medusa/internal/hdf5_column.h"
#include "medusa/medusa/internal/hdf5_errors.h"
#include "medusa/medusa/internal/hdf5_handle.h"
#include "store_layout.h"

#include "medusa/core/error.h"

#include <cstdio>
#include <optional>
#include <unistd.h>

namespace medusa {

namespace L = layout;
using h5::Column;
using h5::Handle;

namespace {

Handle create_group(hid_t file, const char* name, const std::string& path) {
  Handle g = h5::group_handle(H5Gcreate2(file, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  if (!g.valid())
    h5::fail(path, std::string("cannot create group /") + name);
  return g;
}

} // namespace

struct StoreWriter::Impl {
  std::string path;
  std::string temporary;
  Handle file;
  Handle events;
  Handle cells;
  bool run_written = false;
  bool finished = false;
  bool failed = false;
  Publish publish = Publish::on_finish;

  // /events
  std::optional<Column<std::uint64_t>> batch_index, batch_slab, frame_index, frame_batch;
  std::optional<Column<double>> batch_u, batch_time, frame_time;
  std::optional<Column<std::uint8_t>> batch_at_frame;
  std::optional<Column<std::uint32_t>> batch_ranks;
  // /cells
  std::optional<Column<std::uint64_t>> id, birth_batch, death_batch, vertex_offset, facet_offset, facets;
  std::optional<Column<std::uint32_t>> birth_rank, death_rank;
  std::optional<Column<double>> birth_time, death_time;
  std::optional<Column<std::uint8_t>> kind;
  std::optional<Column<std::int32_t>> vertices;
  std::uint64_t vertex_entries = 0;
  std::uint64_t facet_entries = 0;

  // Closes every dataset and group (not the file), innermost first.
  void close_objects() {
    batch_index.reset();
    batch_slab.reset();
    batch_u.reset();
    batch_time.reset();
    batch_at_frame.reset();
    batch_ranks.reset();
    frame_index.reset();
    frame_batch.reset();
    frame_time.reset();
    id.reset();
    kind.reset();
    birth_batch.reset();
    birth_rank.reset();
    birth_time.reset();
    death_batch.reset();
    death_rank.reset();
    death_time.reset();
    vertex_offset.reset();
    vertices.reset();
    facet_offset.reset();
    facets.reset();
    events.reset();
    cells.reset();
  }

  // Runs `f`; on StoreError marks the writer failed (its destructor then removes the temporary file).
  template <class F> void guarded(F&& f) {
    if (failed)
      throw StoreError("store " + path + ": the writer failed earlier");
    if (finished)
      throw InternalError("store " + path + ": written after finish");
    h5::Quiet quiet;
    try {
      f();
    } catch (...) {
      failed = true;
      throw;
    }
  }
};

StoreWriter::StoreWriter(const std::string& path, Publish publish) : impl_(std::make_unique<Impl>()) {
  Impl& w = *impl_;
  w.path = path;
  w.publish = publish;
  w.temporary = path + ".tmp-" + std::to_string(static_cast<long long>(::getpid()));
  h5::Quiet quiet;
  // Format 1.10 objects: every object header, B-tree and chunk index carries a checksum, so a flipped
  // byte in the metadata is detected rather than read as data.
  Handle fapl = h5::plist_handle(H5Pcreate(H5P_FILE_ACCESS));
  if (!fapl.valid() || H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_V110, H5F_LIBVER_V110) < 0 ||
      H5Pset_fclose_degree(fapl.get(), H5F_CLOSE_STRONG) < 0)
    h5::fail(path, "cannot set up file access");
  w.file = h5::file_handle(H5Fcreate(w.temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()));
  if (!w.file.valid())
    h5::fail(path, "cannot create " + w.temporary);
  try {
    const hid_t f = w.file.get();
    h5::write_attribute(f, L::format, std::string(L::format_name), path);
    h5::write_attribute(f, L::format_version, static_cast<std::int64_t>(store_format_version), path);
    w.events = create_group(f, L::events, path);
    w.cells = create_group(f, L::cells, path);
    const hid_t e = w.events.get();
    const hid_t c = w.cells.get();
    w.batch_index.emplace(e, L::batch_index, path);
    w.batch_slab.emplace(e, L::batch_slab, path);
    w.batch_u.emplace(e, L::batch_u, path);
    w.batch_time.emplace(e, L::batch_time, path);
    w.batch_at_frame.emplace(e, L::batch_at_frame, path);
    w.batch_ranks.emplace(e, L::batch_ranks, path);
    w.frame_index.emplace(e, L::frame_index, path);
    w.frame_batch.emplace(e, L::frame_batch, path);
    w.frame_time.emplace(e, L::frame_time, path);
    w.id.emplace(c, L::cell_id, path);
    w.kind.emplace(c, L::kind, path);
    w.birth_batch.emplace(c, L::birth_batch, path);
    w.birth_rank.emplace(c, L::birth_rank, path);
    w.birth_time.emplace(c, L::birth_time, path);
    w.death_batch.emplace(c, L::death_batch, path);
    w.death_rank.emplace(c, L::death_rank, path);
    w.death_time.emplace(c, L::death_time, path);
    w.vertex_offset.emplace(c, L::vertex_offset, path);
    w.vertices.emplace(c, L::vertices, path);
    w.facet_offset.emplace(c, L::facet_offset, path);
    w.facets.emplace(c, L::facets, path);
    w.vertex_offset->push(0);
    w.facet_offset->push(0);
  } catch (...) {
    w.failed = true;
    w.close_objects();
    w.file.reset();
    std::remove(w.temporary.c_str());
    throw;
  }
}

StoreWriter::~StoreWriter() {
  Impl& w = *impl_;
  if (w.finished)
    return;
  h5::Quiet quiet;
  // Close every dataset before the file, then delete the unfinished file: no partial store remains.
  w.close_objects();
  w.file.reset();
  std::remove(w.temporary.c_str());
}

const std::string& StoreWriter::path() const { return impl_->path; }
const std::string& StoreWriter::temporary_path() const { return impl_->temporary; }

void StoreWriter::run(const RunInfo& info, const kinetic::Trajectories& input) {
  Impl& w = *impl_;
  w.guarded([&] {
    if (w.run_written)
      throw InternalError("store " + w.path + ": run metadata given twice");
    w.run_written = true;
    const hid_t f = w.file.get();
    h5::write_attribute(f, L::radius, info.radius, w.path);
    h5::write_attribute(f, L::radius_text, info.radius_text, w.path);
    h5::write_attribute(f, L::grid_scale, static_cast<std::int64_t>(input.scale), w.path);
    h5::write_attribute(f, L::dimension, static_cast<std::int64_t>(input.dimension), w.path);
    h5::write_attribute(f, L::source_files, info.source_files, w.path);
    h5::write_attribute(f, L::input_warnings, info.input_warnings, w.path);
    h5::write_attribute(f, L::command_line, info.command_line, w.path);
    h5::write_attribute(f, L::software_version, info.software_version, w.path);
    h5::write_attribute(f, L::periodic_axes, info.periodic_axes, w.path);
    for (std::size_t a = 0; a < 3; ++a)
      h5::write_attribute(f, L::periodic_length[a], info.periodic_lengths[a], w.path);
    h5::write_attribute(f, L::position_source, info.position_source, w.path);
    h5::write_attribute(f, L::snap_policy, info.snap_policy, w.path);
    h5::write_attribute(f, L::snapped_positions, info.snapped_positions, w.path);
    h5::write_attribute(f, L::snap_max_displacement, info.snap_max_displacement, w.path);
    if (!info.run_id.empty())
      h5::write_attribute(f, L::run_id, info.run_id, w.path);

    Handle g = create_group(f, L::input, w.path);
    h5::write_attribute(g.get(), L::type_names, input.type_names, w.path);
    Column<std::int64_t> cell_id(g.get(), L::input_cell_id, w.path);
    Column<std::int32_t> cell_type(g.get(), L::input_cell_type, w.path);
    Column<std::uint64_t> first_frame(g.get(), L::input_first_frame, w.path);
    Column<std::uint64_t> offset(g.get(), L::input_position_offset, w.path);
    Column<std::int64_t> positions(g.get(), L::input_positions, w.path, 3);
    Column<std::int64_t> frame_times(g.get(), L::input_frame_times, w.path);
    std::uint64_t rows = 0;
    offset.push(0);
    for (const kinetic::Trajectory& t : input.cells) {
      cell_id.push(t.cell_id);
      cell_type.push(static_cast<std::int32_t>(t.type));
      first_frame.push(t.first_frame);
      for (const kinetic::GridPoint& p : t.positions)
        for (std::int64_t x : p)
          positions.push(x);
      rows += t.positions.size();
      offset.push(rows);
    }
    for (std::int64_t t : input.frame_times)
      frame_times.push(t);
    cell_id.flush();
    cell_type.flush();
    first_frame.flush();
    offset.flush();
    positions.flush();
    frame_times.flush();
  });
}

void StoreWriter::batch(const BatchRecord& b) {
  Impl& w = *impl_;
  w.guarded([&] {
    w.batch_index->push(b.batch);
    w.batch_slab->push(b.slab);
    w.batch_u->push(b.u);
    w.batch_time->push(b.time);
    w.batch_at_frame->push(b.at_frame ? 1 : 0);
    w.batch_ranks->push(b.ranks);
  });
}

void StoreWriter::frame(const FrameRecord& fr) {
  Impl& w = *impl_;
  w.guarded([&] {
    w.frame_index->push(fr.frame);
    w.frame_batch->push(fr.batch);
    w.frame_time->push(fr.time);
  });
}

void StoreWriter::cell(const Cell& c) {
  Impl& w = *impl_;
  w.guarded([&] {
    w.id->push(c.id);
    w.kind->push(static_cast<std::uint8_t>(c.kind));
    w.birth_batch->push(c.birth.batch);
    w.birth_rank->push(c.birth.rank);
    w.birth_time->push(c.birth.time);
    w.death_batch->push(c.death.batch);
    w.death_rank->push(c.death.rank);
    w.death_time->push(c.death.time);
    for (VertexId v : c.vertices)
      w.vertices->push(v);
    w.vertex_entries += c.vertices.size();
    w.vertex_offset->push(w.vertex_entries);
    for (CellId f : c.facets)
      w.facets->push(f);
    w.facet_entries += c.facets.size();
    w.facet_offset->push(w.facet_entries);
  });
}

void StoreWriter::finish(const VirtualTime& end) {
  Impl& w = *impl_;
  w.guarded([&] {
    if (!w.run_written)
      throw InternalError("store " + w.path + ": finished without run metadata and input");
    for (auto* c : {&*w.batch_index, &*w.batch_slab, &*w.frame_index, &*w.frame_batch, &*w.id,
                    &*w.birth_batch, &*w.death_batch, &*w.vertex_offset, &*w.facet_offset, &*w.facets})
      c->flush();
    for (auto* c : {&*w.batch_u, &*w.batch_time, &*w.frame_time, &*w.birth_time, &*w.death_time})
      c->flush();
    for (auto* c : {&*w.batch_ranks, &*w.birth_rank, &*w.death_rank})
      c->flush();
    w.batch_at_frame->flush();
    w.kind->flush();
    w.vertices->flush();
    const hid_t f = w.file.get();
    h5::write_attribute(f, L::cell_count, static_cast<std::uint64_t>(w.id->size()), w.path);
    h5::write_attribute(f, L::batch_count, static_cast<std::uint64_t>(w.batch_index->size()), w.path);
    h5::write_attribute(f, L::frame_count, static_cast<std::uint64_t>(w.frame_index->size()), w.path);
    h5::write_attribute(f, L::end_batch, static_cast<std::uint64_t>(end.batch), w.path);
    h5::write_attribute(f, L::end_rank, static_cast<std::uint64_t>(end.rank), w.path);
    h5::write_attribute(f, L::end_time, end.time, w.path);
    if (H5Fflush(f, H5F_SCOPE_GLOBAL) < 0)
      h5::fail(w.path, "cannot flush " + w.temporary);
    // Written last: a store without it was not finished (docs/FORMAT.md).
    h5::write_attribute(f, L::complete, static_cast<std::int64_t>(1), w.path);
    w.close_objects();
    if (!w.file.reset())
      h5::fail(w.path, "cannot close " + w.temporary);
    if (w.publish == Publish::on_finish && std::rename(w.temporary.c_str(), w.path.c_str()) != 0)
      throw StoreError("store " + w.path + ": cannot rename " + w.temporary + " to it");
  });
  w.finished = true;
}

void skip_hdf5_cleanup_at_exit() { H5dont_atexit(); }

void write_store(const std::string& path, const Medusa& medusa) {
  StoreWriter writer(path);
  writer.run(medusa.run, medusa.input);
  for (const BatchRecord& b : medusa.batches)
    writer.batch(b);
  for (const FrameRecord& f : medusa.frames)
    writer.frame(f);
  for (const Cell& c : medusa.cells)
    writer.cell(c);
  writer.finish(medusa.end);
}

} // namespace medusa
