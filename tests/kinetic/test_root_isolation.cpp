// Certified root isolation in doubles (root_isolation.h) and exact comparison of the times it
// produces (SlabTime over IsolatedRoot). Expected roots are derived on paper.
#include "algebraic_time.h"
#include "root_cache.h"
#include "root_isolation.h"

#include <CGAL/FPU.h>
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <random>
#include <stdexcept>

using namespace medusa::kinetic;

namespace {

// Integer polynomial c0 + c1 u + c2 u^2 + ... as exact and interval polynomials.
Poly<mpz_class> exact_poly(std::initializer_list<long> c) {
  Poly<mpz_class> f;
  Poly<mpz_class> mono{mpz_class(1)};
  const Poly<mpz_class> u{mpz_class(0), mpz_class(1)};
  for (long x : c) {
    f = f + Poly<mpz_class>{mpz_class(x)} * mono;
    mono = mono * u;
  }
  return f;
}

IntervalPoly interval_poly(std::initializer_list<long> c) {
  IntervalPoly f;
  IntervalPoly mono{Interval(1)};
  const IntervalPoly u{Interval(0), Interval(1)};
  for (long x : c) {
    f = f + IntervalPoly{Interval(static_cast<double>(x))} * mono;
    mono = mono * u;
  }
  return f;
}

// The time of the first root after `start` of the polynomial with coefficients c, isolated in doubles.
SlabTime isolated_time(std::initializer_list<long> c, double start = 0.0) {
  CGAL::Protect_FPU_rounding<true> guard;
  IntervalPoly f = interval_poly(c);
  FirstSignChange r = first_sign_change(f, start, 12);
  REQUIRE(r.status == FirstSignChange::Status::root);
  Poly<mpz_class> e = exact_poly(c);
  auto root = make_isolated_root([e] { return to_exact_poly(e); });
  root->enclosure = f;
  root->lo = r.lo;
  root->hi = r.hi;
  root->sign_lo = r.sign;
  return SlabTime(root);
}

// The root of 10^6 u + c0 on (lo, hi), where it is negative at lo, with each coefficient's enclosure
// widened by `widen` as if from plain doubles; `requests` counts the calls for its exact polynomial.
SlabTime widened_linear_root(long c0, double widen, double lo, double hi, int& requests) {
  auto root = make_isolated_root([c0, &requests] {
    ++requests;
    return to_exact_poly(exact_poly({c0, 1000000}));
  });
  root->enclosure = IntervalPoly{Interval(static_cast<double>(c0) - widen, static_cast<double>(c0) + widen),
                                 Interval(1000000 - widen, 1000000 + widen)};
  root->wide = true;
  root->lo = lo;
  root->hi = hi;
  root->sign_lo = -1;
  return SlabTime(root);
}

// Both ends of t's enclosure bracket `root`.
void require_encloses(const SlabTime& t, double root) {
  double lo, hi;
  t.enclosure(lo, hi);
  REQUIRE(lo < root);
  REQUIRE(root < hi);
}

} // namespace

TEST_CASE("isolation finds the flip time of the worked example in an interval around it",
          "[kinetic][isolation]") {
  // 32u^2 - 94u + 61 (docs/MATH.md §B) is positive at 0 and has its first root at
  // u* = (47 - sqrt(257)) / 32 ~ 0.96778; the other root (47 + sqrt(257)) / 32 > 1.
  CGAL::Protect_FPU_rounding<true> guard;
  FirstSignChange r = first_sign_change(interval_poly({61, -94, 32}), 0.0, 12);
  REQUIRE(r.status == FirstSignChange::Status::root);
  REQUIRE(r.sign == 1);
  const double u = (47.0 - std::sqrt(257.0)) / 32.0;
  REQUIRE(r.lo < u);
  REQUIRE(u < r.hi);
}

TEST_CASE("isolation proves a polynomial without roots after the start keeps its sign",
          "[kinetic][isolation]") {
  // (u - 1/4)(u - 3/4) = u^2 - u + 3/16, times 16: roots 1/4 and 3/4, negative between them.
  CGAL::Protect_FPU_rounding<true> guard;
  FirstSignChange r = first_sign_change(interval_poly({3, -16, 16}), 0.8, 12);
  REQUIRE(r.status == FirstSignChange::Status::none);
  REQUIRE(r.sign == 1);
  FirstSignChange s = first_sign_change(interval_poly({3, -16, 16}), 0.5, 12);
  REQUIRE(s.status == FirstSignChange::Status::root);
  REQUIRE(s.sign == -1);
  REQUIRE(s.lo < 0.75);
  REQUIRE(0.75 < s.hi);
}

