// The exact zero tests at a slab start (libkinetic/src/start_determinants.h, KeyPolynomial::
// vanishes_at_start) against the oracle: the constant coefficient of the certificate polynomial in
// exact integers (certificate_polynomials.h), on random points of a small box, where coplanar,
// collinear and cospherical sets are frequent, and on the corners of a lattice cube.
#include "medusa/kinetic/certificate_polynomials.h"
#include "root_cache.h"
#include "start_determinants.h"

#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <iostream>
#include <random>

using medusa::kinetic::MovingPoint;
using medusa::kinetic::Poly;
namespace certificate = medusa::kinetic::certificate;
namespace detail = medusa::kinetic::detail;

namespace {

// Positions in a box of side 3 (many degenerate sets); velocities anywhere, since only the start
// counts. Coordinates near the 2^40 limit keep every difference exact in doubles.
std::array<MovingPoint, 5> random_points(std::mt19937_64& rng, bool far) {
  std::uniform_int_distribution<std::int64_t> small(0, 2), velocity(-50, 50);
  const std::int64_t offset = far ? (std::int64_t(1) << 39) : 0;
  std::array<MovingPoint, 5> p;
  for (MovingPoint& m : p)
    for (int a = 0; a < 3; ++a) {
      m.a[static_cast<std::size_t>(a)] = offset + small(rng) * (far ? 1000003 : 1);
      m.b[static_cast<std::size_t>(a)] = velocity(rng);
    }
  return p;
}

bool zero_at_start(const Poly<mpz_class>& f) { return f.degree_bound() < 0 || f[0] == 0; }

} // namespace

TEST_CASE("the zero tests at a slab start agree with the exact polynomials' constant coefficients") {
  const std::uint64_t seed = 20261127;
  std::cout << "start determinants: seed " << seed << "\n";
  std::mt19937_64 rng(seed);
  int zero_sphere = 0, zero_orientation = 0, nonzero_sphere = 0, cases = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const auto p = random_points(rng, trial % 2 == 1);
    const MovingPoint* q[5] = {&p[0], &p[1], &p[2], &p[3], &p[4]};
    const bool s3 = zero_at_start(certificate::in_sphere<mpz_class>(p[0], p[1], p[2], p[3], p[4]));
    const bool s2 = zero_at_start(certificate::in_circle<mpz_class>(p[0], p[1], p[2], p[3]));
    const bool o3 = zero_at_start(certificate::orientation<mpz_class>(p[0], p[1], p[2], p[3]));
    const bool o2 = zero_at_start(certificate::orientation_2<mpz_class>(p[0], p[1], p[2]));
    CHECK(detail::in_sphere_vanishes_at_start(q, 5) == s3);
    CHECK(detail::in_sphere_vanishes_at_start(q, 4) == s2);
    CHECK(detail::orientation_vanishes_at_start(q, 4) == o3);
    CHECK(detail::orientation_vanishes_at_start(q, 3) == o2);
    // The root-cache key's polynomial of the two orientations of a facet with its apices (kind 4).
    detail::KeyPolynomial key;
    key.kind = 4;
    key.count = 5;
    key.pts = p;
    CHECK(key.vanishes_at_start() ==
          (o3 || zero_at_start(certificate::orientation<mpz_class>(p[0], p[1], p[2], p[4]))));
    key.count = 4;
    CHECK(key.vanishes_at_start() ==
          (o2 || zero_at_start(certificate::orientation_2<mpz_class>(p[0], p[1], p[3]))));
    zero_sphere += s3;
    nonzero_sphere += !s3;
    zero_orientation += o3;
    ++cases;
  }
  // Both answers occur often enough for the comparison to mean something.
  CHECK(cases == 4000);
  CHECK(zero_sphere > 100);
  CHECK(nonzero_sphere > 100);
  CHECK(zero_orientation > 100);
}

TEST_CASE("the eight corners of a lattice cube are cospherical at the slab start and not after it") {
  // CC3D's BlobInitializer layout (MATH.md 5.5): cells on a cubic lattice of spacing 5.
  std::array<MovingPoint, 8> corner;
  for (int i = 0; i < 8; ++i) {
    corner[static_cast<std::size_t>(i)].a = {5 * (i & 1), 5 * ((i >> 1) & 1), 5 * ((i >> 2) & 1)};
    corner[static_cast<std::size_t>(i)].b = {i, 2 * i - 7, 3 - i};
  }
  const MovingPoint* sphere[5] = {&corner[0], &corner[1], &corner[2], &corner[4], &corner[7]};
  const MovingPoint* face[4] = {&corner[0], &corner[1], &corner[2], &corner[3]};
  const MovingPoint* solid[4] = {&corner[0], &corner[1], &corner[2], &corner[4]};
  CHECK(detail::in_sphere_vanishes_at_start(sphere, 5));
  CHECK(detail::orientation_vanishes_at_start(face, 4));
  CHECK_FALSE(detail::orientation_vanishes_at_start(solid, 4));
  // Their polynomials vanish at 0 but not identically: the motion breaks the degeneracy at once.
  const Poly<mpz_class> f =
      certificate::in_sphere<mpz_class>(corner[0], corner[1], corner[2], corner[4], corner[7]);
  CHECK(f[0] == 0);
  bool moves = false;
  for (int i = 1; i <= f.degree_bound(); ++i)
    moves = moves || f[i] != 0;
  CHECK(moves);
}
