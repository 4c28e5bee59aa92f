#include "medusa/kinetic/root_isolation.h"

#include <array>

namespace medusa::kinetic {

namespace {

int certified_sign(const Interval& x) {
  if (x.inf() > 0)
    return 1;
  if (x.sup() < 0)
    return -1;
  return 0;
}

} // namespace

FirstSignChange first_sign_change(const IntervalPoly& f, double start, int max_depth) {
  FirstSignChange result;
  struct Piece {
    double lo, hi;
    int depth;
  };
  // Depth-first, left piece first, so pieces are settled in increasing u; the stack never holds
  // more than one pending right half per level.
  std::array<Piece, 64> stack{};
  int top = 0;
  if (!(start < 1.0))
    return result;
  stack[top++] = {start, 1.0, 0};
  int sign = 0;
  std::array<Interval, IntervalPoly::max_degree + 1> beta{};
  while (top > 0) {
    Piece p = stack[--top];
    const int n = bernstein_coefficients(f, p.lo, p.hi, beta);
    int variations = 0, first = 0, previous = 0;
    bool certified = n >= 0;
    for (int j = 0; certified && j <= n; ++j) {
      int s = certified_sign(beta[static_cast<std::size_t>(j)]);
      if (s == 0) {
        certified = false;
        break;
      }
      if (j == 0)
        first = s;
      else if (s != previous)
        ++variations;
      previous = s;
    }
    if (sign == 0 && certified && p.lo == start)
      sign = first;
    if (certified && variations <= 1 && first == sign) {
      if (variations == 0)
        continue;
      result.status = FirstSignChange::Status::root;
      result.sign = sign;
      result.lo = p.lo;
      result.hi = p.hi;
      return result;
    }
    // Uncertain coefficients or several variations: halve, unless f(start) itself is uncertain
    // (the sign just after start is then unknown) or the depth is exhausted.
    const double mid = 0.5 * (p.lo + p.hi);
    if (p.depth >= max_depth || top + 2 > static_cast<int>(stack.size()) || !(p.lo < mid && mid < p.hi) ||
        (p.lo == start && certified_sign(beta[0]) == 0))
      return result;
    stack[static_cast<std::size_t>(top++)] = {mid, p.hi, p.depth + 1};
    stack[static_cast<std::size_t>(top++)] = {p.lo, mid, p.depth + 1};
  }
  result.status = FirstSignChange::Status::none;
  result.sign = sign;
  return result;
}

Refinement refine_root(const IntervalPoly& f, double& lo, double& hi, int sign_lo) {
  const double mid = 0.5 * (lo + hi);
  if (!(lo < mid && mid < hi))
    return Refinement::stuck;
  int n = f.degree_bound();
  Interval acc = n >= 0 ? f[n] : Interval(0);
  const Interval u(mid);
  for (int i = n - 1; i >= 0; --i)
    acc = acc * u + f[i];
  if (acc.inf() == 0 && acc.sup() == 0) {
    lo = hi = mid;
    return Refinement::exact;
  }
  int s = certified_sign(acc);
  if (s == 0)
    return Refinement::stuck;
  (s == sign_lo ? lo : hi) = mid;
  return Refinement::narrowed;
}

} // namespace medusa::kinetic