TEST_CASE("isolation refuses a root at the start and a double root", "[kinetic][isolation]") {
  CGAL::Protect_FPU_rounding<true> guard;
  // 2u - 1 vanishes at the start 1/2: the sign just after it is not decided in doubles.
  REQUIRE(first_sign_change(interval_poly({-1, 2}), 0.5, 12).status == FirstSignChange::Status::undecided);
  // 4(u - 1/2)^2 touches 0 without changing sign: no certified answer either way.
  REQUIRE(first_sign_change(interval_poly({1, -4, 4}), 0.0, 12).status == FirstSignChange::Status::undecided);
}

TEST_CASE("refinement narrows an isolating interval to the root and finds dyadic roots exactly",
          "[kinetic][isolation]") {
  CGAL::Protect_FPU_rounding<true> guard;
  // 2u^2 - 1: root 1/sqrt(2).
  IntervalPoly f = interval_poly({-1, 0, 2});
  double lo = 0.0, hi = 1.0;
  while (refine_root(f, lo, hi, -1) == Refinement::narrowed) {
  }
  REQUIRE(lo <= std::sqrt(0.5));
  REQUIRE(std::sqrt(0.5) <= hi);
  REQUIRE(hi - lo < 1e-15);
  // 8u - 3: root 3/8, met exactly by bisection of (0, 1).
  IntervalPoly g = interval_poly({-3, 8});
  lo = 0.0;
  hi = 1.0;
  Refinement step = Refinement::narrowed;
  while (step == Refinement::narrowed)
    step = refine_root(g, lo, hi, -1);
  REQUIRE(step == Refinement::exact);
  REQUIRE(lo == 0.375);
  REQUIRE(hi == 0.375);
}

TEST_CASE("a bisection step whose midpoint has no certified sign cuts at the quarter points",
          "[kinetic][isolation]") {
  CGAL::Protect_FPU_rounding<true> guard;
  // u - [0.499, 0.501]: the sign is certified only outside [0.499, 0.501], so on (0.4, 0.6) the
  // midpoint 0.5 is undecided, while the quarter points 0.45 (negative) and 0.55 (positive) are
  // decided: the root 1/2 lies in the middle half.
  const IntervalPoly f{Interval(-0.501, -0.499), Interval(1)};
  double lo = 0.4, hi = 0.6;
  REQUIRE(refine_root(f, lo, hi, -1) == Refinement::narrowed);
  REQUIRE(lo == 0.45);
  REQUIRE(hi == 0.55);
  // On (0.4995, 0.5005) the quarter points 0.49975 and 0.50025 are undecided too: doubles are done.
  lo = 0.4995;
  hi = 0.5005;
  REQUIRE(refine_root(f, lo, hi, -1) == Refinement::stuck);
  REQUIRE(lo == 0.4995);
  REQUIRE(hi == 0.5005);
}

TEST_CASE("times isolated in doubles compare exactly, equal roots of different polynomials included",
          "[kinetic][isolation]") {
  // 2u^2 - 1 and 2u^3 + 2u^2 - u - 1 (= (2u^2 - 1)(u + 1)) have the same root 1/sqrt(2) in [0, 1]: the
  // enclosures cannot separate them, so the comparison goes exact and answers equal.
  SlabTime a = isolated_time({-1, 0, 2});
  SlabTime b = isolated_time({-1, -1, 2, 2});
  const TimeComparisonCounts before = time_comparison_counts();
  REQUIRE(compare(a, b) == 0);
  REQUIRE(time_comparison_counts().algebraic - before.algebraic == 1);
  REQUIRE(a == b);
  // 1/sqrt(2) < 0.7072 = 884/1250 and > 0.7071; against rationals and another root (4u^2 - 2u - 1 has
  // the root (1 + sqrt(5)) / 4 ~ 0.809).
  REQUIRE(a < SlabTime(Rational(7072, 10000)));
  REQUIRE(SlabTime(Rational(7071, 10000)) < a);
  SlabTime c = isolated_time({-1, -2, 4});
  REQUIRE(a < c);
  REQUIRE(!(c < a));
  // The exact value agrees with CGAL's isolation of the same polynomial.
  REQUIRE(CGAL::to_double(a.algebraic()) == Approx(std::sqrt(0.5)).epsilon(1e-15));
}

