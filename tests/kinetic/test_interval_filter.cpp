#include "interval_filter.h"

#include <CGAL/FPU.h>
#include <catch2/catch.hpp>
#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <vector>

using namespace medusa::kinetic;

namespace {
IntervalPoly poly(std::initializer_list<double> c) {
  IntervalPoly f;
  IntervalPoly mono{Interval(1)};
  const IntervalPoly u{Interval(0), Interval(1)};
  for (double x : c) {
    f = f + IntervalPoly{Interval(x)} * mono;
    mono = mono * u;
  }
  return f;
}
} // namespace

TEST_CASE("the Bernstein filter proves the worked example's orientation certificate positive",
          "[kinetic][filter]") {
  // O(b,a,d,e) = 320 - 240u of docs/MATH.md §B: Bernstein (320, 80), positive on [0, 1].
  CGAL::Protect_FPU_rounding<true> guard;
  REQUIRE(bernstein_sign(poly({320, -240}), 0.0) == 1);
  REQUIRE(bernstein_sign(poly({-320, 240}), 0.0) == -1);
}

TEST_CASE("the Bernstein filter refuses to decide a polynomial with a root in the slab",
          "[kinetic][filter]") {
  // 32u^2 - 94u + 61 has a root at u ~ 0.9678 (docs/MATH.md §B).
  CGAL::Protect_FPU_rounding<true> guard;
  REQUIRE(bernstein_sign(poly({61, -94, 32}), 0.0) == 0);
  // On [0.97, 1] it is negative throughout.
  REQUIRE(bernstein_sign(poly({61, -94, 32}), 0.97) == -1);
}

TEST_CASE("interval evaluation decides the sign away from roots only", "[kinetic][filter]") {
  CGAL::Protect_FPU_rounding<true> guard;
  IntervalPoly f = poly({-1, 2}); // root at 1/2
  REQUIRE(interval_sign(f, 0.75, 0.8) == 1);
  REQUIRE(interval_sign(f, 0.1, 0.2) == -1);
  REQUIRE(interval_sign(f, 0.4, 0.6) == 0);
}

TEST_CASE("subdivision proves a polynomial without roots that one Bernstein test cannot",
          "[kinetic][filter]") {
  // f = (4u - 2)^2 + 1/100 > 0 on [0, 1]: Bernstein coefficients on [0, 1] are (4.01, -3.99, 4.01),
  // so one test is undecided; on [0, 1/2] and [1/2, 1] they are all positive.
  CGAL::Protect_FPU_rounding<true> guard;
  IntervalPoly f = poly({4.01, -16, 16});
  REQUIRE(bernstein_sign(f, 0.0) == 0);
  REQUIRE(bernstein_sign_subdivided(f, 0.0, 3) == 1);
  // With a real root it stays undecided at every depth.
  REQUIRE(bernstein_sign_subdivided(poly({3.99, -16, 16}), 0.0, 6) == 0);
}

TEST_CASE("subdivision settles negative polynomials and refuses every sign change", "[kinetic][filter]") {
  CGAL::Protect_FPU_rounding<true> guard;
  // -((4u - 2)^2 + 1/100) < 0 on [0, 1], with the same undecided first test as above.
  REQUIRE(bernstein_sign_subdivided(poly({-4.01, 16, -16}), 0.0, 3) == -1);
  // Opposite signs at the ends (a root at 1/2, or at 0.9678 in docs/MATH.md §B's certificate).
  REQUIRE(bernstein_sign_subdivided(poly({-1, 2}), 0.0, 6) == 0);
  REQUIRE(bernstein_sign_subdivided(poly({61, -94, 32}), 0.0, 6) == 0);
  // After its root, on [0.97, 1], the same certificate is negative throughout.
  REQUIRE(bernstein_sign_subdivided(poly({61, -94, 32}), 0.97, 6) == -1);
  // A root of even multiplicity inside: (2u - 1)^2 vanishes at 1/2 without changing sign.
  REQUIRE(bernstein_sign_subdivided(poly({1, -4, 4}), 0.0, 6) == 0);
}

