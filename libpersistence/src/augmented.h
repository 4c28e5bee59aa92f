// The augmented bipartite graph of W_p (docs/MATH.md §7.7), internal to libpersistence: rows are the
// points of a (0..n-1) and the diagonal copies of b (n..n+m-1); columns are the points of b (0..m-1)
// and the diagonal copies of a (m..m+n-1). A point goes to a diagonal copy only through its own
// projection; diagonal copies match each other for free.
#pragma once

#include "medusa/persistence/points.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <vector>

namespace medusa::persistence::detail {

class AugmentedProblem {
public:
  AugmentedProblem(const std::vector<Point>& a, const std::vector<Point>& b, double p) : a_(a), b_(b), p_(p) {
    for (const Point& x : a_)
      diag_a_.push_back(power((x.death - x.birth) / 2));
    for (const Point& y : b_)
      diag_b_.push_back(power((y.death - y.birth) / 2));
  }

  std::size_t size() const { return a_.size() + b_.size(); }
  std::size_t n() const { return a_.size(); }
  std::size_t m() const { return b_.size(); }

  // Cost of row i and column j, +inf when the pair is not an edge.
  double cost(std::size_t i, std::size_t j) const {
    const std::size_t n = a_.size(), m = b_.size();
    if (i < n)
      return j < m ? power(linf(a_[i], b_[j])) : (j - m == i ? diag_a_[i] : infinity());
    return j < m ? (i - n == j ? diag_b_[j] : infinity()) : 0.0;
  }

  // Calls f(j, cost) for every column j joined to row i.
  template <class F> void for_each_edge(std::size_t i, F&& f) const {
    const std::size_t n = a_.size(), m = b_.size();
    if (i < n) {
      for (std::size_t j = 0; j < m; ++j)
        f(j, power(linf(a_[i], b_[j])));
      f(m + i, diag_a_[i]);
    } else {
      f(i - n, diag_b_[i - n]);
      for (std::size_t k = 0; k < n; ++k)
        f(m + k, 0.0);
    }
  }

  double power(double x) const { return p_ == 1.0 ? x : std::pow(x, p_); }
  static double infinity() { return std::numeric_limits<double>::infinity(); }

private:
  static double linf(const Point& x, const Point& y) {
    return std::max(std::abs(x.birth - y.birth), std::abs(x.death - y.death));
  }

  const std::vector<Point>& a_;
  const std::vector<Point>& b_;
  double p_;
  std::vector<double> diag_a_, diag_b_;
};

// Minimum total cost of a perfect matching (Hungarian method with potentials, O(N^3)).
double hungarian_cost(const AugmentedProblem& problem);

struct AuctionResult {
  double cost = 0;        // sum of the costs of the final matching
  double lower_bound = 0; // dual bound: the optimum is >= lower_bound
};

// Auction with epsilon-scaling; after each phase the matching cost and the dual bound of the prices
// are compared, and `done(cost, lower_bound)` decides whether to stop. Returns the last phase's
// values (the loop also stops once epsilon is negligible against the largest cost).
AuctionResult auction(const AugmentedProblem& problem, const std::function<bool(double, double)>& done);

} // namespace medusa::persistence::detail
