// The enclosures from plain doubles (certificate_enclosure.h) against the exact integer coefficients
// of the same certificates, at every magnitude the grid allows, in exactly degenerate positions and
// in both rounding modes; and the filter they feed is as decisive as interval arithmetic.
#include "certificate_enclosure.h"
#include "certificate_polynomials.h"

#include <CGAL/FPU.h>
#include <CGAL/Gmpz.h>
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <gmpxx.h>
#include <random>

using namespace medusa::kinetic;

namespace {

// Positions below `position`, displacements below `velocity` in magnitude, all integers.
MovingPoint random_point(std::mt19937_64& rng, std::int64_t position, std::int64_t velocity) {
  std::uniform_int_distribution<std::int64_t> a(-position, position), b(-velocity, velocity);
  MovingPoint m;
  for (int i = 0; i < 3; ++i) {
    m.a[i] = a(rng);
    m.b[i] = b(rng);
  }
  return m;
}

// Every exact coefficient lies in its interval, compared exactly (a double is a rational).
void require_encloses(const IntervalPoly& f, const Poly<mpz_class>& exact) {
  REQUIRE(f.degree_bound() >= exact.degree_bound());
  for (int k = 0; k <= f.degree_bound(); ++k) {
    const mpq_class c = k <= exact.degree_bound() ? mpq_class(exact[k]) : mpq_class(0);
    CAPTURE(k, f[k].inf(), f[k].sup(), c.get_d());
    REQUIRE(mpq_class(f[k].inf()) <= c);
    REQUIRE(c <= mpq_class(f[k].sup()));
  }
}

struct Scale {
  const char* name;
  std::int64_t position, velocity;
};

// Small lattices, a CC3D run on the 10^-6 grid, and the largest coordinates the grid accepts.
const Scale scales[] = {{"small", 10, 10},
                        {"cc3d", 50000000, 1000000},
                        {"extreme", (std::int64_t(1) << 40) - 1, (std::int64_t(1) << 40) - 1}};

// The corners of a cube of side s at (x, y, z), moving together: every five are cospherical and
// every four coplanar or not, so the constant coefficients cancel exactly.
MovingPoint corner(int i, std::int64_t x, std::int64_t y, std::int64_t z, std::int64_t s, std::int64_t v) {
  MovingPoint m;
  m.a = {x + (i & 1) * s, y + ((i >> 1) & 1) * s, z + ((i >> 2) & 1) * s};
  m.b = {v, -v, 2 * v};
  return m;
}

} // namespace

TEST_CASE("the in-sphere and in-circle enclosures from doubles contain the exact coefficients",
          "[kinetic][certificate]") {
  const bool upward = GENERATE(false, true);
  std::uint64_t seed = GENERATE(11, 12);
  CAPTURE(upward, seed);
  std::mt19937_64 rng(seed);
  CGAL::Protect_FPU_rounding<true> guard(upward ? CGAL_FE_UPWARD : CGAL_FE_TONEAREST);
  for (const Scale& s : scales) {
    CAPTURE(s.name);
    for (int trial = 0; trial < 300; ++trial) {
      MovingPoint p[5];
      for (auto& x : p)
        x = random_point(rng, s.position / 2, s.velocity / 2);
      require_encloses(in_sphere_enclosure(p[0], p[1], p[2], p[3], p[4]),
                       certificate::in_sphere<mpz_class>(p[0], p[1], p[2], p[3], p[4]));
      require_encloses(in_circle_enclosure(p[0], p[1], p[2], p[3]),
                       certificate::in_circle<mpz_class>(p[0], p[1], p[2], p[3]));
    }
  }
}

TEST_CASE("the enclosures contain an exactly vanishing coefficient far from the origin",
          "[kinetic][certificate]") {
  const bool upward = GENERATE(false, true);
  CAPTURE(upward);
  CGAL::Protect_FPU_rounding<true> guard(upward ? CGAL_FE_UPWARD : CGAL_FE_TONEAREST);
  const std::int64_t far = (std::int64_t(1) << 39) - 12345, side = 5000000;
  MovingPoint c[8];
  for (int i = 0; i < 8; ++i)
    c[i] = corner(i, far, -far, far / 3, side, 700000);
  const Poly<mpz_class> exact = certificate::in_sphere<mpz_class>(c[0], c[1], c[2], c[4], c[7]);
  REQUIRE(exact[0] == 0); // cospherical at u = 0, by construction
  require_encloses(in_sphere_enclosure(c[0], c[1], c[2], c[4], c[7]), exact);
  const Poly<mpz_class> planar = certificate::in_circle<mpz_class>(c[0], c[1], c[2], c[3]);
  REQUIRE(planar[0] == 0);
  require_encloses(in_circle_enclosure(c[0], c[1], c[2], c[3]), planar);
}

