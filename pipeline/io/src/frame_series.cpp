#include "frame_series.h"

#include "medusa/core/error.h"

#include <algorithm>
#include <map>
#include <set>

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
  // Evenly saved: more than half its gaps are the step. A series saved at MCS 0, 10, 100, 1000, or
  // every 100 MCS and then every 10, is not.
  std::size_t even = 0;
  for (std::size_t k = 1; k < mcs.size(); ++k)
    even += mcs[k] - mcs[k - 1] == step ? 1 : 0;
  if (2 * even <= mcs.size() - 1)
    return gaps;
  // A hole: a multiple of the step between gaps of the step (or the series' end).
  const auto gap = [&](std::size_t k) { return k >= 1 && k < mcs.size() ? mcs[k] - mcs[k - 1] : step; };
  for (std::size_t k = 1; k < mcs.size(); ++k)
    if (gap(k) != step && gap(k) % step == 0 && gap(k - 1) == step && gap(k + 1) == step)
      gaps.push_back({k, step});
  return gaps;
}

namespace {

struct Frame {
  std::int64_t mcs = 0;
  std::vector<std::int64_t> ids; // in the file's order
  std::int64_t first_line = 0, last_line = 0;
};

std::string rows_text(const Frame& f) {
  const std::size_t n = f.ids.size();
  return std::to_string(n) +
         (n == 1 ? " row (line " + std::to_string(f.first_line)
                 : " rows (lines " + std::to_string(f.first_line) + " to " + std::to_string(f.last_line)) +
         ")";
}

// Frame k is missing most of the cells present both before and after it, and at least half those of the
// frame before: rows lost, or an MCS mistyped on a few rows (which then form a frame of their own).
// Cells that divide or die do not come back.
bool lacks_most_lasting_cells(const std::vector<Frame>& frames, std::size_t k, std::size_t& lacking,
                              std::size_t& lasting) {
  const std::set<std::int64_t> here(frames[k].ids.begin(), frames[k].ids.end());
  const std::set<std::int64_t> after(frames[k + 1].ids.begin(), frames[k + 1].ids.end());
  lacking = lasting = 0;
  for (std::int64_t id : frames[k - 1].ids)
    if (after.count(id)) {
      ++lasting;
      lacking += here.count(id) ? 0 : 1;
    }
  // Half the cells of the frame before, too: a frame next to a stray one shares few cells with it.
  return 2 * lacking > lasting && 2 * lacking >= frames[k - 1].ids.size();
}

// The last frame stops part of the way through the one before it, row for row: a file still being
// written (a simulation writes its cells in the same order at every frame). At least two rows short,
// so that the death of the last-listed cell alone is not taken for it.
bool stops_partway(const Frame& before, const Frame& last) {
  return last.ids.size() + 2 <= before.ids.size() &&
         std::equal(last.ids.begin(), last.ids.end(), before.ids.begin());
}

} // namespace

void check_csv_frames(std::vector<CellSample>& samples, const std::string& path, const RunOptions& options,
                      std::vector<std::string>& warnings) {
  std::map<std::int64_t, Frame> by_mcs;
  for (const CellSample& s : samples) {
    Frame& f = by_mcs[s.mcs];
    f.mcs = s.mcs;
    f.first_line = f.ids.empty() ? s.line : std::min(f.first_line, s.line);
    f.last_line = std::max(f.last_line, s.line);
    f.ids.push_back(s.cell_id);
  }
  std::vector<Frame> frames;
  for (auto& entry : by_mcs)
    frames.push_back(std::move(entry.second));
  const std::string go_on =
      " (rerun with " + options.spellings.skip_unreadable_frames + " to go on without it)";

  std::vector<std::int64_t> incomplete, mcs;
  const auto refuse_or_leave_out = [&](const Frame& f, const std::string& what) {
    if (!options.skip_unreadable_frames)
      throw InputError(what + go_on);
    warnings.push_back(what + "; left out");
    incomplete.push_back(f.mcs);
  };
  for (std::size_t k = 1; k + 1 < frames.size(); ++k) {
    std::size_t lacking = 0, lasting = 0;
    if (lacks_most_lasting_cells(frames, k, lacking, lasting))
      refuse_or_leave_out(frames[k], path + ": MCS " + std::to_string(frames[k].mcs) + " lacks " +
                                         std::to_string(lacking) + " of the " + std::to_string(lasting) +
                                         " cells present at MCS " + std::to_string(frames[k - 1].mcs) +
                                         " and MCS " + std::to_string(frames[k + 1].mcs) + ", with " +
                                         rows_text(frames[k]) +
                                         ": an incomplete frame (rows lost, or an MCS mistyped)");
  }
  if (frames.size() >= 2 && stops_partway(frames[frames.size() - 2], frames.back())) {
    const Frame &before = frames[frames.size() - 2], &last = frames.back();
    refuse_or_leave_out(last, path + ": the last frame, MCS " + std::to_string(last.mcs) + ", stops after " +
                                  rows_text(last) + " where MCS " + std::to_string(before.mcs) + " has " +
                                  std::to_string(before.ids.size()) +
                                  " in the same order: a file still being written");
  }
  // The series without the frames left out; a gap where one of them was is said already.
  std::sort(incomplete.begin(), incomplete.end());
  for (const Frame& f : frames)
    if (!std::binary_search(incomplete.begin(), incomplete.end(), f.mcs))
      mcs.push_back(f.mcs);
  for (const SeriesGap& g : series_gaps(mcs)) {
    if (std::upper_bound(incomplete.begin(), incomplete.end(), mcs[g.k - 1]) !=
        std::lower_bound(incomplete.begin(), incomplete.end(), mcs[g.k]))
      continue;
    const std::string what = path + ": no row has MCS " + std::to_string(mcs[g.k - 1] + g.step) +
                             ": the frames go from MCS " + std::to_string(mcs[g.k - 1]) + " to MCS " +
                             std::to_string(mcs[g.k]) + ", every " + std::to_string(g.step) +
                             " MCS elsewhere";
    if (!options.skip_unreadable_frames)
      throw InputError(what + go_on);
    warnings.push_back(what);
  }
  if (!incomplete.empty())
    samples.erase(std::remove_if(samples.begin(), samples.end(),
                                 [&](const CellSample& s) {
                                   return std::binary_search(incomplete.begin(), incomplete.end(), s.mcs);
                                 }),
                  samples.end());
}

} // namespace medusa::io::internal
