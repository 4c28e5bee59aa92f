#include "medusa/io/periodic_domain.h"

#include "medusa/core/error.h"

namespace medusa::io {

std::string PeriodicDomain::axes() const {
  std::string text;
  for (int a = 0; a < 3; ++a)
    if (periodic[static_cast<std::size_t>(a)])
      text += std::string(text.empty() ? "" : ",") + char('x' + a);
  return text;
}

PeriodicDomain periodic_domain(const Cc3dSimulation& sim, const std::array<std::int64_t, 3>& origin,
                               const std::array<std::int64_t, 3>& spacing) {
  PeriodicDomain d;
  for (std::size_t a = 0; a < 3; ++a) {
    if (!sim.periodic[a])
      continue;
    if (spacing[a] <= 0)
      throw InputError(sim.path + ": periodic axis " + char('x' + a) +
                       " with a non-positive lattice spacing");
    std::int64_t period = 0;
    if (__builtin_mul_overflow(sim.dimensions[a], spacing[a], &period))
      throw InputError(sim.path + ": the period along " + char('x' + a) + " overflows 64 bits in grid units");
    d.periodic[a] = true;
    d.origin[a] = origin[a];
    d.period[a] = period;
    d.lattice[a] = sim.dimensions[a];
  }
  return d;
}

std::int64_t minimum_image(std::int64_t d, std::int64_t period) {
  std::int64_t r = d % period; // (-period, period)
  if (r < 0)
    r += period; // [0, period)
  // [0, period) -> [-period/2, period/2): 2r >= period means r - period is the nearer image.
  if (r >= period - r)
    r -= period;
  return r;
}

std::int64_t wrap_coordinate(std::int64_t x, std::int64_t origin, std::int64_t period) {
  std::int64_t r = (x - origin) % period;
  if (r < 0)
    r += period;
  return origin + r;
}

kinetic::GridPoint wrap_into_domain(const PeriodicDomain& domain, kinetic::GridPoint p) {
  for (std::size_t a = 0; a < 3; ++a)
    if (domain.periodic[a])
      p[a] = wrap_coordinate(p[a], domain.origin[a], domain.period[a]);
  return p;
}

} // namespace medusa::io