TEST_CASE("roots whose wide enclosures leave bisection stuck are told apart on the exact polynomial "
          "rounded to intervals, without algebraic reals",
          "[kinetic][isolation]") {
  // 10^6 u - 371001 and 10^6 u - 371002: roots 0.371001 < 0.371002. Their enclosures, as if from
  // plain doubles, are widened by 5000 on each coefficient, so neither sign is certified on
  // [0.3640, 0.3780] and bisection of the isolating intervals (0.3, 0.45) is stuck at once. Each
  // exact polynomial is asked for once (the rounding to intervals), and no algebraic real is built.
  int requests = 0;
  SlabTime a = widened_linear_root(-371001, 5000, 0.3, 0.45, requests);
  SlabTime b = widened_linear_root(-371002, 5000, 0.3, 0.45, requests);
  const TimeComparisonCounts before = time_comparison_counts();
  REQUIRE(compare(a, b) == -1);
  REQUIRE(compare(b, a) == 1);
  CHECK(requests == 2);
  REQUIRE(time_comparison_counts().sharpened - before.sharpened == 2);
  REQUIRE(time_comparison_counts().algebraic == before.algebraic);
  REQUIRE_FALSE(a.isolated()->algebraic.has_value());
  REQUIRE_FALSE(b.isolated()->algebraic.has_value());
  REQUIRE(a.isolated()->sharp != nullptr);
  REQUIRE(b.isolated()->sharp != nullptr);
  // The sharpened enclosures still isolate the roots: both ends bracket them.
  require_encloses(a, 0.371001);
  require_encloses(b, 0.371002);
}

TEST_CASE("roots narrowed around their own estimates are told apart in doubles, without the exact "
          "polynomial",
          "[kinetic][isolation]") {
  // 10^6 u - 371001 and 10^6 u - 371002, their coefficients widened by 0.01 as if from plain doubles:
  // each sign is certified except within about 1.4e-8 of its root. Each isolating interval is
  // centred on its root (as narrow_root leaves it), 2^-19 wide, so the two overlap and bisection
  // meets an undecided midpoint at once; the quarter points go on until the roots, 10^-6 apart,
  // separate.
  int requests = 0;
  SlabTime a = widened_linear_root(-371001, 0.01, 0.371001 - 0x1p-20, 0.371001 + 0x1p-20, requests);
  SlabTime b = widened_linear_root(-371002, 0.01, 0.371002 - 0x1p-20, 0.371002 + 0x1p-20, requests);
  const TimeComparisonCounts before = time_comparison_counts();
  REQUIRE(compare(a, b) == -1);
  REQUIRE(compare(b, a) == 1);
  REQUIRE(requests == 0);
  REQUIRE(time_comparison_counts().sharpened == before.sharpened);
  REQUIRE(time_comparison_counts().algebraic == before.algebraic);
  require_encloses(a, 0.371001);
  require_encloses(b, 0.371002);
}