TEST_CASE("the Bernstein test on a subinterval uses that interval only", "[kinetic][filter]") {
  CGAL::Protect_FPU_rounding<true> guard;
  IntervalPoly f = poly({-1, 2}); // root at 1/2
  REQUIRE(bernstein_sign(f, 0.0, 0.25) == -1);
  REQUIRE(bernstein_sign(f, 0.75, 1.0) == 1);
  REQUIRE(bernstein_sign(f, 0.25, 0.75) == 0);
}

TEST_CASE("the sign of the factor between two enclosures of one polynomial is read off a coefficient",
          "[kinetic][filter]") {
  CGAL::Protect_FPU_rounding<true> guard;
  IntervalPoly f = poly({0, 3, -1}); // 3u - u^2 = u (3 - u)
  REQUIRE(proportionality_sign(f, poly({0, -6, 2})) == -1);
  REQUIRE(proportionality_sign(f, poly({0, 1.5, -0.5})) == 1);
  // With u divided out of f: g = 3 - u, so f = u g.
  REQUIRE(proportionality_sign(f, poly({3, -1}), 1) == 1);
  REQUIRE(proportionality_sign(f, poly({-3, 1}), 1) == -1);
  // Enclosures that all contain zero decide nothing.
  IntervalPoly wide;
  wide = IntervalPoly{Interval(-1, 1)};
  REQUIRE(proportionality_sign(wide, poly({2})) == 0);
}

namespace {

// A random interval polynomial for the bound tests: a product of up to 8 factors (u - r) in interval
// arithmetic, half of them with a root in [near_lo, near_hi] (there the large coefficients cancel,
// the hard case for error bounds), the others anywhere in [-1, 2]; scaled by a power of two from
// 2^-300 to 2^300; its coefficients kept as computed, widened by 1e-15 or by 1e-6 relative.
IntervalPoly random_test_polynomial(std::mt19937& rng, double near_lo, double near_hi) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> degree(0, 8), scale(-300, 300), widen(0, 2);
  const int n = degree(rng);
  IntervalPoly f{Interval(std::ldexp(1.0, scale(rng)))};
  for (int k = 0; k < n; ++k) {
    const double r = k % 2 == 0 ? near_lo + (near_hi - near_lo) * unit(rng) : 3.0 * unit(rng) - 1.0;
    f = f * IntervalPoly{Interval(-r), Interval(1)};
  }
  const int w = widen(rng);
  for (int i = 0; w > 0 && i <= f.degree_bound(); ++i) {
    const double m = std::max(std::fabs(f[i].inf()), std::fabs(f[i].sup()));
    f[i] = f[i] + Interval(-m, m) * Interval(w == 1 ? 1e-15 : 1e-6);
  }
  return f;
}

// The exact value at x of the polynomial whose coefficients are the lower (upper) ends of f's.
mpq_class exact_value_of_ends(const IntervalPoly& f, double x, bool upper) {
  mpq_class v = 0;
  for (int i = f.degree_bound(); i >= 0; --i)
    v = v * mpq_class(x) + mpq_class(upper ? f[i].sup() : f[i].inf());
  return v;
}

} // namespace

TEST_CASE("point values from doubles enclose every polynomial of the enclosure, cancellations included",
          "[kinetic][filter]") {
  // For x >= 0 the smallest and largest values over the coefficient box are those of the lower and
  // upper ends: each is checked exactly in rationals, on polynomials with roots within 1e-6 of x.
  const unsigned seed = std::random_device{}();
  CAPTURE(seed);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  CGAL::Protect_FPU_rounding<true> guard;
  int decided = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const double x = trial % 10 == 0 ? std::ldexp(std::round(std::ldexp(unit(rng), 6)), -6) : unit(rng);
    const IntervalPoly f = random_test_polynomial(rng, x - 5e-7, x + 5e-7);
    CAPTURE(trial, f.degree_bound(), x);
    const std::optional<Interval> v = value_at_point_from_doubles(f, x);
    REQUIRE(v.has_value());
    REQUIRE(mpq_class(v->inf()) <= exact_value_of_ends(f, x, false));
    REQUIRE(exact_value_of_ends(f, x, true) <= mpq_class(v->sup()));
    const Interval full = value_at_point(f, x);
    REQUIRE(mpq_class(full.inf()) <= exact_value_of_ends(f, x, false));
    REQUIRE(exact_value_of_ends(f, x, true) <= mpq_class(full.sup()));
    decided += v->inf() > 0 || v->sup() < 0;
  }
  // The cheap stage must actually settle signs, not only be safe. It settles about 39% of these
  // polynomials (1,146-1,183 of 3,000 in six runs); as a binomial count its standard deviation is
  // about 27, so 900 lies 9 deviations below the mean: a failure means the filter lost power.
  REQUIRE(decided > 900);
}

