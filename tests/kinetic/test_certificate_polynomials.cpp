// Each certificate formula of docs/MATH.md §3.1 against CGAL's exact static predicates and constructions
// on random integer inputs, at several rational times, for both signs.
#include "algebraic_time.h"
#include "certificate_polynomials.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <catch2/catch.hpp>

#include <random>

using namespace medusa::kinetic;
using K = CGAL::Exact_predicates_exact_constructions_kernel;

namespace {

MovingPoint random_point(std::mt19937_64& rng, int range) {
  std::uniform_int_distribution<int> d(-range, range);
  MovingPoint m;
  for (int i = 0; i < 3; ++i) {
    m.a[i] = d(rng);
    m.b[i] = d(rng);
  }
  return m;
}

K::Point_3 at(const MovingPoint& m, const mpq_class& u) {
  auto c = [&](int i) { return K::FT(mpq_class(m.a[i]) + u * mpq_class(m.b[i])); };
  return K::Point_3(c(0), c(1), c(2));
}

int sign_at_rational(const Poly<mpz_class>& f, const mpq_class& u) {
  mpq_class acc = 0;
  for (int i = f.degree_bound(); i >= 0; --i)
    acc = acc * u + mpq_class(f[i]);
  return sgn(acc);
}

int sign_of(CGAL::Sign s) { return s == CGAL::POSITIVE ? 1 : (s == CGAL::NEGATIVE ? -1 : 0); }

const mpq_class times[] = {mpq_class(0), mpq_class(1, 3), mpq_class(5, 7), mpq_class(1)};

} // namespace

TEST_CASE("the orientation polynomial has the sign of CGAL::orientation", "[kinetic][certificate]") {
  std::uint64_t seed = GENERATE(1, 2, 3);
  CAPTURE(seed);
  std::mt19937_64 rng(seed);
  int positive = 0, negative = 0;
  for (int trial = 0; trial < 200; ++trial) {
    MovingPoint p[4];
    for (auto& x : p)
      x = random_point(rng, 20);
    Poly<mpz_class> f = certificate::orientation<mpz_class>(p[0], p[1], p[2], p[3]);
    for (const mpq_class& u : times) {
      int expected = sign_of(CGAL::orientation(at(p[0], u), at(p[1], u), at(p[2], u), at(p[3], u)));
      REQUIRE(sign_at_rational(f, u) == expected);
      positive += expected > 0;
      negative += expected < 0;
    }
  }
  REQUIRE(positive > 0);
  REQUIRE(negative > 0);
}

TEST_CASE("the in-sphere polynomial is negative exactly when the point is inside", "[kinetic][certificate]") {
  std::uint64_t seed = GENERATE(4, 5, 6);
  CAPTURE(seed);
  std::mt19937_64 rng(seed);
  int inside = 0, outside = 0;
  for (int trial = 0; trial < 200; ++trial) {
    MovingPoint p[5];
    for (auto& x : p)
      x = random_point(rng, 10);
    Poly<mpz_class> f = certificate::in_sphere<mpz_class>(p[0], p[1], p[2], p[3], p[4]);
    for (const mpq_class& u : times) {
      K::Point_3 q[5];
      for (int i = 0; i < 5; ++i)
        q[i] = at(p[i], u);
      int o = sign_of(CGAL::orientation(q[0], q[1], q[2], q[3]));
      if (o == 0)
        continue;
      // CGAL's oriented sphere: ON_POSITIVE_SIDE is the bounded side when O > 0; both it and InS
      // change sign under odd permutations, so InS = -side in every order.
      int side = sign_of(CGAL::side_of_oriented_sphere(q[0], q[1], q[2], q[3], q[4]));
      REQUIRE(sign_at_rational(f, u) == -side);
      inside += side * o > 0;
      outside += side * o < 0;
    }
  }
  REQUIRE(inside > 0);
  REQUIRE(outside > 0);
}

