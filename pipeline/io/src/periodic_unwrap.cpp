#include "medusa/io/periodic_unwrap.h"

#include "medusa/core/error.h"

namespace medusa::io {

namespace {

// A grid coordinate in lattice units, exactly: "12.5" for 12500000 at scale 10^6.
std::string lattice_units(std::int64_t x, std::int64_t scale) {
  const bool negative = x < 0;
  const std::uint64_t m = negative ? 0 - static_cast<std::uint64_t>(x) : static_cast<std::uint64_t>(x);
  const std::uint64_t s = static_cast<std::uint64_t>(scale);
  std::string text = std::to_string(m / s);
  std::string frac = std::to_string(m % s);
  if (m % s != 0) {
    std::size_t digits = 0;
    for (std::uint64_t t = s; t > 1; t /= 10)
      ++digits;
    frac.insert(0, digits - frac.size(), '0');
    frac.erase(frac.find_last_not_of('0') + 1);
    text += "." + frac;
  }
  return (negative ? "-" : "") + text;
}

} // namespace

void unwrap_trajectories(kinetic::Trajectories& trajectories, const PeriodicDomain& domain,
                         const std::vector<std::string>& sources) {
  if (!domain.any())
    return;
  for (kinetic::Trajectory& c : trajectories.cells) {
    kinetic::GridPoint previous_wrapped = c.positions.front();
    for (std::size_t k = 1; k < c.positions.size(); ++k) {
      const kinetic::GridPoint wrapped = c.positions[k];
      for (std::size_t a = 0; a < 3; ++a) {
        if (!domain.periodic[a])
          continue;
        const std::int64_t period = domain.period[a];
        // Exact integer minimum image (docs/MATH.md §8.2); -period/2 is the one ambiguous step.
        const std::int64_t step = minimum_image(wrapped[a] - previous_wrapped[a], period);
        if (2 * step == -period) {
          const std::size_t frame = c.first_frame + k;
          const std::string& file = sources.size() > frame ? sources[frame] : sources.front();
          throw InputError(file + ": cell " + std::to_string(c.cell_id) + " moves " +
                           lattice_units(-step, trajectories.scale) + " along " + char('x' + a) +
                           " between MCS " + std::to_string(trajectories.frame_times[frame - 1]) +
                           " and MCS " + std::to_string(trajectories.frame_times[frame]) +
                           ", half the period of the periodic lattice: the way it crossed the boundary is "
                           "ambiguous (docs/MATH.md §8.2)");
        }
        c.positions[k][a] = c.positions[k - 1][a] + step;
      }
      previous_wrapped = wrapped;
    }
  }
}

} // namespace medusa::io