TEST_CASE("a time whose enclosure spans many points of the reporting grid is rounded to the nearest on the "
          "exact polynomial, without algebraic reals",
          "[kinetic][isolation]") {
  // Roots c0 / 10^6 of 10^6 u - c0 in the slab from MCS 100 to 200, enclosed as if from plain doubles
  // widened by 5000 on each coefficient: no interval test decides a grid point in (0.3, 0.7), which
  // holds about 2^44 points of the 2^-32 MCS grid. The reported time must be t = 100 + 100 u rounded
  // half up to that grid, computed here in rationals; 500000 puts the root on a grid point (MCS 150).
  for (const long c0 : {371001L, 500000L, 633333L}) {
    CAPTURE(c0);
    auto root = make_isolated_root([c0] { return to_exact_poly(exact_poly({-c0, 1000000})); });
    root->enclosure = IntervalPoly{Interval(static_cast<double>(-c0) - 5000, static_cast<double>(-c0) + 5000),
                                   Interval(1000000 - 5000, 1000000 + 5000)};
    root->lo = 0.3;
    root->hi = 0.7;
    root->sign_lo = -1;
    const SlabTime u(root);
    const TimeComparisonCounts before = time_comparison_counts();
    const double reported = u.reported_time(100, 200);
    const mpq_class t = mpq_class(100) + mpq_class(c0, 1000000) * 100;
    const mpq_class scaled = t * mpq_class(mpz_class(1) << 32) + mpq_class(1, 2);
    mpz_class grid;
    mpz_fdiv_q(grid.get_mpz_t(), scaled.get_num_mpz_t(), scaled.get_den_mpz_t());
    REQUIRE(reported == std::ldexp(grid.get_d(), -32));
    REQUIRE(time_comparison_counts().reported_exactly > before.reported_exactly); // decided exactly
    REQUIRE_FALSE(root->algebraic.has_value());
  }
}

TEST_CASE("isolated times of random quadratics order as their exact roots do", "[kinetic][isolation]") {
  // Roots r = p/q of (q u - p)(u + 1) and the isolated times must order exactly as the rationals.
  const unsigned seed = std::random_device{}();
  CAPTURE(seed);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<long> num(1, 999);
  int compared = 0;
  for (int trial = 0; trial < 200; ++trial) {
    long p1 = num(rng), p2 = num(rng), q = 1000;
    // (q u - p)(u + 1) = -p + (q - p) u + q u^2
    SlabTime t1 = isolated_time({-p1, q - p1, q});
    SlabTime t2 = isolated_time({-p2, q - p2, q});
    int expected = p1 < p2 ? -1 : (p2 < p1 ? 1 : 0);
    REQUIRE(compare(t1, t2) == expected);
    REQUIRE(compare(t1, SlabTime(Rational(p1, q))) == 0);
    ++compared;
  }
  REQUIRE(compared == 200);
}

TEST_CASE("two isolations of one polynomial compare in doubles, without exact arithmetic",
          "[kinetic][isolation]") {
  // 16u^2 - 16u + 3 = (4u - 1)(4u - 3): roots 1/4 and 3/4. Isolating intervals of the same root found
  // from different starts are nested after refinement, so they compare equal; the exact polynomial is
  // never needed (it would throw).
  CGAL::Protect_FPU_rounding<true> guard;
  IntervalPoly f = interval_poly({3, -16, 16});
  auto make = [&](double start) {
    FirstSignChange r = first_sign_change(f, start, 12);
    REQUIRE(r.status == FirstSignChange::Status::root);
    auto root =
        make_isolated_root([]() -> ExactPoly { throw std::logic_error("exact polynomial requested"); });
    root->enclosure = f;
    root->lo = r.lo;
    root->hi = r.hi;
    root->sign_lo = r.sign;
    root->key = {0, 1, 2, 3, 4, 5};
    root->slab = 7;
    return SlabTime(root);
  };
  SlabTime a = make(0.0), b = make(0.1), c = make(0.5);
  REQUIRE(compare(a, b) == 0);
  REQUIRE(compare(b, a) == 0);
  REQUIRE(compare(a, c) == -1);
  REQUIRE(compare(c, b) == 1);
}