TEST_CASE("a polynomial vanishing exactly at a dyadic point evaluates to exactly zero there",
          "[kinetic][filter]") {
  // (u - 5/8)(3u^2 + 1) = 3u^3 - 15/8 u^2 + u - 5/8: the doubles' bound cannot exclude zero, so the
  // interval stage runs, and every one of its steps is exact.
  CGAL::Protect_FPU_rounding<true> guard;
  const IntervalPoly f = poly({-0.625, 1, -1.875, 3});
  const Interval v = value_at_point(f, 0.625);
  REQUIRE(v.inf() == 0);
  REQUIRE(v.sup() == 0);
  REQUIRE(value_at_point(f, 0.5).sup() < 0);
  REQUIRE(value_at_point(f, 0.75).inf() > 0);
}

namespace {

// beta_j of bernstein_coefficients, exactly: g(v) = f(lo + (hi - lo) v), then binomial sums.
std::vector<mpq_class> exact_bernstein(const IntervalPoly& f, double lo, double hi, bool upper) {
  const int n = f.degree_bound();
  std::vector<mpq_class> a(static_cast<std::size_t>(n + 1)), g(a.size());
  for (int i = 0; i <= n; ++i)
    a[static_cast<std::size_t>(i)] = upper ? f[i].sup() : f[i].inf();
  const mpq_class l(lo), s = mpq_class(hi) - mpq_class(lo);
  mpz_class choose;
  for (int i = 0; i <= n; ++i) {
    mpq_class sum = 0, lp = 1;
    for (int j = i; j <= n; ++j) {
      mpz_bin_uiui(choose.get_mpz_t(), static_cast<unsigned long>(j), static_cast<unsigned long>(i));
      sum += mpq_class(choose) * lp * a[static_cast<std::size_t>(j)];
      lp *= l;
    }
    mpq_class sp = 1;
    for (int k = 0; k < i; ++k)
      sp *= s;
    g[static_cast<std::size_t>(i)] = sum * sp;
  }
  std::vector<mpq_class> beta(a.size());
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= j; ++i) {
      mpz_bin_uiui(choose.get_mpz_t(), static_cast<unsigned long>(n - i), static_cast<unsigned long>(j - i));
      beta[static_cast<std::size_t>(j)] += mpq_class(choose) * g[static_cast<std::size_t>(i)];
    }
  return beta;
}

} // namespace

