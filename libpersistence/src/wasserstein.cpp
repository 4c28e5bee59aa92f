#include "medusa/persistence/wasserstein.h"

#include "augmented.h"
#include "medusa/core/error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace medusa::persistence {
namespace {

void check_order(double p) {
  if (!(p >= 1.0) || !std::isfinite(p))
    throw InputError("Wasserstein distance: order p = " + std::to_string(p) + " must be finite and >= 1");
}

double root(double sum, double p) { return p == 1.0 ? sum : std::pow(sum, 1.0 / p); }

// With one side empty every point goes to the diagonal.
bool trivial(const std::vector<Point>& a, const std::vector<Point>& b, double p, double& value) {
  if (!a.empty() && !b.empty())
    return false;
  const detail::AugmentedProblem problem(a, b, p);
  double sum = 0;
  for (std::size_t i = 0; i < problem.size(); ++i)
    sum += problem.cost(i, i < problem.n() ? problem.m() + i : i - problem.n());
  value = root(sum, p);
  return true;
}

} // namespace

double wasserstein_finite_exact(const std::vector<Point>& a, const std::vector<Point>& b, double p) {
  check_order(p);
  double value = 0;
  if (trivial(a, b, p, value))
    return value;
  return root(detail::hungarian_cost(detail::AugmentedProblem(a, b, p)), p);
}

ApproximateDistance wasserstein_finite_auction(const std::vector<Point>& a, const std::vector<Point>& b,
                                               double p, double delta) {
  check_order(p);
  if (!(delta > 0))
    throw InputError("Wasserstein distance: relative error delta = " + std::to_string(delta) +
                     " must be > 0");
  ApproximateDistance result;
  if (trivial(a, b, p, result.value)) {
    result.exact = true;
    return result;
  }
  const detail::AugmentedProblem problem(a, b, p);
  // Certified when cost^(1/p) <= (1 + delta) * lower^(1/p) <= (1 + delta) * W_p; a zero cost is optimal.
  auto certified = [&](double cost, double lower) {
    return cost == 0 || (lower > 0 && root(cost, p) <= (1 + delta) * root(lower, p));
  };
  const detail::AuctionResult r = detail::auction(problem, certified);
  if (!certified(r.cost, r.lower_bound)) {
    result.value = root(detail::hungarian_cost(problem), p);
    result.exact = true;
    return result;
  }
  result.value = root(r.cost, p);
  result.relative_error = r.cost == 0 ? 0.0 : result.value / root(r.lower_bound, p) - 1;
  return result;
}

DistanceResult wasserstein_distance(const PointDiagram& a, const PointDiagram& b,
                                    const WassersteinOptions& options) {
  check_order(options.p);
  check_points(a, "Wasserstein distance, first diagram");
  check_points(b, "Wasserstein distance, second diagram");
  DistanceResult result;
  if (a.finite.size() + b.finite.size() <= options.exact_limit) {
    result.finite = wasserstein_finite_exact(a.finite, b.finite, options.p);
  } else {
    const ApproximateDistance approx =
        wasserstein_finite_auction(a.finite, b.finite, options.p, options.delta);
    result.finite = approx.value;
    result.exact = approx.exact;
    result.relative_error = approx.relative_error;
  }
  result.essential_count_a = a.essential.size();
  result.essential_count_b = b.essential.size();
  if (a.essential.size() != b.essential.size()) {
    result.essential = detail::AugmentedProblem::infinity();
  } else {
    // Sorted births are an optimal matching on the line (docs/MATH.md §7.7).
    std::vector<double> x = a.essential, y = b.essential;
    std::sort(x.begin(), x.end());
    std::sort(y.begin(), y.end());
    double sum = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
      sum += options.p == 1.0 ? std::abs(x[i] - y[i]) : std::pow(std::abs(x[i] - y[i]), options.p);
    result.essential = root(sum, options.p);
  }
  if (options.ignore_essential)
    result.total = result.finite;
  else if (std::isinf(result.essential))
    result.total = result.essential;
  else
    result.total = root((options.p == 1.0 ? result.finite : std::pow(result.finite, options.p)) +
                            (options.p == 1.0 ? result.essential : std::pow(result.essential, options.p)),
                        options.p);
  return result;
}

} // namespace medusa::persistence
