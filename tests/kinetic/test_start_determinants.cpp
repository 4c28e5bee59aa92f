// The exact zero tests at a slab start (libkinetic/src/start_determinants.h, KeyPolynomial::
// vanishes_at_start) and the static Delaunay check that uses them (static_delaunay.h: keeps_sign at
// u = 0), against the oracle: the certificate polynomial in exact integers (certificate_polynomials.h)
// and its real roots. Random points of a small box make cospherical, coplanar and collinear sets
// frequent; the corners of a lattice cube are CC3D's initial layout.
#include "algebraic_time.h"
#include "certificate_polynomials.h"
#include "root_cache.h"
#include "start_determinants.h"
#include "static_delaunay.h"

#include <CGAL/FPU.h>
#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <iostream>
#include <memory>
#include <random>
#include <vector>

using medusa::kinetic::MovingPoint;
using medusa::kinetic::Poly;
namespace certificate = medusa::kinetic::certificate;
namespace detail = medusa::kinetic::detail;

namespace {

// Positions in a box of side 3 (many degenerate sets), scaled and moved near the 2^40 coordinate
// limit when `far`; velocities in [-v, v], which the start ignores.
std::array<MovingPoint, 5> random_points(std::mt19937_64& rng, bool far, std::int64_t v) {
  std::uniform_int_distribution<std::int64_t> small(0, 2), velocity(-v, v);
  const std::int64_t offset = far ? (std::int64_t(1) << 39) : 0;
  std::array<MovingPoint, 5> p;
  for (MovingPoint& m : p)
    for (std::size_t a = 0; a < 3; ++a) {
      m.a[a] = offset + small(rng) * (far ? 1000003 : 1);
      m.b[a] = velocity(rng);
    }
  return p;
}

// Whether the first n points are pairwise distinct at the start, in the first `axes` coordinates.
bool distinct(const std::array<MovingPoint, 5>& p, std::size_t n, std::size_t axes) {
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      bool same = true;
      for (std::size_t a = 0; a < axes; ++a)
        same = same && p[i].a[a] == p[j].a[a];
      if (same)
        return false;
    }
  return true;
}

bool zero_at_start(const Poly<mpz_class>& f) { return f.degree_bound() < 0 || f[0] == 0; }

} // namespace

TEST_CASE("the zero tests at a slab start agree with the exact polynomials' constant coefficients") {
  const std::uint64_t seed = 20261127;
  std::cout << "start determinants: seed " << seed << "\n";
  std::mt19937_64 rng(seed);
  // Degenerate sets of distinct points (a repeated point makes every determinant zero).
  int cospherical = 0, cocircular = 0, coplanar = 0, collinear = 0, general_sphere = 0, general_circle = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const auto p = random_points(rng, trial % 2 == 1, 50);
    const MovingPoint* q[5] = {&p[0], &p[1], &p[2], &p[3], &p[4]};
    const bool s3 = zero_at_start(certificate::in_sphere<mpz_class>(p[0], p[1], p[2], p[3], p[4]));
    const bool s2 = zero_at_start(certificate::in_circle<mpz_class>(p[0], p[1], p[2], p[3]));
    const bool o3 = zero_at_start(certificate::orientation<mpz_class>(p[0], p[1], p[2], p[3]));
    const bool o2 = zero_at_start(certificate::orientation_2<mpz_class>(p[0], p[1], p[2]));
    const bool o3b = zero_at_start(certificate::orientation<mpz_class>(p[0], p[1], p[2], p[4]));
    const bool o2b = zero_at_start(certificate::orientation_2<mpz_class>(p[0], p[1], p[3]));
    // The engine calls them with rounding upwards (interval arithmetic in progress).
    CGAL::Protect_FPU_rounding<true> upwards;
    CHECK(detail::in_sphere_vanishes_at_start(q, 5) == s3);
    CHECK(detail::in_sphere_vanishes_at_start(q, 4) == s2);
    CHECK(detail::orientation_vanishes_at_start(q, 4) == o3);
    CHECK(detail::orientation_vanishes_at_start(q, 3) == o2);
    // The same through the root cache's keys: kind 0 in-sphere / in-circle, 1 orientation, 4 the
    // orientations of a facet with each of its two apices.
    detail::KeyPolynomial key;
    auto motion = std::make_shared<detail::SlabMotion>();
    motion->points.assign(p.begin(), p.end());
    key.motion = motion;
    key.ids = {0, 1, 2, 3, 4};
    for (const std::size_t count : {std::size_t(5), std::size_t(4)}) {
      const bool spatial = count == 5;
      key.count = static_cast<int>(count);
      key.kind = 0;
      CHECK(key.vanishes_at_start() == (spatial ? s3 : s2));
      key.kind = 4;
      CHECK(key.vanishes_at_start() == (spatial ? (o3 || o3b) : (o2 || o2b)));
      key.kind = 1;
      key.count = static_cast<int>(count - 1);
      CHECK(key.vanishes_at_start() == (spatial ? o3 : o2));
    }
    if (distinct(p, 5, 3))
      ++(s3 ? cospherical : general_sphere);
    if (distinct(p, 4, 2))
      ++(s2 ? cocircular : general_circle);
    coplanar += distinct(p, 4, 3) && o3;
    collinear += distinct(p, 3, 2) && o2;
  }
  std::cout << "  distinct points: " << cospherical << " cospherical, " << cocircular << " cocircular, "
            << coplanar << " coplanar, " << collinear << " collinear\n";
  // Both answers occur on sets of distinct points often enough for the comparison to mean something.
  CHECK(cospherical > 50);
  CHECK(general_sphere > 50);
  CHECK(cocircular > 50);
  CHECK(general_circle > 50);
  CHECK(coplanar > 50);
  CHECK(collinear > 50);
}

