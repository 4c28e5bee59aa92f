#include "recorded_domain.h"

#include "medusa/core/error.h"

#include <cstdio>

namespace medusa::cli {

std::string periodic_domain_text(const medusa::RunInfo& run, std::int64_t scale, const std::string& aside) {
  std::string axes, periods;
  for (std::size_t a = 0; a < 3; ++a) {
    const std::int64_t length = run.periodic_lengths[a];
    if (length <= 0)
      continue;
    char period[32];
    std::snprintf(period, sizeof period, "%.17g", static_cast<double>(length) / static_cast<double>(scale));
    axes += (axes.empty() ? "" : ", ") + std::string(1, static_cast<char>('x' + a));
    periods += (periods.empty() ? "" : " x ") + std::string(period);
  }
  return axes.empty() ? std::string()
                      : "periodic along " + axes + " (period " + periods + " lattice units" + aside + ")";
}

io::PeriodicDomain recorded_domain(const medusa::RunInfo& run, std::int64_t scale, const std::string& store) {
  if (run.periodic_axes.find_first_not_of("xyz,") != std::string::npos)
    throw StoreError(store + ": periodic_axes '" + run.periodic_axes + "' names an axis other than x, y, z");
  io::PeriodicDomain domain;
  for (std::size_t a = 0; a < 3; ++a) {
    const char axis = static_cast<char>('x' + a);
    if (run.periodic_axes.find(axis) == std::string::npos)
      continue;
    if (run.periodic_lengths[a] <= 0)
      throw StoreError(store + ": periodic along " + axis + " without a positive periodic_length_" + axis);
    domain.periodic[a] = true;
    domain.period[a] = run.periodic_lengths[a];
    domain.lattice[a] = scale > 0 ? run.periodic_lengths[a] / scale : 0;
  }
  return domain;
}

} // namespace medusa::cli