TEST_CASE("the radius polynomials compare the smallest circumradius with rho", "[kinetic][certificate]") {
  std::uint64_t seed = GENERATE(7, 8);
  CAPTURE(seed);
  std::mt19937_64 rng(seed);
  int shorts[3] = {0, 0, 0}, longs[3] = {0, 0, 0};
  for (int trial = 0; trial < 150; ++trial) {
    MovingPoint p[4];
    for (auto& x : p)
      x = random_point(rng, 12);
    std::uniform_int_distribution<int> rd(1, 400);
    mpz_class P = rd(rng), Q = std::uniform_int_distribution<int>(1, 3)(rng);
    K::FT rho2 = K::FT(mpq_class(P, Q));
    Poly<mpz_class> fe = certificate::edge_radius<mpz_class>(p[0], p[1], P, Q);
    Poly<mpz_class> ft = certificate::triangle_radius<mpz_class>(p[0], p[1], p[2], P, Q);
    Poly<mpz_class> fT = certificate::tetrahedron_radius<mpz_class>(p[0], p[1], p[2], p[3], P, Q);
    for (const mpq_class& u : times) {
      K::Point_3 q[4];
      for (int i = 0; i < 4; ++i)
        q[i] = at(p[i], u);
      int e = sign_of(CGAL::compare(CGAL::squared_radius(q[0], q[1]), rho2));
      REQUIRE(sign_at_rational(fe, u) == e);
      (e <= 0 ? shorts[0] : longs[0])++;
      if (!CGAL::collinear(q[0], q[1], q[2])) {
        int t = sign_of(CGAL::compare(CGAL::squared_radius(q[0], q[1], q[2]), rho2));
        REQUIRE(sign_at_rational(ft, u) == t);
        (t <= 0 ? shorts[1] : longs[1])++;
      }
      if (!CGAL::coplanar(q[0], q[1], q[2], q[3])) {
        int T = sign_of(CGAL::compare(CGAL::squared_radius(q[0], q[1], q[2], q[3]), rho2));
        REQUIRE(sign_at_rational(fT, u) == T);
        (T <= 0 ? shorts[2] : longs[2])++;
      }
    }
  }
  for (int d = 0; d < 3; ++d) {
    CHECK(shorts[d] > 0);
    CHECK(longs[d] > 0);
  }
}

TEST_CASE("the Gabriel polynomials test the smallest circumball", "[kinetic][certificate]") {
  std::uint64_t seed = GENERATE(9, 10);
  CAPTURE(seed);
  std::mt19937_64 rng(seed);
  int in = 0, out = 0;
  for (int trial = 0; trial < 200; ++trial) {
    MovingPoint p[4];
    for (auto& x : p)
      x = random_point(rng, 8);
    Poly<mpz_class> g1 = certificate::gabriel_edge<mpz_class>(p[0], p[1], p[3]);
    Poly<mpz_class> g2 = certificate::gabriel_triangle<mpz_class>(p[0], p[1], p[2], p[3]);
    for (const mpq_class& u : times) {
      K::Point_3 q[4];
      for (int i = 0; i < 4; ++i)
        q[i] = at(p[i], u);
      // side_of_bounded_sphere: ON_BOUNDED_SIDE = strictly inside -> G < 0.
      int s1 = CGAL::side_of_bounded_sphere(q[0], q[1], q[3]);
      REQUIRE(sign_at_rational(g1, u) == -s1);
      if (!CGAL::collinear(q[0], q[1], q[2])) {
        int s2 = CGAL::side_of_bounded_sphere(q[0], q[1], q[2], q[3]);
        REQUIRE(sign_at_rational(g2, u) == -s2);
        (s2 > 0 ? in : out)++;
      }
    }
  }
  REQUIRE(in > 0);
  REQUIRE(out > 0);
}

TEST_CASE("sign just after a root follows the first non-vanishing derivative", "[kinetic][algebraic]") {
  // f = (u - 1/2)^2 (u - 3/4): zero at 1/2 without sign change, sign change at 3/4.
  Poly<mpz_class> f;
  {
    Poly<mpz_class> a(mpz_class(-1), mpz_class(2)), b(mpz_class(-3), mpz_class(4));
    f = a * a * b;
  }
  ExactPoly e = to_exact_poly(f);
  REQUIRE(sign_plus(e, SlabTime(Rational(1, 2))) == -1);
  REQUIRE(sign_at(e, SlabTime(Rational(1, 2))) == 0);
  REQUIRE(sign_plus(e, SlabTime(Rational(3, 4))) == 1);
  std::vector<AlgebraicReal> roots = sign_changes_after(e, SlabTime());
  REQUIRE(roots.size() == 1);
  REQUIRE(roots[0] == AlgebraicReal(Rational(3, 4)));
}