TEST_CASE("narrowing reaches the requested width around the root, and the tightest interval doubles allow",
          "[kinetic][isolation]") {
  // (1000 u - p)(u + 1)(u - 2): p/1000 is its only root in (0, 1). Checked exactly: the integer
  // polynomial has opposite signs at the narrowed ends (or vanishes at a dyadic root found exactly).
  const unsigned seed = std::random_device{}();
  CAPTURE(seed);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<long> num(1, 999);
  int narrowed = 0;
  for (int trial = 0; trial < 200; ++trial) {
    // Expanded: 2p + (p - 2000) u - (1000 + p) u^2 + 1000 u^3.
    const long p = num(rng);
    const std::initializer_list<long> c = {2 * p, p - 2000, -1000 - p, 1000};
    const Poly<mpz_class> e = exact_poly(c);
    const double width = trial % 2 == 0 ? 0x1p-24 : 0.0;
    CGAL::Protect_FPU_rounding<true> guard;
    const IntervalPoly f = interval_poly(c);
    const FirstSignChange r = first_sign_change(f, 0.0, 12);
    REQUIRE(r.status == FirstSignChange::Status::root);
    double lo = r.lo, hi = r.hi;
    const Refinement step = narrow_root(f, lo, hi, r.sign, width);
    CAPTURE(p, lo, hi);
    auto exact_at = [&](double x) {
      mpq_class acc = 0;
      for (int i = e.degree_bound(); i >= 0; --i)
        acc = acc * mpq_class(x) + mpq_class(e[i]);
      return acc;
    };
    if (step == Refinement::exact) {
      REQUIRE(lo == hi);
      REQUIRE(exact_at(lo) == 0);
      continue;
    }
    REQUIRE(r.lo <= lo);
    REQUIRE(hi <= r.hi);
    REQUIRE(sgn(exact_at(lo)) == r.sign);
    REQUIRE(sgn(exact_at(hi)) == -r.sign);
    if (width > 0)
      REQUIRE(hi - lo <= width);
    else {
      // As tight as doubles allow: interval Horner at u <= 1 errs by at most about 2n u sum|c_i|
      // (n = 3, u = 2^-53) on each side, so the sign is certified once |f| exceeds that, i.e.
      // outside a zone of half-width 2n u sum|c_i| / |f'(root)| around the root, with
      // f'(p/1000) = 1000 (r + 1)(r - 2). Twice that, plus a few ulps of slack.
      const double r_ = p / 1000.0;
      const double sum = 2.0 * p + std::abs(p - 2000.0) + (1000.0 + p) + 1000.0;
      const double zone = 4.0 * 6.0 * 0x1p-53 * sum / std::abs(1000.0 * (r_ + 1.0) * (r_ - 2.0));
      REQUIRE(hi - lo <= zone + 4 * 0x1p-52);
    }
    ++narrowed;
  }
  REQUIRE(narrowed > 0);
}

TEST_CASE(
    "overlapping isolations of one polynomial, neither inside the other, compare without exact arithmetic",
    "[kinetic][isolation]") {
  // 16u^2 - 16u + 3 = (4u - 1)(4u - 3): roots 1/4 and 3/4. (0.2, 0.3) and (0.24, 0.5) both isolate
  // 1/4: equal. (0.2, 0.5) isolates 1/4 and (0.4, 0.8) isolates 3/4: they overlap on (0.4, 0.5), where
  // the polynomial keeps its sign, so the first is earlier. The exact polynomial would throw.
  IntervalPoly f;
  {
    CGAL::Protect_FPU_rounding<true> guard;
    f = interval_poly({3, -16, 16});
  }
  auto make = [&](double lo, double hi, int sign_lo) {
    auto root =
        make_isolated_root([]() -> ExactPoly { throw std::logic_error("exact polynomial requested"); });
    root->enclosure = f;
    root->lo = lo;
    root->hi = hi;
    root->sign_lo = sign_lo;
    root->key = {0, 1, 2, 3, 4, 5};
    root->slab = 3;
    return SlabTime(root);
  };
  const SlabTime a = make(0.2, 0.3, 1), b = make(0.24, 0.5, 1);
  REQUIRE(compare(a, b) == 0);
  REQUIRE(compare(b, a) == 0);
  const SlabTime first = make(0.2, 0.5, 1), second = make(0.4, 0.8, -1);
  REQUIRE(compare(first, second) == -1);
  REQUIRE(compare(second, first) == 1);
}

