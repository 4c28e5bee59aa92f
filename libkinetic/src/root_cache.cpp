// The exact polynomial behind a root-cache key (docs/MATH.md §3.1, §3.8).
#include "root_cache.h"

#include "certificate_polynomials.h"
#include "fixed_integer.h"
#include "start_determinants.h"

#include <stdexcept>
#include <utility>

namespace medusa::kinetic::detail {

namespace {

// The polynomial of `key` on the points p in the number type NT; rho() gives P and Q of rho^2 = P/Q
// in NT, asked for by the radius polynomials only.
template <class NT, class Rho>
Poly<NT> coefficients_in(const KeyPolynomial& key, const std::array<MovingPoint, 5>& p, const Rho& rho) {
  const int kind = key.kind, count = key.count;
  Poly<NT> f;
  // In-circle and planar orientation have one point fewer than in-sphere and orientation.
  if (kind == 0 && count == 4)
    f = certificate::in_circle<NT>(p[0], p[1], p[2], p[3]);
  else if (kind == 0)
    f = certificate::in_sphere<NT>(p[0], p[1], p[2], p[3], p[4]);
  else if (kind == 1 && count == 3)
    f = certificate::orientation_2<NT>(p[0], p[1], p[2]);
  else if (kind == 1)
    f = certificate::orientation<NT>(p[0], p[1], p[2], p[3]);
  else if (kind == 4 && count == 4) // orientations of the triangles p0 p1 p2 and p0 p1 p3
    f = certificate::orientation_2<NT>(p[0], p[1], p[2]) * certificate::orientation_2<NT>(p[0], p[1], p[3]);
  else if (kind == 4) // orientations of the tetrahedra p0 p1 p2 p3 and p0 p1 p2 p4
    f = certificate::orientation<NT>(p[0], p[1], p[2], p[3]) *
        certificate::orientation<NT>(p[0], p[1], p[2], p[4]);
  else if (kind == 3 && count == 3) // fold test at a planar hull vertex p0 with hull neighbours p1, p2
    f = certificate::dot<NT>(certificate::difference<NT>(p[0], p[1]),
                             certificate::difference<NT>(p[0], p[2]));
  else if (kind == 3) { // fold test at the hull ridge p0 p1 with apices p2, p3
    const auto ab = certificate::difference<NT>(p[0], p[1]);
    f = certificate::dot<NT>(certificate::cross<NT>(ab, certificate::difference<NT>(p[0], p[2])),
                             certificate::cross<NT>(ab, certificate::difference<NT>(p[0], p[3])));
  } else {
    const auto [P, Q] = rho();
    if (count == 2)
      f = certificate::edge_radius<NT>(p[0], p[1], P, Q);
    else if (count == 3)
      f = certificate::triangle_radius<NT>(p[0], p[1], p[2], P, Q);
    else
      f = certificate::tetrahedron_radius<NT>(p[0], p[1], p[2], p[3], P, Q);
  }
  return f;
}

} // namespace

Poly<mpz_class> KeyPolynomial::coefficients(const std::array<MovingPoint, 5>& p) const {
  // In 512-bit integers first (fixed_integer.h), in GMP if a value needs more.
  try {
    const Poly<FixedInt> f = coefficients_in<FixedInt>(
        *this, p, [&] { return std::make_pair(to_fixed(motion->rho2->num), to_fixed(motion->rho2->den)); });
    Poly<mpz_class> g = Poly<mpz_class>::zero_of_degree(f.degree_bound());
    for (int i = 0; i <= f.degree_bound(); ++i)
      g[i] = to_mpz(f[i]);
    return g;
  } catch (const std::overflow_error&) {
    return coefficients_in<mpz_class>(*this, p,
                                      [&] { return std::make_pair(motion->rho2->num, motion->rho2->den); });
  }
}

std::array<MovingPoint, 5> KeyPolynomial::points() const {
  std::array<MovingPoint, 5> p{};
  for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i)
    p[i] = pt(i);
  return p;
}

bool KeyPolynomial::vanishes_at_start() const {
  const std::array<MovingPoint, 5> pts = points();
  const MovingPoint* p[5] = {&pts[0], &pts[1], &pts[2], &pts[3], &pts[4]};
  const auto n = static_cast<std::size_t>(count);
  if (kind == 0)
    return in_sphere_vanishes_at_start(p, n);
  if (kind == 1)
    return orientation_vanishes_at_start(p, n);
  if (kind == 4) { // the orientations of the facet (n - 2 points) with each of its two apices
    const MovingPoint* second[4] = {p[0], p[1], p[2], p[3]};
    second[n - 2] = p[n - 1];
    return orientation_vanishes_at_start(p, n - 1) || orientation_vanishes_at_start(second, n - 1);
  }
  // Radius and fold polynomials are products and sums of several determinants: the exact integers.
  std::array<MovingPoint, 5> frozen = pts;
  for (MovingPoint& p : frozen)
    p.b = {0, 0, 0};
  const Poly<mpz_class> f = coefficients(frozen);
  return f.degree_bound() < 0 || f[0] == 0;
}

bool KeyPolynomial::translate_of(const KeyPolynomial& other) const {
  if (kind != other.kind || count != other.count || count == 0 ||
      (kind == 2 && motion->rho2 != other.motion->rho2))
    return false;
  const std::array<MovingPoint, 5> pts = points(), other_pts = other.points();
  const auto n = static_cast<std::size_t>(count);
  const auto moved_to = [](const MovingPoint& p, const std::array<std::int64_t, 3>& t, const MovingPoint& q) {
    return p.b == q.b && p.a[0] + t[0] == q.a[0] && p.a[1] + t[1] == q.a[1] && p.a[2] + t[2] == q.a[2];
  };
  const bool any_order = kind == 0 || kind == 1 || kind == 2;
  for (std::size_t j = 0; j < (any_order ? n : 1); ++j) {
    const std::array<std::int64_t, 3> t{other_pts[j].a[0] - pts[0].a[0], other_pts[j].a[1] - pts[0].a[1],
                                        other_pts[j].a[2] - pts[0].a[2]};
    bool all = true;
    for (std::size_t i = 0; i < n && all; ++i) {
      if (!any_order) {
        all = moved_to(pts[i], t, other_pts[i]);
        continue;
      }
      bool found = false;
      for (std::size_t k = 0; k < n && !found; ++k)
        found = moved_to(pts[i], t, other_pts[k]);
      all = found;
    }
    if (all)
      return true;
  }
  return false;
}

ExactPoly KeyPolynomial::operator()() const {
  const Poly<mpz_class> f = coefficients(points());
  // Divide out u^m: the same roots in (0, 1], and no root at 0, where an isolating interval
  // starting at a frame may begin (CGAL's algebraic reals need a polynomial non-zero at the ends).
  int m = 0;
  while (m < f.degree_bound() && f[m] == 0)
    ++m;
  const Poly<mpz_class> g = f.shifted_down(m);
  return to_exact_poly(g);
}

} // namespace medusa::kinetic::detail
