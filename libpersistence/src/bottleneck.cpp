#include "medusa/persistence/bottleneck.h"

#include "matching.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <random>

namespace medusa::persistence {
namespace detail {

std::size_t max_matching(const std::vector<std::vector<std::size_t>>& adjacency, std::size_t right_count) {
  const std::size_t n = adjacency.size();
  const std::size_t none = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> match_left(n, none), match_right(right_count, none), level(n);
  std::size_t size = 0;
  auto bfs = [&] {
    std::queue<std::size_t> queue;
    bool found = false;
    for (std::size_t u = 0; u < n; ++u) {
      level[u] = match_left[u] == none ? 0 : none;
      if (match_left[u] == none)
        queue.push(u);
    }
    while (!queue.empty()) {
      const std::size_t u = queue.front();
      queue.pop();
      for (std::size_t v : adjacency[u]) {
        const std::size_t w = match_right[v];
        if (w == none)
          found = true;
        else if (level[w] == none) {
          level[w] = level[u] + 1;
          queue.push(w);
        }
      }
    }
    return found;
  };
  // Iterative DFS along the BFS layers, so that long augmenting paths do not exhaust the stack.
  std::vector<std::size_t> next(n);
  auto dfs = [&](std::size_t root) {
    std::vector<std::size_t> stack{root};
    while (!stack.empty()) {
      const std::size_t u = stack.back();
      bool advanced = false;
      while (next[u] < adjacency[u].size()) {
        const std::size_t v = adjacency[u][next[u]];
        const std::size_t w = match_right[v];
        if (w == none) {
          // Augment along the stack: each left vertex takes the edge it is currently exploring.
          for (std::size_t k = stack.size(); k-- > 0;) {
            const std::size_t x = stack[k];
            const std::size_t y = adjacency[x][next[x]];
            match_right[y] = x;
            match_left[x] = y;
          }
          return true;
        }
        if (level[w] == level[u] + 1) {
          stack.push_back(w);
          advanced = true;
          break;
        }
        ++next[u];
      }
      if (!advanced) {
        level[u] = none;
        stack.pop_back();
        if (!stack.empty())
          ++next[stack.back()];
      }
    }
    return false;
  };
  while (bfs()) {
    std::fill(next.begin(), next.end(), 0);
    for (std::size_t u = 0; u < n; ++u)
      if (match_left[u] == none && dfs(u))
        ++size;
  }
  return size;
}

} // namespace detail

namespace {

double linf(const Point& x, const Point& y) {
  return std::max(std::abs(x.birth - y.birth), std::abs(x.death - y.death));
}
double half_persistence(const Point& x) { return (x.death - x.birth) / 2; }

// Whether some matching with ground distances <= r covers every point of `from` whose half
// persistence exceeds r (those cannot go to the diagonal).
bool far_points_matchable(const std::vector<Point>& from, const std::vector<Point>& to, double r) {
  std::vector<std::vector<std::size_t>> adjacency;
  for (const Point& x : from) {
    if (half_persistence(x) <= r)
      continue;
    adjacency.emplace_back();
    for (std::size_t j = 0; j < to.size(); ++j)
      if (linf(x, to[j]) <= r)
        adjacency.back().push_back(j);
    if (adjacency.back().empty())
      return false;
  }
  return detail::max_matching(adjacency, to.size()) == adjacency.size();
}

// d_B <= r iff a partial matching with edges <= r leaves only points of half persistence <= r
// unmatched. Such a matching must cover the far points of a and the far points of b; by the
// Mendelsohn-Dulmage theorem one matching covering both sets exists iff one covers each.
bool feasible(const std::vector<Point>& a, const std::vector<Point>& b, double r) {
  return far_points_matchable(a, b, r) && far_points_matchable(b, a, r);
}

} // namespace

double bottleneck_finite(const std::vector<Point>& a, const std::vector<Point>& b, std::size_t sort_limit) {
  // Matching every point to the diagonal costs the largest half persistence: an upper bound, and
  // only ground distances below it can be the answer.
  double upper = 0;
  for (const Point& x : a)
    upper = std::max(upper, half_persistence(x));
  for (const Point& y : b)
    upper = std::max(upper, half_persistence(y));
  // The optimum is a candidate (0, a half persistence or a ground distance) and feasibility is
  // monotone in r. The answer stays in (lo, hi] with hi feasible. There are n*m ground distances, so
  // they are not stored while too many remain: a candidate drawn uniformly from the open interval
  // (reservoir sampling) splits it, as in quickselect, until few enough remain to sort.
  auto for_each_candidate = [&](auto&& f) {
    f(0.0);
    for (const Point& x : a)
      f(half_persistence(x));
    for (const Point& y : b)
      f(half_persistence(y));
    for (const Point& x : a)
      for (const Point& y : b)
        f(linf(x, y));
  };
  double lo = -1, hi = upper;
  std::mt19937_64 rng(0x6d65647573610001ULL);
  for (;;) {
    std::size_t count = 0;
    double pivot = hi;
    for_each_candidate([&](double c) {
      if (lo < c && c < hi && std::uniform_int_distribution<std::size_t>(0, count++)(rng) == 0)
        pivot = c;
    });
    if (count == 0)
      return hi;
    if (count <= sort_limit)
      break;
    (feasible(a, b, pivot) ? hi : lo) = pivot;
  }
  std::vector<double> candidates;
  for_each_candidate([&](double c) {
    if (lo < c && c < hi)
      candidates.push_back(c);
  });
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  candidates.push_back(hi);
  std::size_t first = 0, last = candidates.size() - 1; // candidates[last] is feasible
  while (first < last) {
    const std::size_t mid = first + (last - first) / 2;
    if (feasible(a, b, candidates[mid]))
      last = mid;
    else
      first = mid + 1;
  }
  return candidates[last];
}

DistanceResult bottleneck_distance(const PointDiagram& a, const PointDiagram& b, bool ignore_essential) {
  check_points(a, "bottleneck distance, first diagram");
  check_points(b, "bottleneck distance, second diagram");
  DistanceResult result;
  result.finite = bottleneck_finite(a.finite, b.finite);
  result.essential_count_a = a.essential.size();
  result.essential_count_b = b.essential.size();
  if (a.essential.size() != b.essential.size()) {
    result.essential = std::numeric_limits<double>::infinity();
  } else {
    // On a line, sorted order is an optimal matching for every W_p and for d_B (docs/MATH.md §7.7).
    std::vector<double> x = a.essential, y = b.essential;
    std::sort(x.begin(), x.end());
    std::sort(y.begin(), y.end());
    for (std::size_t i = 0; i < x.size(); ++i)
      result.essential = std::max(result.essential, std::abs(x[i] - y[i]));
  }
  result.total = ignore_essential ? result.finite : std::max(result.finite, result.essential);
  return result;
}

} // namespace medusa::persistence