TEST_CASE("the tightest narrowing finds every short dyadic root exactly", "[kinetic][isolation]") {
  // f = (2^b u - k) h(u), h > 0 on [0, 1] with small integer coefficients: every coefficient is an
  // exact double, so f vanishes exactly (as a point interval) at k / 2^b and nowhere near it, and
  // narrowing to width 0 must end on lo == hi == k / 2^b (events at equal rational times compare
  // equal, docs/MATH.md §3.7).
  const unsigned seed = std::random_device{}();
  CAPTURE(seed);
  std::mt19937_64 rng(seed);
  CGAL::Protect_FPU_rounding<true> guard;
  int cases = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const int b = 4 + static_cast<int>(rng() % 21); // up to 24 bits
    const long scale = 1L << b;
    const long k = 1 + static_cast<long>(rng() % static_cast<unsigned long>(scale - 1));
    std::array<long, 5> h{};
    for (long& c : h)
      c = 1 + static_cast<long>(rng() % (1u << 20)); // positive: h > 0 on [0, 1]
    std::array<long, 6> c{};
    for (std::size_t i = 0; i < h.size(); ++i) {
      c[i] += -k * h[i];
      c[i + 1] += scale * h[i];
    }
    IntervalPoly f = IntervalPoly::zero_of_degree(5);
    for (int i = 0; i <= 5; ++i)
      f[i] = Interval(static_cast<double>(c[static_cast<std::size_t>(i)]));
    const double q = static_cast<double>(k) / static_cast<double>(scale);
    double lo = std::max(0.0, q - 0x1p-20), hi = std::min(1.0, q + 0x1p-20);
    CAPTURE(b, k);
    REQUIRE(narrow_root(f, lo, hi, -1, 0.0) == Refinement::exact);
    REQUIRE(lo == q);
    REQUIRE(hi == q);
    ++cases;
  }
  REQUIRE(cases == 2000);
}

TEST_CASE("the reported time of an event does not depend on how far its interval was refined",
          "[kinetic][isolation][reported]") {
  // u* = (47 - sqrt(257)) / 32 (docs/MATH.md §B) in the slab [0, 1]. Its cell c = floor(u* 2^33) is the
  // largest k with k <= u* 2^33, i.e. (47 2^33 - 32 k)^2 >= 257 2^66 (both sides positive), checked in
  // integers; the reported time is floor((c + 1) / 2) 2^-32 (docs/MATH.md §3.12).
  const mpz_class two33 = mpz_class(1) << 33;
  auto at_or_below = [&](const mpz_class& k) {
    const mpz_class lhs = 47 * two33 - 32 * k;
    return lhs * lhs >= 257 * two33 * two33;
  };
  mpz_class c(static_cast<unsigned long>(std::floor((47.0 - std::sqrt(257.0)) / 32.0 * 0x1p33)));
  while (!at_or_below(c))
    c -= 1;
  while (at_or_below(c + 1))
    c += 1;
  const double expected = std::ldexp(mpz_class((c + 1) / 2).get_d(), -32);

  const SlabTime wide = isolated_time({61, -94, 32});
  const SlabTime tight = isolated_time({61, -94, 32});
  tight.tighten();
  double lo = 0, hi = 0, tight_lo = 0, tight_hi = 0;
  wide.enclosure(lo, hi);
  tight.enclosure(tight_lo, tight_hi);
  INFO("wide interval width " << hi - lo << ", tight " << tight_hi - tight_lo);
  REQUIRE(tight_hi - tight_lo < hi - lo);
  CHECK(wide.reported_time(0, 1) == expected);
  CHECK(tight.reported_time(0, 1) == expected);
  // In the slab [100, 200] the same u is t = 100 + 100 u*: the same rule on t.
  const mpz_class two33_100 = two33 * 100;
  // k 2^-33 <= 100 + 100 u* iff 100 sqrt(257) 2^33 <= 4700 2^33 - 32 (k - 100 2^33).
  auto at_or_below_t = [&](const mpz_class& k) {
    const mpz_class lhs = 47 * two33_100 - 32 * (k - two33_100);
    return lhs * lhs >= 257 * two33_100 * two33_100;
  };
  mpz_class ct(
      static_cast<unsigned long>(std::floor((100 + 100 * (47.0 - std::sqrt(257.0)) / 32.0) * 0x1p33)));
  while (!at_or_below_t(ct))
    ct -= 1;
  while (at_or_below_t(ct + 1))
    ct += 1;
  CHECK(wide.reported_time(100, 200) == std::ldexp(mpz_class((ct + 1) / 2).get_d(), -32));
}

