#include "medusa/persistence/summaries.h"

#include "medusa/core/error.h"

#include <algorithm>
#include <cmath>

namespace medusa::persistence {

std::vector<std::size_t> betti_curve(const PointDiagram& diagram, const std::vector<double>& times) {
  std::vector<std::size_t> curve(times.size(), 0);
  for (std::size_t k = 0; k < times.size(); ++k) {
    const double s = times[k];
    for (const Point& x : diagram.finite)
      curve[k] += x.birth <= s && s < x.death;
    for (double b : diagram.essential)
      curve[k] += b <= s;
  }
  return curve;
}

TotalPersistence total_persistence(const PointDiagram& diagram, double p) {
  TotalPersistence result;
  result.p = p;
  for (const Point& x : diagram.finite)
    result.value += p == 1.0 ? x.death - x.birth : std::pow(x.death - x.birth, p);
  result.essential_count = diagram.essential.size();
  return result;
}

PersistenceImage persistence_image(const PointDiagram& diagram, const PersistenceImageParams& params) {
  if (params.birth_pixels == 0 || params.persistence_pixels == 0 || !(params.birth_min < params.birth_max) ||
      !(params.persistence_min < params.persistence_max))
    throw InputError("persistence image: empty grid");
  if (!(params.sigma > 0) || !(params.pi_max > 0))
    throw InputError("persistence image: sigma and pi_max must be positive");
  PersistenceImage image;
  image.params = params;
  image.pixels.assign(params.birth_pixels * params.persistence_pixels, 0.0);
  image.essential_count = diagram.essential.size();
  const double scale = 1.0 / (params.sigma * std::sqrt(2.0));
  auto cdf = [&](double z) { return 0.5 * std::erfc(-z * scale); }; // Phi((x - mu) / sigma), z = x - mu
  const double bw = (params.birth_max - params.birth_min) / static_cast<double>(params.birth_pixels);
  const double pw =
      (params.persistence_max - params.persistence_min) / static_cast<double>(params.persistence_pixels);
  std::vector<double> bx(params.birth_pixels), py(params.persistence_pixels);
  for (const Point& x : diagram.finite) {
    const double pi = x.death - x.birth;
    const double w = std::min(pi / params.pi_max, 1.0);
    if (w <= 0)
      continue;
    // The Gaussian factorises, so a pixel's integral is the product of two 1D CDF differences.
    for (std::size_t c = 0; c < params.birth_pixels; ++c) {
      const double x0 = params.birth_min + bw * static_cast<double>(c);
      bx[c] = cdf(x0 + bw - x.birth) - cdf(x0 - x.birth);
    }
    for (std::size_t r = 0; r < params.persistence_pixels; ++r) {
      const double y0 = params.persistence_min + pw * static_cast<double>(r);
      py[r] = cdf(y0 + pw - pi) - cdf(y0 - pi);
    }
    for (std::size_t r = 0; r < params.persistence_pixels; ++r)
      for (std::size_t c = 0; c < params.birth_pixels; ++c)
        image.pixels[r * params.birth_pixels + c] += w * py[r] * bx[c];
  }
  return image;
}

} // namespace medusa::persistence
