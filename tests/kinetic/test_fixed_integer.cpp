// The exact certificate polynomials in 512-bit integers (libkinetic/src/fixed_integer.h, used by
// KeyPolynomial) against the same formulas in GMP: equal for every kind of certificate, on points
// near the 2^40 coordinate limit, and equal again where a value passes 512 bits and GMP takes over.
#include "algebraic_time.h"
#include "certificate_polynomials.h"
#include "fixed_integer.h"
#include "root_cache.h"

#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <random>
#include <stdexcept>

using medusa::kinetic::FixedInt;
using medusa::kinetic::MovingPoint;
using medusa::kinetic::Poly;
namespace certificate = medusa::kinetic::certificate;
namespace detail = medusa::kinetic::detail;

TEST_CASE("integers of up to 512 bits go to the fixed width and back unchanged, and larger ones are refused",
          "[kinetic][fixed]") {
  const unsigned seed = std::random_device{}();
  CAPTURE(seed);
  gmp_randclass random(gmp_randinit_default);
  random.seed(seed);
  int round_trips = 0;
  for (unsigned bits = 0; bits <= 512; ++bits)
    for (int sign : {1, -1}) {
      const mpz_class x =
          sign *
          (bits == 0 ? mpz_class(0) : mpz_class(random.get_z_bits(bits) | (mpz_class(1) << (bits - 1))));
      CAPTURE(bits, x.get_str(16));
      CHECK(medusa::kinetic::to_mpz(medusa::kinetic::to_fixed(x)) == x);
      ++round_trips;
    }
  REQUIRE(round_trips == 1026);
  CHECK_THROWS_AS(medusa::kinetic::to_fixed(mpz_class(1) << 512), std::overflow_error);
  CHECK_THROWS_AS(medusa::kinetic::to_fixed(-(mpz_class(1) << 600)), std::overflow_error);
}

namespace {

// The key's polynomial in GMP by the certificate formulas, with its root at 0 divided out as
// KeyPolynomial does.
medusa::kinetic::ExactPoly oracle(const detail::KeyPolynomial& key, const std::array<MovingPoint, 5>& p) {
  const mpz_class& P = key.motion->rho2->num;
  const mpz_class& Q = key.motion->rho2->den;
  Poly<mpz_class> f;
  switch (key.kind * 10 + key.count) {
  case 4: f = certificate::in_circle<mpz_class>(p[0], p[1], p[2], p[3]); break;
  case 5: f = certificate::in_sphere<mpz_class>(p[0], p[1], p[2], p[3], p[4]); break;
  case 13: f = certificate::orientation_2<mpz_class>(p[0], p[1], p[2]); break;
  case 14: f = certificate::orientation<mpz_class>(p[0], p[1], p[2], p[3]); break;
  case 22: f = certificate::edge_radius<mpz_class>(p[0], p[1], P, Q); break;
  case 23: f = certificate::triangle_radius<mpz_class>(p[0], p[1], p[2], P, Q); break;
  case 24: f = certificate::tetrahedron_radius<mpz_class>(p[0], p[1], p[2], p[3], P, Q); break;
  case 33:
    f = certificate::dot<mpz_class>(certificate::difference<mpz_class>(p[0], p[1]),
                                    certificate::difference<mpz_class>(p[0], p[2]));
    break;
  case 34: {
    const auto ab = certificate::difference<mpz_class>(p[0], p[1]);
    f = certificate::dot<mpz_class>(
        certificate::cross<mpz_class>(ab, certificate::difference<mpz_class>(p[0], p[2])),
        certificate::cross<mpz_class>(ab, certificate::difference<mpz_class>(p[0], p[3])));
    break;
  }
  case 44:
    f = certificate::orientation_2<mpz_class>(p[0], p[1], p[2]) *
        certificate::orientation_2<mpz_class>(p[0], p[1], p[3]);
    break;
  case 45:
    f = certificate::orientation<mpz_class>(p[0], p[1], p[2], p[3]) *
        certificate::orientation<mpz_class>(p[0], p[1], p[2], p[4]);
    break;
  default: FAIL("no such key");
  }
  int m = 0;
  while (m < f.degree_bound() && f[m] == 0)
    ++m;
  return medusa::kinetic::to_exact_poly(f.shifted_down(m));
}

} // namespace

TEST_CASE("the exact polynomial of every kind of certificate is GMP's, in the fixed width and beyond it",
          "[kinetic][fixed]") {
  const unsigned seed = std::random_device{}();
  CAPTURE(seed);
  std::mt19937_64 rng(seed);
  // Cells spread over 2^39 grid units and moving up to 2^33 in a slab: past CC3D's lattices, inside
  // the accepted coordinates (docs/MATH.md §1.5). rho^2 as CC3D's radii give it, then past 512 bits
  // (radius polynomials overflow in the products, then in rho^2 itself: GMP computes them).
  std::uniform_int_distribution<std::int64_t> position(0, std::int64_t(1) << 39),
      step(-(std::int64_t(1) << 33), std::int64_t(1) << 33);
  const std::array<medusa::kinetic::SquaredRadius, 3> radii{
      {{mpz_class(9622000000000), 1}, {(mpz_class(1) << 450) + 1, 3}, {mpz_class(1) << 600, 7}}};
  const std::array<std::pair<int, int>, 11> keys{
      {{0, 4}, {0, 5}, {1, 3}, {1, 4}, {2, 2}, {2, 3}, {2, 4}, {3, 3}, {3, 4}, {4, 4}, {4, 5}}};
  int compared = 0;
  for (int trial = 0; trial < 20; ++trial) {
    std::array<MovingPoint, 5> p;
    for (MovingPoint& m : p)
      for (std::size_t a = 0; a < 3; ++a) {
        m.a[a] = position(rng);
        m.b[a] = trial % 4 == 0 ? 0 : step(rng); // some at rest: constant coordinates
      }
    for (const auto& rho2 : radii) {
      auto motion = std::make_shared<detail::SlabMotion>();
      motion->points.assign(p.begin(), p.end());
      motion->rho2 = std::make_shared<const medusa::kinetic::SquaredRadius>(rho2);
      for (const auto& [kind, count] : keys) {
        detail::KeyPolynomial key;
        key.kind = kind;
        key.count = count;
        key.ids = {0, 1, 2, 3, 4};
        key.motion = motion;
        CAPTURE(trial, kind, count, rho2.num.get_str(16));
        CHECK(key() == oracle(key, p));
        ++compared;
      }
    }
  }
  REQUIRE(compared == 20 * 3 * 11);
}
