// Names of the groups, datasets and attributes of the store (docs/FORMAT.md is the specification).
#pragma once

namespace medusa::layout {

inline constexpr const char* format_name = "medusa-store";

// Root attributes.
inline constexpr const char* format = "format";
inline constexpr const char* format_version = "format_version";
inline constexpr const char* complete = "complete";
inline constexpr const char* radius = "radius";
inline constexpr const char* radius_text = "radius_text";
inline constexpr const char* grid_scale = "grid_scale";
inline constexpr const char* dimension = "dimension";
inline constexpr const char* source_files = "source_files";
inline constexpr const char* input_warnings = "input_warnings";
inline constexpr const char* command_line = "command_line";
inline constexpr const char* periodic_axes = "periodic_axes";
inline constexpr const char* periodic_length[3] = {"periodic_length_x", "periodic_length_y",
                                                   "periodic_length_z"};
inline constexpr const char* software_version = "software_version";
inline constexpr const char* position_source = "position_source";
inline constexpr const char* snap_policy = "snap_policy";
inline constexpr const char* snapped_positions = "snapped_positions";
inline constexpr const char* snap_max_displacement = "snap_max_displacement";
inline constexpr const char* run_id = "run_id";
inline constexpr const char* cell_count = "cell_count";
inline constexpr const char* batch_count = "batch_count";
inline constexpr const char* frame_count = "frame_count";
inline constexpr const char* end_batch = "end_batch";
inline constexpr const char* end_rank = "end_rank";
inline constexpr const char* end_time = "end_time";

// /input
inline constexpr const char* input = "input";
inline constexpr const char* type_names = "type_names";
inline constexpr const char* input_cell_id = "cell_id";
inline constexpr const char* input_cell_type = "cell_type";
inline constexpr const char* input_first_frame = "first_frame";
inline constexpr const char* input_position_offset = "position_offset";
inline constexpr const char* input_positions = "positions";
inline constexpr const char* input_frame_times = "frame_times";

// /events
inline constexpr const char* events = "events";
inline constexpr const char* batch_index = "batch_index";
inline constexpr const char* batch_slab = "batch_slab";
inline constexpr const char* batch_u = "batch_u";
inline constexpr const char* batch_time = "batch_time";
inline constexpr const char* batch_at_frame = "batch_at_frame";
inline constexpr const char* batch_ranks = "batch_ranks";
inline constexpr const char* frame_index = "frame_index";
inline constexpr const char* frame_batch = "frame_batch";
inline constexpr const char* frame_time = "frame_time";

// /cells
inline constexpr const char* cells = "cells";
inline constexpr const char* cell_id = "id";
inline constexpr const char* kind = "kind";
inline constexpr const char* birth_batch = "birth_batch";
inline constexpr const char* birth_rank = "birth_rank";
inline constexpr const char* birth_time = "birth_time";
inline constexpr const char* death_batch = "death_batch";
inline constexpr const char* death_rank = "death_rank";
inline constexpr const char* death_time = "death_time";
inline constexpr const char* vertex_offset = "vertex_offset";
inline constexpr const char* vertices = "vertices";
inline constexpr const char* facet_offset = "facet_offset";
inline constexpr const char* facets = "facets";

} // namespace medusa::layout
