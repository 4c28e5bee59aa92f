#include "frame_series.h"

#include "medusa/core/error.h"

#include <algorithm>
#include <map>

namespace medusa::io::internal {

std::vector<SeriesGap> series_gaps(const std::vector<std::int64_t>& mcs) {
  std::vector<SeriesGap> gaps;
  if (mcs.size() < 3)
    return gaps;
  std::int64_t step = mcs[1] - mcs[0];
  for (std::size_t k = 1; k < mcs.size(); ++k)
    step = std::min(step, mcs[k] - mcs[k - 1]);
  if (step <= 0)
    return gaps;
  // Evenly saved: at least half its gaps are the step. A series saved at MCS 0, 10, 100, 1000 is not.
  std::size_t even = 0;
  for (std::size_t k = 1; k < mcs.size(); ++k)
    even += mcs[k] - mcs[k - 1] == step ? 1 : 0;
  if (2 * even < mcs.size() - 1)
    return gaps;
  for (std::size_t k = 1; k < mcs.size(); ++k) {
    const std::int64_t gap = mcs[k] - mcs[k - 1];
    if (gap != step && gap % step == 0)
      gaps.push_back({k, step});
  }
  return gaps;
}

namespace {

struct FrameRows {
  std::int64_t mcs = 0;
  std::size_t rows = 0;
  std::int64_t first_line = 0, last_line = 0;
};

std::string rows_text(std::size_t n) { return std::to_string(n) + (n == 1 ? " row" : " rows"); }

} // namespace

void check_csv_frames(std::vector<CellSample>& samples, const std::string& path, const RunOptions& options,
                      std::vector<std::string>& warnings) {
  std::map<std::int64_t, FrameRows> by_mcs;
  for (const CellSample& s : samples) {
    FrameRows& f = by_mcs[s.mcs];
    f.mcs = s.mcs;
    f.first_line = f.rows == 0 ? s.line : std::min(f.first_line, s.line);
    f.last_line = std::max(f.last_line, s.line);
    ++f.rows;
  }
  std::vector<FrameRows> frames;
  for (const auto& entry : by_mcs)
    frames.push_back(entry.second);
  const std::string go_on =
      " (rerun with " + options.spellings.skip_unreadable_frames + " to go on without it)";

  // Cells divide and die a few at a time; a frame with fewer than half the rows of a frame beside it
  // was cut (the last one of a run still writing its CSV) or holds rows whose MCS is mistyped.
  std::vector<std::int64_t> incomplete;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const FrameRows* fuller = nullptr;
    for (const std::size_t j : {k - 1, k + 1})
      if (j < frames.size() && (fuller == nullptr || frames[j].rows > fuller->rows))
        fuller = &frames[j];
    if (fuller == nullptr || 2 * frames[k].rows >= fuller->rows)
      continue;
    const FrameRows& f = frames[k];
    const std::string what =
        path + ": MCS " + std::to_string(f.mcs) + " has " + rows_text(f.rows) +
        (f.rows > 1 ? " (lines " + std::to_string(f.first_line) + " to " + std::to_string(f.last_line)
                    : " (line " + std::to_string(f.first_line)) +
        ") where MCS " + std::to_string(fuller->mcs) + " has " + std::to_string(fuller->rows) +
        ": an incomplete frame (a file still being written, or a mistyped MCS)";
    if (!options.skip_unreadable_frames)
      throw InputError(what + go_on);
    warnings.push_back(what + "; left out");
    incomplete.push_back(f.mcs);
  }
  if (!incomplete.empty()) {
    samples.erase(std::remove_if(samples.begin(), samples.end(),
                                 [&](const CellSample& s) {
                                   return std::binary_search(incomplete.begin(), incomplete.end(), s.mcs);
                                 }),
                  samples.end());
    frames.erase(std::remove_if(frames.begin(), frames.end(),
                                [&](const FrameRows& f) {
                                  return std::binary_search(incomplete.begin(), incomplete.end(), f.mcs);
                                }),
                 frames.end());
  }

  std::vector<std::int64_t> mcs;
  for (const FrameRows& f : frames)
    mcs.push_back(f.mcs);
  for (const SeriesGap& g : series_gaps(mcs)) {
    const std::string what = path + ": no row has MCS " + std::to_string(mcs[g.k - 1] + g.step) +
                             ": the frames go from MCS " + std::to_string(mcs[g.k - 1]) + " to MCS " +
                             std::to_string(mcs[g.k]) + ", every " + std::to_string(g.step) +
                             " MCS elsewhere";
    if (!options.skip_unreadable_frames)
      throw InputError(what + go_on);
    warnings.push_back(what);
  }
}

} // namespace medusa::io::internal
