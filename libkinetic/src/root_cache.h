// The per-slab root cache (docs/MATH.md §3.8, caching): certificates built on the same points share their
// polynomial up to sign, hence its roots. A key names the polynomial; KeyPolynomial rebuilds it.
#pragma once

#include "algebraic_time.h"
#include "medusa/kinetic/kinetic_alpha_complex.h"
#include "medusa/kinetic/simplex.h"
#include "moving_point.h"

#include <array>
#include <cstddef>
#include <memory>
#include <unordered_map>
#include <vector>

namespace medusa::kinetic::detail {

// The kind of polynomial (0 in-sphere or in-circle, 1 orientation, 2 radius, 3 fold test of a hull
// ridge: the ridge's points, then its apices; 4 orientations of a facet's two top simplices: the
// facet's points, then its apices), then its points, -2
// padded (the number of points tells the 2D polynomials from the 3D ones).
struct CacheKey {
  std::array<VertexId, 6> v;
  bool operator==(const CacheKey& o) const { return v == o.v; }
};
struct CacheKeyHash {
  std::size_t operator()(const CacheKey& k) const {
    std::size_t h = 0;
    for (VertexId x : k.v)
      h = h * 0x9E3779B97F4A7C15ULL + static_cast<std::size_t>(x + 3);
    return h;
  }
};

using RootCache = std::unordered_map<CacheKey, RealRoots, CacheKeyHash>;

// The exact polynomial behind a root-cache key, up to sign (docs/MATH.md §3.1): the in-sphere determinant
// of five points (in-circle of four in 2D), the orientation of four (three in 2D), or the radius
// polynomial of a simplex, or the fold test of a hull ridge (Engine::fold_poly). It copies the points'
// motion, so it stays valid after the triangulation has moved on within the slab.
// The cells' motion in one slab (indexed by vertex id) and rho^2: what key polynomials are computed
// from. Immutable once its slab has started, and shared by the roots isolated in it, so that a
// root's exact polynomial can be computed on demand, even after the engine has moved on
// (Engine::set_slab_motion writes the next slab's motion into a copy while such roots remain).
struct SlabMotion {
  std::vector<MovingPoint> points;
  std::shared_ptr<const SquaredRadius> rho2;
};

// A certificate polynomial named by its kind and points: every root isolated in doubles holds one
// (about five per cell at a slab start), so it names its points by id in the slab's motion rather
// than copying them.
struct KeyPolynomial {
  int kind = 0; // 0 in-sphere, 1 orientation, 2 radius, 3 fold test, 4 orientations (as CacheKey::v[0])
  int count = 0;
  std::array<VertexId, 5> ids{};
  std::shared_ptr<const SlabMotion> motion;

  const MovingPoint& pt(std::size_t i) const { return motion->points[static_cast<std::size_t>(ids[i])]; }
  std::array<MovingPoint, 5> points() const; // pt(0), ..., pt(count - 1), then zeros

  ExactPoly operator()() const;

  // Whether other is this polynomial on the same points translated by one integer vector, in any
  // order where the polynomial is alternating or symmetric in its points (in-sphere, orientation,
  // radius) and in the same order otherwise: then the two are equal up to sign (translation
  // invariance), with the same roots (docs/MATH.md §3.7; the copies of a periodic run, §8.6).
  bool translate_of(const KeyPolynomial& other) const;

  // Whether the polynomial vanishes at u = 0, exactly: its value there is the static determinant of
  // the points frozen at the slab start, far cheaper than the whole polynomial in exact integers.
  bool vanishes_at_start() const;

private:
  Poly<mpz_class> coefficients(const std::array<MovingPoint, 5>& p) const;
};

} // namespace medusa::kinetic::detail
