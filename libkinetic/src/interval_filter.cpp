#include "interval_filter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace medusa::kinetic {

namespace {

int degree_of(const IntervalPoly& f) {
  int n = f.degree_bound();
  // Trailing coefficients that are exactly zero do not count (they come from cancellations of
  // exact products, e.g. stationary points).
  while (n > 0 && f[n].inf() == 0 && f[n].sup() == 0)
    --n;
  return n;
}

// The two stages in plain doubles below share this. Rounding is upward (every caller's guard sets
// it), so each operation's relative error is below u = 2^-52 and, for a subnormal result, its
// absolute error below 2^-1074.

// An interval coefficient as a double centre c and a radius r rounded up: the true coefficient lies
// in [c - r, c + r].
struct Centred {
  double c, r;
};
Centred centred(const Interval& a) {
  const double c = 0.5 * (a.inf() + a.sup());
  return {c, std::max(a.sup() - c, c - a.inf())};
}

// gamma_k = k u / (1 - k u) <= k u (1 + 2 k u) for k u <= 1/2 (Higham, Accuracy and Stability of
// Numerical Algorithms, 3.1): the relative error of a chain of k roundings.
double gamma(double k) {
  const double g = k * 0x1p-52;
  return g * (1.0 + 2.0 * g);
}

// [v - bound, v + bound] rounded outward (upward: v + bound is an upper bound, -((-v) + bound) a
// lower one); nullopt when not finite.
std::optional<Interval> around(double v, double bound) {
  const double upper = v + bound, lower = -((-v) + bound);
  if (!std::isfinite(upper) || !std::isfinite(lower))
    return std::nullopt;
  return Interval(lower, upper);
}

// Horner in interval arithmetic at u (a point or an interval); n is f's degree.
Interval horner(const IntervalPoly& f, int n, const Interval& u) {
  Interval acc = f[n];
  for (int i = n - 1; i >= 0; --i)
    acc = acc * u + f[i];
  return acc;
}

// The Bernstein coefficients of bernstein_coefficients from plain doubles: true when every one of
// them has a certified sign (beta then holds enclosures), false when the caller must use intervals.
// The map from coefficients to beta is linear with non-negative weights, so it runs on the midpoints,
// on their absolute values (rounded upward) and on the radii side by side, and the enclosure is
// beta(c) +- (gamma_k m + map(r) + 2^-1000), k = n^2 + 3n + 4 roundings: docs/MATH.md §3.11.
bool bernstein_from_doubles(const IntervalPoly& f, int n, double lo, double hi,
                            std::array<Interval, IntervalPoly::max_degree + 1>& beta) {
  if (!(lo >= 0.0 && lo < hi))
    return false;
  constexpr std::size_t size = IntervalPoly::max_degree + 1;
  std::array<double, size> c{}, m{}, r{};
  const std::size_t top = static_cast<std::size_t>(n);
  for (std::size_t i = 0; i <= top; ++i) {
    const Centred a = centred(f[static_cast<int>(i)]);
    c[i] = a.c;
    m[i] = std::fabs(a.c);
    r[i] = a.r;
  }
  if (lo != 0.0 || hi != 1.0) {
    for (std::size_t k = 0; k < top; ++k)
      for (std::size_t i = top; i-- > k;) {
        c[i] += lo * c[i + 1];
        m[i] += lo * m[i + 1];
        r[i] += lo * r[i + 1];
      }
    const double s = hi - lo; // rounded upward: the |.| and radius maps only grow
    double p = 1.0;
    for (std::size_t i = 1; i <= top; ++i) {
      p *= s;
      c[i] *= p;
      m[i] *= p;
      r[i] *= p;
    }
  }
  const double g = gamma(double(n) * n + 3.0 * n + 4.0);
  for (std::size_t j = 0; j <= top; ++j) {
    double b = 0.0, bm = 0.0, br = 0.0;
    for (std::size_t i = 0; i <= j; ++i) {
      const double w = binomial[top - i][j - i];
      b += w * c[i];
      bm += w * m[i];
      br += w * r[i];
    }
    const std::optional<Interval> enclosure = around(b, br + g * bm + 0x1p-1000);
    if (!enclosure || certified_sign(*enclosure) == 0)
      return false;
    beta[j] = *enclosure;
  }
  return true;
}

} // namespace

