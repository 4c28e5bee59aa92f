#include "augmented.h"

namespace medusa::persistence::detail {

double hungarian_cost(const AugmentedProblem& problem) {
  // Shortest augmenting paths with row/column potentials u, v (1-based, column 0 is the virtual
  // start). Forbidden pairs have infinite reduced cost and are never chosen, as a perfect matching of
  // finite cost always exists.
  const std::size_t N = problem.size();
  const double inf = AugmentedProblem::infinity();
  std::vector<double> u(N + 1, 0.0), v(N + 1, 0.0), minv(N + 1);
  std::vector<std::size_t> owner(N + 1, 0), way(N + 1, 0);
  std::vector<char> used(N + 1);
  // The O(N^3) inner loop reads each cost about N times: tabulate them when the table is modest.
  const bool tabulate = N <= 3000;
  std::vector<double> table;
  if (tabulate) {
    table.resize(N * N);
    for (std::size_t i = 0; i < N; ++i)
      for (std::size_t j = 0; j < N; ++j)
        table[i * N + j] = problem.cost(i, j);
  }
  auto cost = [&](std::size_t i, std::size_t j) { return tabulate ? table[i * N + j] : problem.cost(i, j); };
  for (std::size_t i = 1; i <= N; ++i) {
    owner[0] = i;
    std::size_t j0 = 0;
    std::fill(minv.begin(), minv.end(), inf);
    std::fill(used.begin(), used.end(), 0);
    do {
      used[j0] = 1;
      const std::size_t i0 = owner[j0];
      double delta = inf;
      std::size_t j1 = 0;
      for (std::size_t j = 1; j <= N; ++j) {
        if (used[j])
          continue;
        const double cur = cost(i0 - 1, j - 1) - u[i0] - v[j];
        if (cur < minv[j]) {
          minv[j] = cur;
          way[j] = j0;
        }
        if (minv[j] < delta) {
          delta = minv[j];
          j1 = j;
        }
      }
      for (std::size_t j = 0; j <= N; ++j) {
        if (used[j]) {
          u[owner[j]] += delta;
          v[j] -= delta;
        } else {
          minv[j] -= delta;
        }
      }
      j0 = j1;
    } while (owner[j0] != 0);
    do {
      const std::size_t j1 = way[j0];
      owner[j0] = owner[j1];
      j0 = j1;
    } while (j0 != 0);
  }
  double total = 0;
  for (std::size_t j = 1; j <= N; ++j)
    total += cost(owner[j] - 1, j - 1);
  return total;
}

} // namespace medusa::persistence::detail
