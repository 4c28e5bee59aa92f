#include "medusa/kinetic/interval_filter.h"

#include <CGAL/FPU.h>
#include <catch2/catch.hpp>

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
  // O(b,a,d,e) = 320 - 240u of MATH.md Appendix B: Bernstein (320, 80), positive on [0, 1].
  CGAL::Protect_FPU_rounding<true> guard;
  REQUIRE(bernstein_sign(poly({320, -240}), 0.0) == 1);
  REQUIRE(bernstein_sign(poly({-320, 240}), 0.0) == -1);
}

TEST_CASE("the Bernstein filter refuses to decide a polynomial with a root in the slab",
          "[kinetic][filter]") {
  // 32u^2 - 94u + 61 has a root at u ~ 0.9678 (MATH.md Appendix B).
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
  // Opposite signs at the ends (a root at 1/2, or at 0.9678 in MATH.md Appendix B's certificate).
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