bool bernstein_coefficients_from_doubles(const IntervalPoly& f, double lo, double hi,
                                         std::array<Interval, IntervalPoly::max_degree + 1>& beta) {
  const int n = degree_of(f);
  return n >= 0 && bernstein_from_doubles(f, n, lo, hi, beta);
}

int bernstein_coefficients(const IntervalPoly& f, double lo, double hi,
                           std::array<Interval, IntervalPoly::max_degree + 1>& beta) {
  int n = degree_of(f);
  if (n < 0)
    return n;
  // Plain doubles first: when they certify every sign, intervals could only tighten the enclosures.
  if (bernstein_from_doubles(f, n, lo, hi, beta))
    return n;
  std::array<Interval, IntervalPoly::max_degree + 1> g{};
  for (int i = 0; i <= n; ++i)
    g[i] = f[i];
  if (lo != 0.0 || hi != 1.0) {
    // Taylor shift h(v) = f(lo + v) by repeated synthetic division, then scale by (hi - lo)^i so that
    // g(v) = f(lo + (hi - lo) v) on v in [0, 1] (docs/MATH.md §3.8, restriction to [u_lo, 1]).
    const Interval l(lo);
    for (int k = 0; k < n; ++k)
      for (int i = n - 1; i >= k; --i)
        g[i] += l * g[i + 1];
    const Interval s = Interval(hi) - l;
    Interval p(1);
    for (int i = 1; i <= n; ++i) {
      p *= s;
      g[i] *= p;
    }
  }
  // beta_j = sum_{i<=j} C(n-i, j-i) g_i = C(n, j) b_j: the Bernstein coefficients up to positive factors.
  for (int j = 0; j <= n; ++j) {
    Interval b(0);
    for (int i = 0; i <= j; ++i)
      b += Interval(binomial[n - i][j - i]) * g[i];
    beta[static_cast<std::size_t>(j)] = b;
  }
  return n;
}

int bernstein_sign(const IntervalPoly& f, double lo, double hi) {
  std::array<Interval, IntervalPoly::max_degree + 1> beta{};
  int n = bernstein_coefficients(f, lo, hi, beta);
  if (n < 0)
    return 0;
  int common = 0;
  for (int j = 0; j <= n; ++j) {
    int s = certified_sign(beta[static_cast<std::size_t>(j)]);
    if (s == 0 || (common != 0 && s != common))
      return 0;
    common = s;
  }
  return common;
}

int bernstein_sign_subdivided(const IntervalPoly& f, double lo, int depth) {
  const Interval value_lo = value_at_point(f, lo);
  const int at_lo = certified_sign(value_lo);
  // Dominance first: for u and lo in [0, 1], |f(u) - f(lo)| <= sum_{i >= 1} |f_i| |u^i - lo^i| <=
  // sum_{i >= 1} |f_i|, so f keeps the sign of f(lo) on [lo, 1] when |f(lo)| exceeds that sum. A few
  // additions settle most certificates of a frame, where cells move little compared with their
  // spacing, before any Bernstein coefficient is computed. (lo < 0, which an enclosure of a time just
  // after a slab start can have, is left to Bernstein: |u^i - lo^i| is no longer bounded by 1 there.)
  if (at_lo != 0 && lo >= 0.0) {
    Interval tail(0);
    for (int i = 1, n = degree_of(f); i <= n; ++i)
      tail += CGAL::abs(f[i]);
    if (value_lo.inf() > tail.sup() || value_lo.sup() < -tail.sup())
      return at_lo;
  }
  // A definite sign change proves a root in [lo, 1], so no subdivision can settle f: certificates
  // that fail inside the slab leave here after two evaluations instead of 2^depth pieces.
  if (at_lo * interval_sign(f, 1.0, 1.0) < 0)
    return 0;
  // The first Bernstein coefficient of every piece starting at lo is f(lo), computed by the same
  // Horner steps as at_lo (the Taylor shift's constant term; the doubles' bound is only wider): when
  // at_lo is undecided, no piece containing lo ever is. This is the common case of the certificates
  // a flip creates, which vanish at now.
  if (at_lo == 0)
    return 0;
  // Depth-first over dyadic pieces of [lo, 1]; each piece must be decided with one common sign.
  struct Piece {
    double lo, hi;
    int depth;
  };
  Piece stack[64];
  int top = 0, common = at_lo;
  stack[top++] = {lo, 1.0, 0};
  std::array<Interval, IntervalPoly::max_degree + 1> beta{};
  while (top > 0) {
    Piece p = stack[--top];
    const int n = bernstein_coefficients(f, p.lo, p.hi, beta);
    if (n < 0)
      return 0;
    // beta_0 and beta_n are f at the piece's ends, up to positive factors.
    const int first = certified_sign(beta[0]), last = certified_sign(beta[static_cast<std::size_t>(n)]);
    if ((first != 0 && common != 0 && first != common) || (last != 0 && common != 0 && last != common))
      return 0;
    int s = 0;
    for (int j = 0; j <= n; ++j) {
      const int sj = certified_sign(beta[static_cast<std::size_t>(j)]);
      if (sj == 0 || (s != 0 && sj != s)) {
        s = 0;
        break;
      }
      s = sj;
    }
    if (s == 0) {
      double mid = 0.5 * (p.lo + p.hi);
      if (p.depth >= depth || top + 2 > 64 || !(p.lo < mid && mid < p.hi))
        return 0;
      stack[top++] = {mid, p.hi, p.depth + 1};
      stack[top++] = {p.lo, mid, p.depth + 1};
      continue;
    }
    if (common != 0 && s != common)
      return 0;
    common = s;
  }
  return common;
}