TEST_CASE("Bernstein coefficients from doubles enclose those of every polynomial of the enclosure",
          "[kinetic][filter]") {
  // The map from coefficients to Bernstein coefficients on [lo, hi] within [0, 1] has non-negative
  // weights, so over the coefficient box beta_j is smallest at the lower ends and largest at the
  // upper ends: both are computed exactly in rationals, on polynomials with roots in [lo, hi].
  const unsigned seed = std::random_device{}();
  CAPTURE(seed);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  CGAL::Protect_FPU_rounding<true> guard;
  int certified = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    double lo = unit(rng), hi = unit(rng);
    if (trial % 3 == 0)
      hi = 1.0;
    if (trial % 7 == 0)
      lo = 0.0;
    if (lo > hi)
      std::swap(lo, hi);
    if (!(lo < hi))
      continue;
    const IntervalPoly f = random_test_polynomial(rng, lo, hi);
    CAPTURE(trial, f.degree_bound(), lo, hi);
    const std::vector<mpq_class> low = exact_bernstein(f, lo, hi, false),
                                 high = exact_bernstein(f, lo, hi, true);
    std::array<Interval, IntervalPoly::max_degree + 1> beta{};
    if (bernstein_coefficients_from_doubles(f, lo, hi, beta)) {
      ++certified;
      for (int j = 0; j <= f.degree_bound(); ++j) {
        CAPTURE(j);
        REQUIRE(mpq_class(beta[static_cast<std::size_t>(j)].inf()) <= low[static_cast<std::size_t>(j)]);
        REQUIRE(high[static_cast<std::size_t>(j)] <= mpq_class(beta[static_cast<std::size_t>(j)].sup()));
      }
    }
    REQUIRE(bernstein_coefficients(f, lo, hi, beta) == f.degree_bound());
    for (int j = 0; j <= f.degree_bound(); ++j) {
      REQUIRE(mpq_class(beta[static_cast<std::size_t>(j)].inf()) <= low[static_cast<std::size_t>(j)]);
      REQUIRE(high[static_cast<std::size_t>(j)] <= mpq_class(beta[static_cast<std::size_t>(j)].sup()));
    }
  }
  // 1,895-1,912 in six runs, a binomial count with a standard deviation below 30: 1,500 lies more than
  // 13 deviations below, so a failure means the bound from doubles lost power, not bad luck.
  REQUIRE(certified > 1500);
}

TEST_CASE("the subdivided filter refuses a polynomial vanishing at the left end of its interval",
          "[kinetic][filter]") {
  // f = (4u - 1)(u + 1) vanishes at u = 1/4 and is positive on (1/4, 1]: "no root on [1/4, 1]" is
  // false, so the filter must answer 0 (and does so without subdividing); just right of the root
  // it proves the sign.
  CGAL::Protect_FPU_rounding<true> guard;
  const IntervalPoly f = poly({-1, 3, 4});
  REQUIRE(bernstein_sign_subdivided(f, 0.25, 4) == 0);
  REQUIRE(bernstein_sign_subdivided(f, 0.3, 4) == 1);
  REQUIRE(bernstein_sign_subdivided(Interval(-1) * f, 0.3, 4) == -1);
}

namespace {

// Sturm's oracle over the rationals, independent of the filter: the sign of f at lo, and the number
// of distinct real roots of f in (lo, 1].
using QPoly = std::vector<mpq_class>; // coefficients, lowest degree first, no trailing zeros

void trim(QPoly& p) {
  while (!p.empty() && p.back() == 0)
    p.pop_back();
}

mpq_class evaluate(const QPoly& p, const mpq_class& x) {
  mpq_class acc = 0;
  for (std::size_t i = p.size(); i-- > 0;)
    acc = acc * x + p[i];
  return acc;
}

QPoly remainder(QPoly a, const QPoly& b) {
  while (a.size() >= b.size() && !a.empty()) {
    const mpq_class q = a.back() / b.back();
    const std::size_t shift = a.size() - b.size();
    for (std::size_t i = 0; i < b.size(); ++i)
      a[shift + i] -= q * b[i];
    a.pop_back(); // cancelled exactly
    trim(a);
  }
  return a;
}

int sign_variations(const std::vector<QPoly>& chain, const mpq_class& x) {
  int count = 0, last = 0;
  for (const QPoly& p : chain) {
    const int s = sgn(evaluate(p, x));
    if (s != 0) {
      if (last != 0 && s != last)
        ++count;
      last = s;
    }
  }
  return count;
}

int roots_in(const QPoly& f, const mpq_class& lo, const mpq_class& hi) {
  std::vector<QPoly> chain{f};
  QPoly d;
  for (std::size_t i = 1; i < f.size(); ++i)
    d.push_back(f[i] * static_cast<long>(i));
  trim(d);
  while (!d.empty()) {
    chain.push_back(d);
    QPoly r = remainder(chain[chain.size() - 2], d);
    for (mpq_class& c : r)
      c = -c;
    d = r;
  }
  return sign_variations(chain, lo) - sign_variations(chain, hi);
}

} // namespace