TEST_CASE("a time on the 2^-32 MCS grid is reported exactly, and one off it at the nearest grid point",
          "[kinetic][isolation][reported]") {
  CHECK(isolated_time({-3, 8}).reported_time(0, 1) == 0.375); // 8u - 3
  // 5u - 4: u = 4/5, not a double; in the slab [0, 100] it is MCS 80, reported exactly.
  CHECK(isolated_time({-4, 5}).reported_time(0, 100) == 80.0);
  CHECK(isolated_time({-4, 5}).reported_time(100, 200) == 180.0);
  // 1/3: 2^32 / 3 = 1431655765.33..., nearest 1431655765.
  CHECK(SlabTime(Rational(1, 3)).reported_time(0, 1) == std::ldexp(1431655765.0, -32));
  // Halves go up: 2^-33 to 2^-32; 3 2^-34 (0.75 of a step) to 2^-32; 2^-34 (0.25) to 0.
  CHECK(SlabTime(Rational(1) / Rational(std::ldexp(1.0, 33))).reported_time(0, 1) == std::ldexp(1.0, -32));
  CHECK(SlabTime(Rational(3) / Rational(std::ldexp(1.0, 34))).reported_time(0, 1) == std::ldexp(1.0, -32));
  CHECK(SlabTime(Rational(1) / Rational(std::ldexp(1.0, 34))).reported_time(0, 1) == 0.0);
  CHECK(SlabTime(Rational(0)).reported_time(40, 60) == 40.0);
  CHECK(SlabTime(Rational(1)).reported_time(40, 60) == 60.0);
}

TEST_CASE("a reported time is the exact time rounded half up to the 2^-32 grid, for any slab and any "
          "time in it",
          "[kinetic][isolation][reported]") {
  // t = t0 + u (t1 - t0) rounded in rationals here, against reported_time's integer counting: doubles
  // u from 0 to 1 (tiny and subnormal ones among them) and rationals p/q that no double holds (their
  // enclosures span grid points), slabs starting before MCS 0 and past 2^40 MCS, where the grid point
  // no longer fits a double and is truncated as GMP's conversion does.
  const unsigned seed = std::random_device{}();
  CAPTURE(seed);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> exponent(0, 1074), pick(0, 4);
  std::uniform_int_distribution<long> start(-1000, 200000), span(1, 1L << 31), den(2, 1000000);
  const auto expected = [](const mpq_class& u, long t0, long t1) {
    const mpq_class t = mpq_class(t0) + u * mpq_class(t1 - t0);
    const mpq_class scaled = t * mpq_class(mpz_class(1) << 32) + mpq_class(1, 2);
    mpz_class grid;
    mpz_fdiv_q(grid.get_mpz_t(), scaled.get_num_mpz_t(), scaled.get_den_mpz_t());
    return std::ldexp(grid.get_d(), -32);
  };
  int compared = 0;
  for (int i = 0; i < 4000; ++i) {
    const long t0 = i % 10 == 0 ? (1L << 40) + start(rng) : start(rng);
    const long t1 = t0 + (i % 7 == 0 ? 1 : span(rng));
    CAPTURE(i, t0, t1);
    if (i % 2 == 0) {
      const int kind = pick(rng);
      const double u = kind == 0   ? std::ldexp(1.0, -exponent(rng))
                       : kind == 1 ? (i % 4 == 0 ? 0.0 : 1.0)
                                   : unit(rng);
      CAPTURE(u);
      CHECK(SlabTime(Rational(u)).reported_time(t0, t1) == expected(mpq_class(u), t0, t1));
    } else {
      const long q = den(rng);
      const long p = std::uniform_int_distribution<long>(0, q)(rng);
      CAPTURE(p, q);
      CHECK(SlabTime(Rational(p) / Rational(q)).reported_time(t0, t1) == expected(mpq_class(p, q), t0, t1));
    }
    ++compared;
  }
  REQUIRE(compared == 4000);
}

TEST_CASE("reported times follow the exact order of the times", "[kinetic][isolation][reported]") {
  // Roots of (u - 1/4)(u - 3/4) times 16, and of 8u - 3 (3/8) between them, in the slab [0, 10].
  const SlabTime first = isolated_time({3, -16, 16});
  const SlabTime middle = isolated_time({-3, 8});
  const SlabTime second = isolated_time({3, -16, 16}, 0.5);
  CHECK(first.reported_time(0, 10) == 2.5);
  CHECK(middle.reported_time(0, 10) == 3.75);
  CHECK(second.reported_time(0, 10) == 7.5);
}