namespace {

// The enclosure of value_at_point from doubles, or nullopt when it is not finite. Proof:
//  * every true coefficient a_i lies in [c_i - r_i, c_i + r_i] (centred), so
//    |sum a_i x^i - sum c_i x^i| <= sum r_i |x|^i;
//  * v = Horner of c at x in floating point: |v - sum c_i x^i| <= gamma_2n sum |c_i| |x|^i (Higham,
//    5.1) plus, for underflow, at most 2^-1074 per product, carried by |x|^k and the step's
//    (1 + gamma): less than 2^-1072 sum |x|^i. The bound uses 2^-1000 instead: arithmetic on
//    subnormal numbers costs a microcode assist, which made this path slower than interval Horner;
//  * the three sums have non-negative terms, so evaluating them rounded upward gives upper bounds.
std::optional<Interval> value_from_doubles(const IntervalPoly& f, int n, double x) {
  const double ax = std::fabs(x);
  const Centred lead = centred(f[n]);
  double v = lead.c, radius = lead.r, magnitude = std::fabs(lead.c), powers = 1.0;
  for (int i = n - 1; i >= 0; --i) {
    const Centred a = centred(f[i]);
    v = v * x + a.c;
    radius = radius * ax + a.r;
    magnitude = magnitude * ax + std::fabs(a.c);
    powers = powers * ax + 1.0;
  }
  return around(v, radius + gamma(2.0 * n) * magnitude + 0x1p-1000 * powers);
}

} // namespace

std::optional<Interval> value_at_point_from_doubles(const IntervalPoly& f, double x) {
  const int n = degree_of(f);
  if (n < 0)
    return Interval(0);
  return value_from_doubles(f, n, x);
}

Interval value_at_point(const IntervalPoly& f, double x) {
  const int n = degree_of(f);
  if (n < 0)
    return Interval(0);
  if (x == 0.0) // a slab start: the constant term, exactly as enclosed
    return f[0];
  if (const auto fast = value_from_doubles(f, n, x); fast && certified_sign(*fast) != 0)
    return *fast;
  return horner(f, n, Interval(x));
}

int interval_sign(const IntervalPoly& f, double lo, double hi) {
  if (lo == hi)
    return certified_sign(value_at_point(f, lo));
  const int n = degree_of(f);
  return n < 0 ? 0 : certified_sign(horner(f, n, Interval(lo, hi)));
}

int proportionality_sign(const IntervalPoly& f, const IntervalPoly& g, int shift) {
  const int n = std::min(f.degree_bound() - shift, g.degree_bound());
  for (int i = 0; i <= n; ++i) {
    const int a = certified_sign(f[i + shift]), b = certified_sign(g[i]);
    if (a != 0 && b != 0)
      return a * b;
  }
  return 0;
}

} // namespace medusa::kinetic
