#include "augmented.h"

namespace medusa::persistence::detail {
namespace {

// Shortest augmenting paths with row/column potentials u, v (1-based, column 0 is the virtual start).
// Forbidden pairs have infinite reduced cost and are never chosen, as a perfect matching of finite
// cost always exists. `cost(i, j)` is 0-based.
template <class Cost> double solve(std::size_t N, const Cost& cost) {
  const double inf = AugmentedProblem::infinity();
  std::vector<double> u(N + 1, 0.0), v(N + 1, 0.0), minv(N + 1);
  std::vector<std::size_t> owner(N + 1, 0), way(N + 1, 0);
  std::vector<char> used(N + 1), matched(N + 1, 0);
  // Start from feasible potentials, u_i = min_j c_ij then v_j = min_i (c_ij - u_i), and a greedy
  // matching on the edges they make tight. Every augmentation below keeps the reduced costs
  // non-negative and the matched edges tight, so the result is still optimal; on the augmented
  // graph of W_p (docs/MATH.md §7.7) most rows, among them the free diagonal-to-diagonal ones, are matched
  // here instead of by an O(N^2) augmenting search each.
  for (std::size_t i = 1; i <= N; ++i) {
    double row_min = inf;
    for (std::size_t j = 1; j <= N; ++j)
      row_min = std::min(row_min, cost(i - 1, j - 1));
    u[i] = row_min;
  }
  std::fill(v.begin() + 1, v.end(), inf);
  for (std::size_t i = 1; i <= N; ++i)
    for (std::size_t j = 1; j <= N; ++j)
      v[j] = std::min(v[j], cost(i - 1, j - 1) - u[i]);
  for (std::size_t i = 1; i <= N; ++i)
    for (std::size_t j = 1; j <= N; ++j)
      if (owner[j] == 0 && cost(i - 1, j - 1) - u[i] - v[j] == 0) {
        owner[j] = i;
        matched[i] = 1;
        break;
      }
  for (std::size_t i = 1; i <= N; ++i) {
    if (matched[i])
      continue;
    owner[0] = i;
    std::size_t j0 = 0;
    std::fill(minv.begin(), minv.end(), inf);
    std::fill(used.begin(), used.end(), 0);
    do {
      used[j0] = 1;
      const std::size_t i0 = owner[j0];
      const double ui0 = u[i0];
      double delta = inf;
      std::size_t j1 = 0;
      for (std::size_t j = 1; j <= N; ++j) {
        if (used[j])
          continue;
        const double cur = cost(i0 - 1, j - 1) - ui0 - v[j];
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

} // namespace

double hungarian_cost(const AugmentedProblem& problem) {
  const std::size_t N = problem.size();
  // The O(N^3) inner loop reads each cost about N times: tabulate them when the table is modest.
  if (N > 3000)
    return solve(N, [&problem](std::size_t i, std::size_t j) { return problem.cost(i, j); });
  std::vector<double> table(N * N);
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j)
      table[i * N + j] = problem.cost(i, j);
  const double* t = table.data();
  return solve(N, [t, N](std::size_t i, std::size_t j) { return t[i * N + j]; });
}

} // namespace medusa::persistence::detail