TEST_CASE("times of proportional polynomials compare equal without algebraic reals", "[kinetic][isolation]") {
  // A certificate on translated copies of its cells (docs/MATH.md §8.6) has the exact polynomial of
  // the original's up to sign: here 2u^2 - 1 and -6u^2 + 3, both with the root 1/sqrt(2) alone in
  // [0, 1]. Stuck in doubles, they are told equal on the exact polynomial, with no algebraic real.
  SlabTime a = isolated_time({-1, 0, 2});
  SlabTime b = isolated_time({3, 0, -6});
  const TimeComparisonCounts before = time_comparison_counts();
  REQUIRE(compare(a, b) == 0);
  REQUIRE(compare(b, a) == 0);
  REQUIRE(time_comparison_counts().proportional - before.proportional == 2);
  REQUIRE(time_comparison_counts().algebraic - before.algebraic == 0);
  // Against a root of another polynomial close to it, still decided and in the right order:
  // 1/sqrt(2) < 6369051672525773 / 2^53, the double nearest to it (2 x^2 > 1 for that x).
  SlabTime above(Rational(CGAL::Gmpz("6369051672525773"), CGAL::Gmpz("9007199254740992")));
  REQUIRE(compare(b, above) == -1);
}

TEST_CASE("a certificate on translated points is known to be the same polynomial without computing it",
          "[kinetic][isolation]") {
  // Five moving points and their translates by (7, -3, 11), listed in another order: the in-sphere
  // polynomial is alternating in its points and translation invariant, so the two are equal up to sign
  // (checked here in exact integers). Changing one displacement, or (for the fold test, whose points
  // are ordered) the order, breaks it.
  std::array<MovingPoint, 5> p{{{{0, 0, 0}, {1, 2, 0}},
                                {{5, 1, 0}, {0, -1, 3}},
                                {{1, 6, 2}, {2, 0, 1}},
                                {{2, 2, 7}, {-1, 1, 0}},
                                {{4, 5, 5}, {0, 0, -2}}}};
  const std::array<std::int64_t, 3> t{7, -3, 11};
  std::array<MovingPoint, 5> q;
  const std::array<std::size_t, 5> order{3, 0, 4, 1, 2};
  for (std::size_t i = 0; i < 5; ++i) {
    q[i] = p[order[i]];
    for (std::size_t a = 0; a < 3; ++a)
      q[i].a[a] += t[a];
  }
  const auto key = [](int kind, int count, const std::array<MovingPoint, 5>& pts) {
    detail::KeyPolynomial k;
    k.kind = kind;
    k.count = count;
    auto motion = std::make_shared<detail::SlabMotion>();
    motion->points.assign(pts.begin(), pts.end());
    k.motion = motion;
    k.ids = {0, 1, 2, 3, 4};
    return k;
  };
  const detail::KeyPolynomial a = key(0, 5, p), b = key(0, 5, q);
  REQUIRE(a.translate_of(b));
  REQUIRE(b.translate_of(a));
  const ExactPoly fa = a(), fb = b();
  REQUIRE((fa == fb || fa == -fb));
  REQUIRE(make_isolated_root(a)->same_polynomial_as(*make_isolated_root(b)));

  std::array<MovingPoint, 5> r = q;
  r[2].b[0] += 1;
  REQUIRE(!a.translate_of(key(0, 5, r)));
  REQUIRE(!make_isolated_root(a)->same_polynomial_as(*make_isolated_root(key(0, 5, r))));

  // The fold test (kind 3) of a ridge p0 p1 with apices p2, p3 is not symmetric in its points.
  REQUIRE(key(3, 4, p).translate_of(key(3, 4, [&] {
    std::array<MovingPoint, 5> s = p;
    for (MovingPoint& m : s)
      for (std::size_t x = 0; x < 3; ++x)
        m.a[x] += t[x];
    return s;
  }())));
  std::array<MovingPoint, 5> swapped = p; // the ridge's two points exchanged: the same set of points
  std::swap(swapped[0], swapped[1]);
  REQUIRE(key(0, 4, p).translate_of(key(0, 4, swapped)));
  REQUIRE(!key(3, 4, p).translate_of(key(3, 4, swapped)));
}
