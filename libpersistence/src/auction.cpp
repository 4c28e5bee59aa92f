#include "augmented.h"

#include <deque>

namespace medusa::persistence::detail {

AuctionResult auction(const AugmentedProblem& problem, const std::function<bool(double, double)>& done) {
  const std::size_t N = problem.size();
  const std::size_t none = std::numeric_limits<std::size_t>::max();
  const double inf = AugmentedProblem::infinity();
  double largest = 0;
  for (std::size_t i = 0; i < N; ++i)
    problem.for_each_edge(i, [&](std::size_t, double c) { largest = std::max(largest, c); });
  if (largest == 0)
    return {};

  std::vector<double> price(N, 0.0);
  std::vector<std::size_t> owner(N), item(N);
  AuctionResult last;
  // Epsilon-scaling as in Bertsekas' auction and Hera: each phase restarts the bidding with the prices
  // of the previous one and a five times smaller epsilon.
  for (double eps = largest / 4; eps > largest * 1e-15; eps /= 5) {
    std::fill(owner.begin(), owner.end(), none);
    std::fill(item.begin(), item.end(), none);
    std::deque<std::size_t> unassigned;
    for (std::size_t i = 0; i < N; ++i)
      unassigned.push_back(i);
    while (!unassigned.empty()) {
      const std::size_t i = unassigned.front();
      unassigned.pop_front();
      double best = inf, second = inf;
      std::size_t best_item = none;
      problem.for_each_edge(i, [&](std::size_t j, double c) {
        const double value = c + price[j];
        if (value < best) {
          second = best;
          best = value;
          best_item = j;
        } else if (value < second) {
          second = value;
        }
      });
      // Raise the price so that the bidder stays eps-happy with its item (eps-complementary slackness).
      price[best_item] += (second == inf ? 0.0 : second - best) + eps;
      if (owner[best_item] != none) {
        item[owner[best_item]] = none;
        unassigned.push_back(owner[best_item]);
      }
      owner[best_item] = i;
      item[i] = best_item;
    }
    // Primal cost of the matching and the dual bound sum_i min_j (c_ij + p_j) - sum_j p_j, valid for
    // any prices (LP duality of the assignment problem).
    double cost = 0, lower = 0;
    for (std::size_t i = 0; i < N; ++i) {
      cost += problem.cost(i, item[i]);
      double row_min = inf;
      problem.for_each_edge(i, [&](std::size_t j, double c) { row_min = std::min(row_min, c + price[j]); });
      lower += row_min;
    }
    for (double p : price)
      lower -= p;
    last = {cost, lower};
    if (done(cost, lower))
      break;
  }
  return last;
}

} // namespace medusa::persistence::detail