TEST_CASE("the radius enclosures from doubles contain the exact coefficients", "[kinetic][certificate]") {
  std::uint64_t seed = GENERATE(13, 14);
  CAPTURE(seed);
  std::mt19937_64 rng(seed);
  CGAL::Protect_FPU_rounding<true> guard;
  for (const Scale& s : scales) {
    CAPTURE(s.name);
    for (int trial = 0; trial < 200; ++trial) {
      MovingPoint p[4];
      for (auto& x : p)
        x = random_point(rng, s.position / 2, s.velocity / 2);
      // rho^2 = P / Q near the squared spacing of the points, with a denominator, P and Q not exact
      // in double.
      const mpz_class Q =
          mpz_class(std::uniform_int_distribution<std::int64_t>(1, 999999937)(rng)) * 1000000007 + 1;
      const mpz_class P = Q * (s.position / 4) * (s.position / 4) + 17;
      const Interval Pi(CGAL::to_interval(CGAL::Gmpz(P.get_mpz_t()))),
          Qi(CGAL::to_interval(CGAL::Gmpz(Q.get_mpz_t())));
      require_encloses(edge_radius_enclosure(p[0], p[1], Pi, Qi),
                       certificate::edge_radius<mpz_class>(p[0], p[1], P, Q));
      require_encloses(triangle_radius_enclosure(p[0], p[1], p[2], Pi, Qi),
                       certificate::triangle_radius<mpz_class>(p[0], p[1], p[2], P, Q));
      require_encloses(tetrahedron_radius_enclosure(p[0], p[1], p[2], p[3], Pi, Qi),
                       certificate::tetrahedron_radius<mpz_class>(p[0], p[1], p[2], p[3], P, Q));
    }
  }
}

TEST_CASE("the enclosure from doubles settles a CC3D-scale certificate whenever intervals do",
          "[kinetic][certificate]") {
  std::uint64_t seed = GENERATE(15, 16);
  CAPTURE(seed);
  std::mt19937_64 rng(seed);
  CGAL::Protect_FPU_rounding<true> guard;
  int decided = 0, agreed = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    MovingPoint p[5];
    for (auto& x : p)
      x = random_point(rng, 10000000, 700000);
    const int tight =
        bernstein_sign_subdivided(certificate::in_sphere<Interval>(p[0], p[1], p[2], p[3], p[4]), 0.0, 4);
    if (tight == 0)
      continue;
    ++decided;
    agreed += bernstein_sign_subdivided(in_sphere_enclosure(p[0], p[1], p[2], p[3], p[4]), 0.0, 4) == tight;
  }
  CAPTURE(decided, agreed);
  REQUIRE(decided > 500);
  REQUIRE(agreed >= 0.99 * decided);
}

TEST_CASE("certificates of points at a time enclose their polynomials' exact values on that time interval",
          "[kinetic][certificate]") {
  const std::uint64_t seed = GENERATE(41, 42);
  CAPTURE(seed);
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> numerator(0, 1 << 20);
  auto value_at = [](const Poly<mpz_class>& f, const mpq_class& u) {
    mpq_class acc = 0;
    for (int i = f.degree_bound(); i >= 0; --i)
      acc = acc * u + mpq_class(f[i]);
    return acc;
  };
  int checked = 0, decided = 0;
  for (const Scale& scale : scales) {
    CAPTURE(scale.name);
    for (int trial = 0; trial < 100; ++trial) {
      MovingPoint p[5];
      for (auto& x : p)
        x = random_point(rng, scale.position, scale.velocity);
      // A point time (lo == hi, as at a frame) and a short interval (an isolated event time).
      const double lo = std::ldexp(numerator(rng), -20);
      const double hi = trial % 2 == 0 ? lo : lo + std::ldexp(1.0, -40);
      Interval g_edge, g_triangle, o;
      {
        CGAL::Protect_FPU_rounding<true> guard;
        const Interval u(lo, hi);
        certificate::PointAtTime q[5];
        for (int i = 0; i < 5; ++i)
          q[i] = {&p[i], u};
        g_edge = certificate::gabriel_edge<Interval>(q[0], q[1], q[2]);
        g_triangle = certificate::gabriel_triangle<Interval>(q[0], q[1], q[2], q[3]);
        o = certificate::orientation<Interval>(q[0], q[1], q[2], q[3]);
      }
      const Poly<mpz_class> exact[3] = {certificate::gabriel_edge<mpz_class>(p[0], p[1], p[2]),
                                        certificate::gabriel_triangle<mpz_class>(p[0], p[1], p[2], p[3]),
                                        certificate::orientation<mpz_class>(p[0], p[1], p[2], p[3])};
      const Interval* enclosures[3] = {&g_edge, &g_triangle, &o};
      for (int c = 0; c < 3; ++c)
        for (double u : {lo, hi}) {
          const mpq_class v = value_at(exact[c], mpq_class(u));
          CAPTURE(c, u, enclosures[c]->inf(), enclosures[c]->sup(), v.get_d());
          REQUIRE(mpq_class(enclosures[c]->inf()) <= v);
          REQUIRE(v <= mpq_class(enclosures[c]->sup()));
          ++checked;
          decided += enclosures[c]->inf() > 0 || enclosures[c]->sup() < 0;
        }
    }
  }
  REQUIRE(checked == 2 * 3 * 3 * 100);
  // Random points are in general position: nearly every sign is decided from the enclosure.
  REQUIRE(decided >= checked * 95 / 100);
}