TEST_CASE("the eight corners of a lattice cube are cospherical at the slab start and not after it") {
  // CC3D's BlobInitializer layout (docs/MATH.md §5.5): cells on a cubic lattice of spacing 5.
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

TEST_CASE(
    "an in-sphere or orientation certificate keeps its sign just after a slab start exactly when it has "
    "no root in (0, delta]") {
  // keeps_sign at u = 0 decides most lattice-degenerate certificates of an initial triangulation on
  // f / u (f(0) = 0 told by the static determinant); the oracle is f's exact real roots.
  const std::uint64_t seed = 2026112701;
  std::cout << "keeps sign at a slab start: seed " << seed << "\n";
  std::mt19937_64 rng(seed);
  const medusa::kinetic::Rational zero(0);
  int vanishing_kept = 0, vanishing_broken = 0, double_root = 0, cases = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const auto p = random_points(rng, false, trial % 3 == 0 ? 1 : 6);
    const bool spatial = trial % 2 == 0;
    const std::size_t n = spatial ? 4 : 3;
    if (!distinct(p, n + 1, spatial ? 3 : 2))
      continue;
    const medusa::kinetic::Rational delta(1, 1 << (1 + trial % 6));
    std::vector<const MovingPoint*> base;
    for (std::size_t i = 0; i < n; ++i)
      base.push_back(&p[i]);
    const Poly<mpz_class> sphere = spatial ? certificate::in_sphere<mpz_class>(p[0], p[1], p[2], p[3], p[4])
                                           : certificate::in_circle<mpz_class>(p[0], p[1], p[2], p[3]);
    const Poly<mpz_class> orient = spatial ? certificate::orientation<mpz_class>(p[0], p[1], p[2], p[3])
                                           : certificate::orientation_2<mpz_class>(p[0], p[1], p[2]);
    auto oracle = [&](const Poly<mpz_class>& f) {
      bool zero_poly = true;
      for (int i = 0; i <= f.degree_bound(); ++i)
        zero_poly = zero_poly && f[i] == 0;
      if (zero_poly)
        return true;
      const medusa::kinetic::AlgebraicReal lo(zero), hi(delta);
      for (const auto& root : medusa::kinetic::real_roots(medusa::kinetic::to_exact_poly(f)).roots)
        if (lo < root.first && !(hi < root.first))
          return false;
      return true;
    };
    const bool sphere_kept = detail::in_sphere_keeps_sign(base, spatial ? p[4] : p[3], zero, delta);
    CHECK(sphere_kept == oracle(sphere));
    CHECK(detail::orientation_keeps_sign(base, zero, delta) == oracle(orient));
    if (zero_at_start(sphere)) {
      ++(sphere_kept ? vanishing_kept : vanishing_broken);
      bool moves = false;
      for (int i = 2; i <= sphere.degree_bound(); ++i)
        moves = moves || sphere[i] != 0;
      double_root += moves && sphere[1] == 0;
    }
    ++cases;
  }
  std::cout << "  " << cases << " cases; in-sphere vanishing at the start: " << vanishing_kept
            << " keep their sign, " << vanishing_broken << " change it in (0, delta], " << double_root
            << " with a double root at 0 (not identically zero)\n";
  CHECK(cases > 1000);
  CHECK(vanishing_kept > 50);
  CHECK(vanishing_broken > 10);
  CHECK(double_root >= 5);
}