TEST_CASE(
    "a sign from the subdivided filter holds on the whole interval, near-dominant constant terms included",
    "[kinetic][filter]") {
  // The filter first tries |f(lo)| > sum_{i >= 1} |f_i|. Polynomials whose |f(lo)| lies between 0 and
  // 1.2 times that sum, with roots in [lo, 1] and without, are checked against Sturm's theorem in exact
  // rationals: every sign the filter gives must be f's on all of [lo, 1].
  const unsigned seed = std::random_device{}();
  CAPTURE(seed);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0), coefficient(-1.0, 1.0), margin(-1.0, 0.2);
  std::uniform_int_distribution<int> degree(1, IntervalPoly::max_degree);
  CGAL::Protect_FPU_rounding<true> guard;
  int decided = 0, with_roots = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const int n = degree(rng);
    const double lo = trial % 2 == 0 ? 0.0 : unit(rng);
    std::vector<double> c(static_cast<std::size_t>(n + 1));
    double tail = 0;
    for (int i = 1; i <= n; ++i) {
      c[static_cast<std::size_t>(i)] = coefficient(rng);
      tail += std::abs(c[static_cast<std::size_t>(i)]);
    }
    // At lo > 0 the test reads f(lo), not f_0: place f(lo) near the tail instead.
    double rest_at_lo = 0, power = 1;
    for (int i = 1; i <= n; ++i) {
      power *= lo;
      rest_at_lo += c[static_cast<std::size_t>(i)] * power;
    }
    const double target = (trial % 4 < 2 ? 1.0 : -1.0) * tail * (1.0 + margin(rng));
    c[0] = target - rest_at_lo;
    IntervalPoly f = IntervalPoly::zero_of_degree(n);
    QPoly q;
    for (int i = 0; i <= n; ++i) {
      f[i] = Interval(c[static_cast<std::size_t>(i)]);
      q.push_back(mpq_class(c[static_cast<std::size_t>(i)]));
    }
    trim(q);
    CAPTURE(trial, n, lo, c);
    const mpq_class l(lo);
    const int at_lo = sgn(evaluate(q, l));
    const int inside = roots_in(q, l, mpq_class(1));
    with_roots += (inside > 0 || at_lo == 0) ? 1 : 0;
    const int s = bernstein_sign_subdivided(f, lo, 4);
    if (s != 0) {
      ++decided;
      REQUIRE(at_lo == s);
      REQUIRE(inside == 0);
    }
  }
  // Both kinds must be present, or the test proves nothing: about a fifth of the polynomials have a
  // root in the interval, and most of the others are decided.
  REQUIRE(with_roots > 400);
  REQUIRE(decided > 2000);
}

TEST_CASE("the dominance test reads the lower end of a wide constant term", "[kinetic][filter]") {
  // f_0 in [0.9, 1.1], f_1 = -0.95: the centre outweighs f_1 but 0.9 - 0.95 u, in the enclosure,
  // vanishes at u = 18/19, so no sign may be claimed on [0, 1]; 1.1 - 0.95 u has none there.
  CGAL::Protect_FPU_rounding<true> guard;
  IntervalPoly f = IntervalPoly::zero_of_degree(1);
  f[0] = Interval(0.9, 1.1);
  f[1] = Interval(-0.95);
  REQUIRE(bernstein_sign_subdivided(f, 0.0, 6) == 0);
  f[0] = Interval(0.96, 1.1);
  REQUIRE(bernstein_sign_subdivided(f, 0.0, 0) == 1);
  REQUIRE(bernstein_sign_subdivided(Interval(-1) * f, 0.0, 0) == -1);
  // Left of 0 the bound |u^i - lo^i| <= 1 fails: 1/2 - u is 3/2 at -1, more than its tail 1, and
  // vanishes at 1/2, so no sign may be claimed on [-1, 1].
  REQUIRE(bernstein_sign_subdivided(poly({0.5, -1}), -1.0, 4) == 0);
}
