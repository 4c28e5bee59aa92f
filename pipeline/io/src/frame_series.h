// Whether a run's frames are all there and whole: the checks shared by the VTK and CSV readers.
#pragma once

#include "medusa/io/cell_sample.h"
#include "medusa/io/run_reader.h"

#include <cstdint>
#include <string>
#include <vector>

namespace medusa::io::internal {

// A gap of an evenly saved series (at least half its gaps equal to its smallest, the step): frames
// k-1 and k are a multiple of the step apart, so the frames between them are missing.
struct SeriesGap {
  std::size_t k;
  std::int64_t step;
};
// The gaps of a series of increasing MCS (none with fewer than three frames, or no common step).
std::vector<SeriesGap> series_gaps(const std::vector<std::int64_t>& mcs);

// The rows of a CSV read whole, frame by frame: a frame holding fewer than half the rows of a
// neighbouring frame is incomplete (a file still being written, a mistyped MCS), and a frame
// missing from the middle of an evenly saved series is missing. Each is an InputError naming the
// file, the MCS and a line, or with options.skip_unreadable_frames a warning, the incomplete frames'
// rows then left out.
void check_csv_frames(std::vector<CellSample>& samples, const std::string& path, const RunOptions& options,
                      std::vector<std::string>& warnings);

} // namespace medusa::io::internal
