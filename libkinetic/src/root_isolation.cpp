#include "root_isolation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace medusa::kinetic {

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

namespace {

// An enclosure [0, 0] proves f vanishes there: interval Horner is exact only when every step was.
bool is_exact_zero(const Interval& v) { return v.inf() == 0 && v.sup() == 0; }

// Moves lo or hi to x inside (lo, hi) by the certified sign of f there.
Refinement cut_at(const IntervalPoly& f, double x, double& lo, double& hi, int sign_lo) {
  const Interval v = value_at_point(f, x);
  if (is_exact_zero(v)) {
    lo = hi = x;
    return Refinement::exact;
  }
  const int s = certified_sign(v);
  if (s == 0)
    return Refinement::stuck;
  (s == sign_lo ? lo : hi) = x;
  return Refinement::narrowed;
}

// A root that is a short dyadic rational (an event at a simple rational time such as 5/8) is met
// by rounding r, a point next to it, to fewer bits: f vanishes exactly there. Sets
// lo = hi = that root and answers true; false when none of these roundings is a root in (lo, hi).
bool dyadic_root_near(const IntervalPoly& f, double r, double& lo, double& hi) {
  if (!(r >= 0.0 && r <= 1.0))
    return false; // event times lie in the slab [0, 1]
  double scale = 1.0;
  for (int bits = 4; bits <= 48; bits += 4) {
    // Scaling by a power of two is exact (r is in [0, 1], far from overflow and underflow), and so
    // is the conversion of an integer below 2^49 back to double. Which rounding of r * 2^bits the
    // integer is (the mode is upward here) does not matter: x is only a candidate, checked exactly.
    // This runs for every event time tightened: no libm calls.
    scale *= 16.0;
    const double x = static_cast<double>(static_cast<std::int64_t>(r * scale + 0.5)) / scale;
    if (!(lo < x && x < hi))
      continue;
    if (is_exact_zero(value_at_point(f, x))) {
      lo = hi = x;
      return true;
    }
  }
  return false;
}

} // namespace

Refinement refine_root(const IntervalPoly& f, double& lo, double& hi, int sign_lo) {
  const double mid = 0.5 * (lo + hi);
  if (!(lo < mid && mid < hi))
    return Refinement::stuck;
  if (const Refinement step = cut_at(f, mid, lo, hi, sign_lo); step != Refinement::stuck)
    return step;
  // An undecided midpoint need not mean doubles are done: narrow_root centres an interval on its
  // Newton estimate, so the midpoint is then the root to within rounding while the quarter points
  // beside it still have certified signs. After both, the root lies in the middle half.
  const double quarter = 0.25 * (hi - lo);
  Refinement result = Refinement::stuck;
  for (const double x : {mid - quarter, mid + quarter}) {
    if (!(lo < x && x < hi))
      continue;
    const Refinement step = cut_at(f, x, lo, hi, sign_lo);
    if (step == Refinement::exact)
      return step;
    if (step == Refinement::narrowed)
      result = step;
  }
  return result;
}

Refinement narrow_root(const IntervalPoly& f, double& lo, double& hi, int sign_lo, double width) {
  const int n = f.degree_bound();
  std::array<double, IntervalPoly::max_degree + 1> c{};
  for (int i = 0; i <= n; ++i)
    c[static_cast<std::size_t>(i)] = 0.5 * (f[i].inf() + f[i].sup());
  // Safeguarded Newton (Newton inside a shrinking bracket, halving when a step leaves it) on the
  // midpoint polynomial: only a proposal, so neither its rounding nor its convergence matters to
  // correctness. The isolating pieces handed in are wide (half the slab on average), where plain
  // Newton from the middle often leaves the interval; the bracket makes every proposal land near the
  // root, so two certified cuts around it usually finish the job.
  auto propose = [&]() {
    double a = lo, b = hi, x = 0.5 * (lo + hi);
    for (int k = 0; k < 64; ++k) {
      double v = c[static_cast<std::size_t>(n)], d = 0.0;
      for (int i = n - 1; i >= 0; --i) {
        d = d * x + v;
        v = v * x + c[static_cast<std::size_t>(i)];
      }
      if (v == 0.0)
        return x;
      ((v > 0) == (sign_lo > 0) ? a : b) = x;
      double y = x - v / d;
      if (!(a < y && y < b))
        y = 0.5 * (a + b);
      if (y == x || !(a < y && y < b))
        return x;
      x = y;
    }
    return x;
  };
  for (int round = 0; round < 4 && hi - lo > width; ++round) {
    const double r = propose();
    const double ulp = std::nextafter(r, 2.0) - r;
    // Around a good proposal, cuts at +-width/4 finish in one round. Asked for the tightest interval
    // (width 0), each round gains 20 bits instead, so that cuts never start inside the noise zone.
    const double e = width > 0 ? std::max(0.25 * width, 4.0 * ulp) : std::max((hi - lo) * 0x1p-20, 4.0 * ulp);
    bool moved = false;
    // The cut at r itself detects a root that is exactly r, which is what the tightest interval is
    // for: events at equal rational times must compare equal. On the way to a given width it is
    // costly (f is tiny there, so doubles cannot decide) and rarely needed: the cuts around r come
    // first, and r only if they fall short. Short dyadic roots near r are searched for once, on the
    // final interval (below), where few roundings of its middle fall inside it.
    const std::array<double, 3> cuts =
        width > 0 ? std::array<double, 3>{r - e, r + e, r} : std::array<double, 3>{r, r - e, r + e};
    for (double x : cuts) {
      if (hi - lo <= width)
        break;
      if (!(lo < x && x < hi))
        continue;
      const Refinement step = cut_at(f, x, lo, hi, sign_lo);
      if (step == Refinement::exact)
        return Refinement::exact;
      moved = moved || step == Refinement::narrowed;
    }
    if (!moved)
      break;
  }
  while (hi - lo > width) {
    const Refinement step = refine_root(f, lo, hi, sign_lo);
    if (step == Refinement::stuck && dyadic_root_near(f, 0.5 * (lo + hi), lo, hi))
      return Refinement::exact; // as tight as doubles allow, and a short dyadic inside is the root
    if (step != Refinement::narrowed)
      return step;
  }
  return Refinement::narrowed;
}

} // namespace medusa::kinetic
