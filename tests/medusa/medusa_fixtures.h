// Building medusas from recorded streams, and comparing them, for the medusa tests.
#pragma once

#include "medusa/medusa/cell_sink.h"
#include "medusa/medusa/complex_index.h"
#include "medusa/medusa/medusa.h"
#include "medusa/medusa/medusa_builder.h"
#include "stream.h"
#include "support/temp_files.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <unistd.h>

namespace medusa::test {

inline medusa::RunInfo test_run_info() {
  medusa::RunInfo info;
  info.radius = 1.05;
  info.radius_text = "1.05";
  info.source_files = {"run/Step_0000.vtk.gz", "run/Step_0010.vtk.gz"};
  info.input_warnings = {"run: the last frame read is MCS 10, but run.xml runs to MCS 100",
                         "run/Step_0005.vtk.gz: snapshot truncated; left out"};
  info.command_line = "medusa run --radius 1.05 run";
  info.software_version = "0.1.0-test";
  info.position_source = "vtk-centroids-voxel-corner";
  info.snap_policy = "nearest-ties-to-even";
  info.snapped_positions = 7;
  info.snap_max_displacement = 1.0 / 3.0;
  return info;
}

// Plays the stream into a builder feeding `sink`, with the test run metadata and a dummy input.
inline void play_into(const Stream& stream, medusa::CellSink& sink, std::size_t vertices,
                      std::size_t frames) {
  medusa::MedusaBuilder builder(sink);
  builder.set_run(test_run_info(), dummy_input(vertices, frames, {}));
  stream.play(builder);
}

inline medusa::Medusa collect(const Stream& stream, std::size_t vertices, std::size_t frames) {
  medusa::MedusaCollector collector;
  play_into(stream, collector, vertices, frames);
  return collector.take();
}

inline SimplexSet tuples(const medusa::Medusa& m, const std::vector<medusa::CellId>& ids) {
  SimplexSet out;
  for (medusa::CellId id : ids)
    out.insert(m.cell(id).vertices.to_vector());
  return out;
}

inline bool same_cell(const medusa::Cell& a, const medusa::Cell& b) {
  return a.id == b.id && a.vertices == b.vertices && a.birth == b.birth && a.death == b.death &&
         a.birth.time == b.birth.time && a.death.time == b.death.time && a.kind == b.kind &&
         a.facets == b.facets;
}

inline bool same_medusa(const medusa::Medusa& a, const medusa::Medusa& b) {
  if (a.cells.size() != b.cells.size() || a.batches.size() != b.batches.size() ||
      a.frames.size() != b.frames.size())
    return false;
  for (std::size_t i = 0; i < a.cells.size(); ++i)
    if (!same_cell(a.cells[i], b.cells[i]))
      return false;
  for (std::size_t i = 0; i < a.batches.size(); ++i) {
    const auto &x = a.batches[i], &y = b.batches[i];
    if (x.batch != y.batch || x.slab != y.slab || x.u != y.u || x.time != y.time ||
        x.at_frame != y.at_frame || x.ranks != y.ranks)
      return false;
  }
  for (std::size_t i = 0; i < a.frames.size(); ++i)
    if (a.frames[i].frame != b.frames[i].frame || a.frames[i].batch != b.frames[i].batch ||
        a.frames[i].time != b.frames[i].time)
      return false;
  if (a.end != b.end || a.end.time != b.end.time)
    return false;
  if (a.run.radius != b.run.radius || a.run.radius_text != b.run.radius_text ||
      a.run.source_files != b.run.source_files || a.run.input_warnings != b.run.input_warnings ||
      a.run.command_line != b.run.command_line || a.run.software_version != b.run.software_version ||
      a.run.position_source != b.run.position_source || a.run.snap_policy != b.run.snap_policy ||
      a.run.snapped_positions != b.run.snapped_positions ||
      a.run.snap_max_displacement != b.run.snap_max_displacement)
    return false;
  if (a.input.scale != b.input.scale || a.input.dimension != b.input.dimension ||
      a.input.frame_times != b.input.frame_times || a.input.type_names != b.input.type_names ||
      a.input.cells.size() != b.input.cells.size())
    return false;
  for (std::size_t i = 0; i < a.input.cells.size(); ++i) {
    const auto &x = a.input.cells[i], &y = b.input.cells[i];
    if (x.cell_id != y.cell_id || x.type != y.type || x.first_frame != y.first_frame ||
        x.positions != y.positions)
      return false;
  }
  return true;
}

} // namespace medusa::test
