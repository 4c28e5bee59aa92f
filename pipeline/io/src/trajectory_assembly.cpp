#include "medusa/io/trajectory_assembly.h"

#include "medusa/core/error.h"

#include <algorithm>
#include <tuple>

namespace medusa::io {

namespace {

std::string location(const CellSample& s, const std::vector<std::string>& sources) {
  std::string where = s.source < sources.size() ? sources[s.source] : std::string("<input>");
  if (s.line > 0)
    where += ":" + std::to_string(s.line);
  return where;
}

} // namespace

AssembledRun assemble_trajectories(std::vector<CellSample> samples, const std::vector<std::string>& sources,
                                   std::int64_t scale, int dimension, std::vector<std::int64_t> frame_times) {
  AssembledRun run;
  kinetic::Trajectories& t = run.trajectories;
  t.scale = scale;
  t.dimension = dimension;
  if (frame_times.empty())
    for (const CellSample& s : samples)
      frame_times.push_back(s.mcs);
  std::sort(frame_times.begin(), frame_times.end());
  frame_times.erase(std::unique(frame_times.begin(), frame_times.end()), frame_times.end());
  t.frame_times = frame_times;

  std::sort(samples.begin(), samples.end(), [](const CellSample& a, const CellSample& b) {
    return std::tie(a.cell_id, a.mcs, a.source, a.line) < std::tie(b.cell_id, b.mcs, b.source, b.line);
  });
  const bool have_volumes =
      !samples.empty() &&
      std::all_of(samples.begin(), samples.end(), [](const CellSample& s) { return s.volume >= 0; });

  std::vector<std::int64_t> single_frame_ids;
  std::size_t i = 0;
  while (i < samples.size()) {
    const CellSample& first = samples[i];
    std::size_t previous_frame = 0;
    bool open = false;
    for (; i < samples.size() && samples[i].cell_id == first.cell_id; ++i) {
      const CellSample& s = samples[i];
      const auto at = std::lower_bound(frame_times.begin(), frame_times.end(), s.mcs);
      if (at == frame_times.end() || *at != s.mcs)
        throw InputError(location(s, sources) + ": cell " + std::to_string(s.cell_id) + " at MCS " +
                         std::to_string(s.mcs) + " which is not a frame of the run");
      const std::size_t frame = static_cast<std::size_t>(at - frame_times.begin());
      if (s.type != first.type)
        throw InputError(location(s, sources) + ": cell " + std::to_string(s.cell_id) + " has type " +
                         std::to_string(s.type) + " at MCS " + std::to_string(s.mcs) + " but type " +
                         std::to_string(first.type) + " at MCS " + std::to_string(first.mcs) + " (" +
                         location(first, sources) + ")");
      if (open && frame == previous_frame)
        throw InputError(location(s, sources) + ": duplicate entry for cell " + std::to_string(s.cell_id) +
                         " at MCS " + std::to_string(s.mcs) + " (first at " +
                         location(samples[i - 1], sources) + ")");
      if (!open || frame != previous_frame + 1) {
        if (open)
          run.warnings.push_back("cell " + std::to_string(s.cell_id) + " is missing from MCS " +
                                 std::to_string(frame_times[previous_frame + 1]) + " to " +
                                 std::to_string(frame_times[frame - 1]) +
                                 ": split into separate trajectories (docs/MATH.md §2.1)");
        kinetic::Trajectory traj;
        traj.cell_id = s.cell_id;
        traj.type = s.type;
        traj.first_frame = frame;
        t.cells.push_back(std::move(traj));
        if (have_volumes)
          run.volumes.emplace_back();
        open = true;
      }
      t.cells.back().positions.push_back(s.position);
      if (have_volumes)
        run.volumes.back().push_back(s.volume);
      previous_frame = frame;
    }
  }
  // The lists grew by doubling, up to 1.6 times their frames for a 20-frame run, and the trajectories
  // are held through the kinetic stage, whose peak is at its start.
  for (kinetic::Trajectory& c : t.cells)
    c.positions.shrink_to_fit();
  for (std::vector<std::int64_t>& v : run.volumes)
    v.shrink_to_fit();
  // Cells present at one frame only: at an earlier frame they are inserted and deleted in that frame's
  // batch; at the last frame they are outside K(t_end-), the state the run ends with, and t_end gets
  // no instant cells (docs/MATH.md §2.1, §5.6, §6.2), so they add nothing to the medusa. Both are said.
  std::vector<std::int64_t> last_frame_ids;
  const std::size_t last = frame_times.size() - 1;
  for (const kinetic::Trajectory& c : t.cells)
    if (c.positions.size() == 1 && frame_times.size() > 1)
      (c.first_frame == last ? last_frame_ids : single_frame_ids).push_back(c.cell_id);
  auto listed = [](const std::vector<std::int64_t>& ids) {
    std::string text;
    for (std::size_t k = 0; k < ids.size() && k < 10; ++k)
      text += (k ? ", " : "") + std::to_string(ids[k]);
    return text + (ids.size() > 10 ? ", ..." : "");
  };
  if (!single_frame_ids.empty())
    run.warnings.push_back(std::to_string(single_frame_ids.size()) +
                           (single_frame_ids.size() == 1 ? " trajectory is" : " trajectories are") +
                           " present on a single frame (cells " + listed(single_frame_ids) +
                           "): each joins and leaves the complex at that frame (docs/MATH.md §2.1, §5.6)");
  if (!last_frame_ids.empty())
    run.warnings.push_back(std::to_string(last_frame_ids.size()) +
                           (last_frame_ids.size() == 1 ? " trajectory is" : " trajectories are") +
                           " present at the last frame only (cells " + listed(last_frame_ids) +
                           "): the analysis ends at the state just before the last frame's instant, "
                           "K(t_end-), which cells new at that frame are not part of, so they are in no "
                           "complex, count or class of the run (docs/MATH.md §6.2)");
  return run;
}

} // namespace medusa::io
