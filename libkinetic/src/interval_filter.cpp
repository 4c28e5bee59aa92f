#include "medusa/kinetic/interval_filter.h"

#include <algorithm>
#include <array>

namespace medusa::kinetic {

namespace {

int sign_of(const Interval& x) {
  if (x.inf() > 0)
    return 1;
  if (x.sup() < 0)
    return -1;
  return 0;
}

int degree_of(const IntervalPoly& f) {
  int n = f.degree_bound();
  // Trailing coefficients that are exactly zero do not count (they come from cancellations of
  // exact products, e.g. stationary points).
  while (n > 0 && f[n].inf() == 0 && f[n].sup() == 0)
    --n;
  return n;
}

} // namespace

int bernstein_coefficients(const IntervalPoly& f, double lo, double hi,
                           std::array<Interval, IntervalPoly::max_degree + 1>& beta) {
  int n = degree_of(f);
  if (n < 0)
    return n;
  std::array<Interval, IntervalPoly::max_degree + 1> g{};
  for (int i = 0; i <= n; ++i)
    g[i] = f[i];
  if (lo != 0.0 || hi != 1.0) {
    // Taylor shift h(v) = f(lo + v) by repeated synthetic division, then scale by (hi - lo)^i so that
    // g(v) = f(lo + (hi - lo) v) on v in [0, 1] (MATH.md 3.8, restriction to [u_lo, 1]).
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
    int s = sign_of(beta[static_cast<std::size_t>(j)]);
    if (s == 0 || (common != 0 && s != common))
      return 0;
    common = s;
  }
  return common;
}

int bernstein_sign_subdivided(const IntervalPoly& f, double lo, int depth) {
  // A definite sign change proves a root in [lo, 1], so no subdivision can settle f: certificates
  // that fail inside the slab leave here after two evaluations instead of 2^depth pieces.
  const int at_lo = interval_sign(f, lo, lo), at_hi = interval_sign(f, 1.0, 1.0);
  if (at_lo * at_hi < 0)
    return 0;
  // Depth-first over dyadic pieces of [lo, 1]; each piece must be decided with one common sign.
  struct Piece {
    double lo, hi;
    int depth;
  };
  Piece stack[64];
  int top = 0, common = at_lo != 0 ? at_lo : at_hi;
  stack[top++] = {lo, 1.0, 0};
  std::array<Interval, IntervalPoly::max_degree + 1> beta{};
  while (top > 0) {
    Piece p = stack[--top];
    const int n = bernstein_coefficients(f, p.lo, p.hi, beta);
    if (n < 0)
      return 0;
    // beta_0 and beta_n are f at the piece's ends, up to positive factors.
    const int first = sign_of(beta[0]), last = sign_of(beta[static_cast<std::size_t>(n)]);
    if ((first != 0 && common != 0 && first != common) || (last != 0 && common != 0 && last != common))
      return 0;
    int s = 0;
    for (int j = 0; j <= n; ++j) {
      const int sj = sign_of(beta[static_cast<std::size_t>(j)]);
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

int interval_sign(const IntervalPoly& f, double lo, double hi) {
  int n = degree_of(f);
  if (n < 0)
    return 0;
  const Interval u(lo, hi);
  Interval acc = f[n];
  for (int i = n - 1; i >= 0; --i)
    acc = acc * u + f[i];
  return sign_of(acc);
}

int proportionality_sign(const IntervalPoly& f, const IntervalPoly& g, int shift) {
  const int n = std::min(f.degree_bound() - shift, g.degree_bound());
  for (int i = 0; i <= n; ++i) {
    const int a = sign_of(f[i + shift]), b = sign_of(g[i]);
    if (a != 0 && b != 0)
      return a * b;
  }
  return 0;
}

} // namespace medusa::kinetic
