// Exact times inside a slab (algebraic_time.h): choosing rationals just after an algebraic time, as
// the static repair at an event time does (Engine::delaunay_after_algebraic_now), and the signs of a
// polynomial just before and just after a time (Engine::flat_without_turning_at_now).
#include "algebraic_time.h"
#include "medusa/core/error.h"

#include <catch2/catch.hpp>

using namespace medusa::kinetic;

namespace {

// The positive root of 9e12 u^2 - (4e12 + 1): sqrt(4/9 + 1/9e12) = 2/3 + 1/(12e12) + O(1e-26), an
// irrational time just above the simple rational 2/3.
SlabTime just_above_two_thirds() {
  Poly<mpz_class> f = Poly<mpz_class>::zero_of_degree(2);
  f[0] = -mpz_class("4000000000001");
  f[2] = mpz_class("9000000000000");
  std::vector<std::pair<AlgebraicReal, int>> roots;
  AlgebraicKernel().solve_1_object()(to_exact_poly(f), std::back_inserter(roots));
  REQUIRE(roots.size() == 2);
  return SlabTime(roots[1].first);
}

// Whether r - a <= (b - a) / 4, exactly: (4r - b) / 3 <= a.
bool within_a_quarter(const SlabTime& a, const Rational& r, const Rational& b) {
  return !(a < SlabTime((4 * r - b) / 3));
}

} // namespace

TEST_CASE("rationals chosen after an algebraic time just above 2/3 close in on it by a quarter each step",
          "[kinetic][algebraic]") {
  // Quartered 40 times, the gap falls below 4^-40 / 12 < 2^-83, far below the 8.3e-14 between the time
  // and 2/3. rational_between, which the static repair at an algebraic time used before, fails the
  // quarter bound here once its dyadics come near 2/3 (step 19 with CGAL 5.5).
  const SlabTime a = just_above_two_thirds();
  REQUIRE_FALSE(a.is_rational());
  REQUIRE(SlabTime(Rational(2, 3)) < a);
  REQUIRE(a < SlabTime(Rational(2, 3) + Rational(1, 1000000) * Rational(1, 1000000)));
  Rational b(3, 4);
  for (int step = 0; step < 40; ++step) {
    CAPTURE(step);
    const Rational r = rational_closer_after(a, b);
    REQUIRE(a < SlabTime(r));
    REQUIRE(r < b);
    REQUIRE(within_a_quarter(a, r, b));
    b = r;
  }
  // 2/3 + 8.4e-14 is above the time; b must already be below it, 2^-83 away from the time at most.
  REQUIRE(SlabTime(b) < SlabTime(Rational(2, 3) + Rational(84, 1000000000) * Rational(1, 1000000)));
}

TEST_CASE("a rational chosen after a rational time is a quarter of the way to the bound",
          "[kinetic][algebraic]") {
  const SlabTime a(Rational(1, 3));
  const Rational r = rational_closer_after(a, Rational(1, 2));
  REQUIRE(r == Rational(3, 8)); // 1/3 + (1/2 - 1/3) / 4
}

TEST_CASE("a rational after a time is refused when the bound is not after it", "[kinetic][algebraic]") {
  const SlabTime a = just_above_two_thirds();
  REQUIRE_THROWS_AS(rational_closer_after(a, Rational(2, 3)), medusa::InternalError);
  REQUIRE_THROWS_AS(rational_closer_after(SlabTime(Rational(1, 2)), Rational(1, 2)), medusa::InternalError);
}

TEST_CASE("the sign just before a time tells a root where a polynomial turns from one where it touches zero",
          "[kinetic][algebraic]") {
  // (2u - 1)^k at u = 1/2: zero there, positive after, (-1)^k before.
  Poly<mpz_class> line = Poly<mpz_class>::zero_of_degree(1);
  line[0] = -1;
  line[1] = 2;
  const SlabTime half(Rational(1, 2));
  Poly<mpz_class> f = line;
  for (int k = 1; k <= 4; ++k, f = f * line) {
    CAPTURE(k);
    REQUIRE(sign_plus(to_exact_poly(f), half) == 1);
    REQUIRE(sign_minus(to_exact_poly(f), half) == (k % 2 == 0 ? 1 : -1));
  }
  // Away from a root both sides have the sign at the time; the zero polynomial has none.
  REQUIRE(sign_minus(to_exact_poly(line), SlabTime(Rational(1, 3))) == -1);
  REQUIRE(sign_minus(to_exact_poly(Poly<mpz_class>::zero_of_degree(1)), half) == 0);
}

TEST_CASE("the sign just before an irrational root follows the parity of its multiplicity",
          "[kinetic][algebraic]") {
  // g = 9e12 u^2 - (4e12 + 1) has the simple root a just above 2/3 and g' = 18e12 u > 0 there: g < 0
  // just before a; g^2 touches zero at a and is positive on both sides.
  const SlabTime a = just_above_two_thirds();
  Poly<mpz_class> g = Poly<mpz_class>::zero_of_degree(2);
  g[0] = -mpz_class("4000000000001");
  g[2] = mpz_class("9000000000000");
  REQUIRE(sign_minus(to_exact_poly(g), a) == -1);
  REQUIRE(sign_plus(to_exact_poly(g), a) == 1);
  REQUIRE(sign_minus(to_exact_poly(g * g), a) == 1);
  REQUIRE(sign_minus(to_exact_poly(-(g * g * g)), a) == 1);
  REQUIRE(sign_plus(to_exact_poly(-(g * g * g)), a) == -1);
}
