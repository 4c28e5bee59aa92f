// The planar certificate formulas (docs/MATH.md §3.2 and §3.3 in dimension 2) against CGAL's exact static 2D
// predicates and constructions on random integer inputs, at several rational times, for both signs.
// The points move in a plane z = const (the z of the input is arbitrary and must not matter).
#include "certificate_polynomials.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <catch2/catch.hpp>

#include <random>

using namespace medusa::kinetic;
using K = CGAL::Exact_predicates_exact_constructions_kernel;

namespace {

MovingPoint random_planar_point(std::mt19937_64& rng, int range, std::int64_t z) {
  std::uniform_int_distribution<int> d(-range, range);
  MovingPoint m;
  for (int i = 0; i < 2; ++i) {
    m.a[i] = d(rng);
    m.b[i] = d(rng);
  }
  m.a[2] = z;
  m.b[2] = 0;
  return m;
}

K::Point_2 at(const MovingPoint& m, const mpq_class& u) {
  auto c = [&](int i) { return K::FT(mpq_class(m.a[i]) + u * mpq_class(m.b[i])); };
  return K::Point_2(c(0), c(1));
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

TEST_CASE("the planar orientation polynomial has the sign of CGAL's 2D orientation",
          "[kinetic][certificate][2d]") {
  std::uint64_t seed = GENERATE(21, 22, 23);
  CAPTURE(seed);
  std::mt19937_64 rng(seed);
  int positive = 0, negative = 0, zero = 0;
  for (int trial = 0; trial < 300; ++trial) {
    MovingPoint p[3];
    for (auto& x : p)
      x = random_planar_point(rng, 4, 17);
    Poly<mpz_class> f = certificate::orientation_2<mpz_class>(p[0], p[1], p[2]);
    REQUIRE(f.degree_bound() <= 2);
    for (const mpq_class& u : times) {
      int expected = sign_of(CGAL::orientation(at(p[0], u), at(p[1], u), at(p[2], u)));
      REQUIRE(sign_at_rational(f, u) == expected);
      positive += expected > 0;
      negative += expected < 0;
      zero += expected == 0;
    }
  }
  REQUIRE(positive > 0);
  REQUIRE(negative > 0);
  REQUIRE(zero > 0);
}

TEST_CASE("the in-circle polynomial is positive exactly when CGAL's oriented circle says so",
          "[kinetic][certificate][2d]") {
  std::uint64_t seed = GENERATE(24, 25, 26);
  CAPTURE(seed);
  std::mt19937_64 rng(seed);
  int inside = 0, outside = 0, on = 0;
  for (int trial = 0; trial < 300; ++trial) {
    MovingPoint p[4];
    for (auto& x : p)
      x = random_planar_point(rng, 5, -3);
    Poly<mpz_class> f = certificate::in_circle<mpz_class>(p[0], p[1], p[2], p[3]);
    REQUIRE(f.degree_bound() <= 4);
    for (const mpq_class& u : times) {
      K::Point_2 q[4];
      for (int i = 0; i < 4; ++i)
        q[i] = at(p[i], u);
      int o = sign_of(CGAL::orientation(q[0], q[1], q[2]));
      if (o == 0)
        continue;
      // ON_POSITIVE_SIDE of the oriented circle is the bounded side when the triangle is
      // counterclockwise; both it and InC change sign under odd permutations.
      int side = sign_of(CGAL::side_of_oriented_circle(q[0], q[1], q[2], q[3]));
      REQUIRE(sign_at_rational(f, u) == side);
      inside += side * o > 0;
      outside += side * o < 0;
      on += side == 0;
    }
  }
  REQUIRE(inside > 0);
  REQUIRE(outside > 0);
  REQUIRE(on > 0);
}

TEST_CASE("the edge and triangle radius polynomials hold for planar points", "[kinetic][certificate][2d]") {
  std::uint64_t seed = GENERATE(27, 28);
  CAPTURE(seed);
  std::mt19937_64 rng(seed);
  int shorts[2] = {0, 0}, longs[2] = {0, 0};
  for (int trial = 0; trial < 200; ++trial) {
    MovingPoint p[3];
    for (auto& x : p)
      x = random_planar_point(rng, 12, 5);
    std::uniform_int_distribution<int> rd(1, 400);
    mpz_class P = rd(rng), Q = std::uniform_int_distribution<int>(1, 3)(rng);
    K::FT rho2 = K::FT(mpq_class(P, Q));
    Poly<mpz_class> fe = certificate::edge_radius<mpz_class>(p[0], p[1], P, Q);
    Poly<mpz_class> ft = certificate::triangle_radius<mpz_class>(p[0], p[1], p[2], P, Q);
    for (const mpq_class& u : times) {
      K::Point_2 q[3];
      for (int i = 0; i < 3; ++i)
        q[i] = at(p[i], u);
      int e = sign_of(CGAL::compare(CGAL::squared_radius(q[0], q[1]), rho2));
      REQUIRE(sign_at_rational(fe, u) == e);
      (e <= 0 ? shorts[0] : longs[0])++;
      if (!CGAL::collinear(q[0], q[1], q[2])) {
        int t = sign_of(CGAL::compare(CGAL::squared_radius(q[0], q[1], q[2]), rho2));
        REQUIRE(sign_at_rational(ft, u) == t);
        (t <= 0 ? shorts[1] : longs[1])++;
      }
    }
  }
  for (int d = 0; d < 2; ++d) {
    CHECK(shorts[d] > 0);
    CHECK(longs[d] > 0);
  }
}

TEST_CASE("the edge Gabriel polynomial tests the diametral disc of planar points",
          "[kinetic][certificate][2d]") {
  std::uint64_t seed = GENERATE(29, 30);
  CAPTURE(seed);
  std::mt19937_64 rng(seed);
  int in = 0, out = 0;
  for (int trial = 0; trial < 200; ++trial) {
    MovingPoint p[3];
    for (auto& x : p)
      x = random_planar_point(rng, 8, 0);
    Poly<mpz_class> g = certificate::gabriel_edge<mpz_class>(p[0], p[1], p[2]);
    for (const mpq_class& u : times) {
      K::Point_2 q[3];
      for (int i = 0; i < 3; ++i)
        q[i] = at(p[i], u);
      // ON_BOUNDED_SIDE = strictly inside the disc with diameter q0 q1 -> G < 0.
      int s = CGAL::side_of_bounded_circle(q[0], q[1], q[2]);
      REQUIRE(sign_at_rational(g, u) == -s);
      (s > 0 ? in : out)++;
    }
  }
  REQUIRE(in > 0);
  REQUIRE(out > 0);
}
