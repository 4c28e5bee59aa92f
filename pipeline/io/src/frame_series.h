// Whether a run's frames are all there and whole: the checks shared by the VTK and CSV readers.
#pragma once

#include "medusa/io/cell_sample.h"
#include "medusa/io/run_reader.h"

#include <cstdint>
#include <string>
#include <vector>

namespace medusa::io::internal {

// A gap of an evenly saved series (more than half its gaps equal to its smallest, the step): frames
// k-1 and k are a multiple of the step apart, between gaps of the step, so the frames between them are
// missing.
struct SeriesGap {
  std::size_t k;
  std::int64_t step;
};
std::vector<SeriesGap> series_gaps(const std::vector<std::int64_t>& mcs);

// The rows of a CSV read whole, frame by frame: a middle frame lacking more than half the cells
// present both before and after it (rows lost, an MCS mistyped), a last frame that stops part of the
// way through the one before, row for row (a file still being written), and a frame missing from an
// evenly saved series are each an InputError naming the file and the MCS, or with
// options.skip_unreadable_frames a warning, the incomplete frames' rows then left out.
void check_csv_frames(std::vector<CellSample>& samples, const std::string& path, const RunOptions& options,
                      std::vector<std::string>& warnings);

} // namespace medusa::io::internal
