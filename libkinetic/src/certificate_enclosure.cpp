// Certified enclosures of the certificate polynomials from one pass in plain doubles.
//
// Each coefficient is widened by an a-priori bound on its rounding error, (D + 8) u S C(n, k)
// A^(n-k) B^k with u = 2^-52, D the depth of the expression and S the constant of its absolute
// polynomial; the bound and the depths and constants of every certificate formula (evaluated in the
// order of certificate_polynomials.h) are derived in docs/MATH.md §3.10. The radius certificates
// Q G - 4 P H (edges Q G - 4 P) then combine the two enclosures with the interval P and Q in interval
// arithmetic, which needs the rounding mode upward (CGAL::Protect_FPU_rounding).
#include "certificate_enclosure.h"

#include "fixed_polynomial.h"

#include <algorithm>
#include <cmath>

namespace medusa::kinetic {

namespace {

// Largest |a| and |b| over the coordinates of the differences q.
template <std::size_t N>
void magnitudes(const fixed::Vec<double, 1> (&q)[N], int coordinates, double& A, double& B) {
  A = 0;
  B = 0;
  for (const auto& v : q)
    for (int i = 0; i < coordinates; ++i) {
      A = std::max(A, std::fabs(v[static_cast<std::size_t>(i)].c[0]));
      B = std::max(B, std::fabs(v[static_cast<std::size_t>(i)].c[1]));
    }
}

template <int N>
IntervalPoly widen(const fixed::Poly<double, N>& f, int depth, double structure, double A, double B) {
  const double scale = (depth + 8) * 0x1p-52 * structure;
  IntervalPoly r = IntervalPoly::zero_of_degree(N);
  double a_power[N + 1], b_power[N + 1];
  a_power[0] = b_power[0] = 1;
  for (int k = 1; k <= N; ++k) {
    a_power[k] = a_power[k - 1] * A;
    b_power[k] = b_power[k - 1] * B;
  }
  for (int k = 0; k <= N; ++k) {
    const double e = scale * binomial[N][k] * a_power[N - k] * b_power[k];
    r[k] = Interval(f.c[k] - e, f.c[k] + e);
  }
  return r;
}

} // namespace

IntervalPoly in_sphere_enclosure(const MovingPoint& p0, const MovingPoint& p1, const MovingPoint& p2,
                                 const MovingPoint& p3, const MovingPoint& y) {
  const fixed::Vec<double, 1> q[4] = {fixed::difference<double>(y, p0), fixed::difference<double>(y, p1),
                                      fixed::difference<double>(y, p2), fixed::difference<double>(y, p3)};
  fixed::Poly<double, 2> w[4];
  for (int i = 0; i < 4; ++i)
    w[i] = fixed::dot(q[i], q[i]);
  const fixed::Vec<double, 2> c01 = fixed::cross(q[0], q[1]), c23 = fixed::cross(q[2], q[3]);
  fixed::Poly<double, 5> f = w[3] * fixed::dot(c01, q[2]) - w[2] * fixed::dot(c01, q[3]);
  f = f + w[1] * fixed::dot(q[0], c23);
  f = f - w[0] * fixed::dot(q[1], c23);
  double A, B;
  magnitudes(q, 3, A, B);
  return widen(f, 17, 72, A, B);
}

IntervalPoly in_circle_enclosure(const MovingPoint& p0, const MovingPoint& p1, const MovingPoint& p2,
                                 const MovingPoint& y) {
  const fixed::Vec<double, 1> q[3] = {fixed::difference<double>(y, p0), fixed::difference<double>(y, p1),
                                      fixed::difference<double>(y, p2)};
  fixed::Poly<double, 2> w[3];
  for (int i = 0; i < 3; ++i)
    w[i] = q[i][0] * q[i][0] + q[i][1] * q[i][1];
  auto minor = [&](int i, int j) { return q[i][0] * q[j][1] - q[i][1] * q[j][0]; };
  fixed::Poly<double, 4> f = w[0] * minor(1, 2) - w[1] * minor(0, 2);
  f = f + w[2] * minor(0, 1);
  double A, B;
  magnitudes(q, 2, A, B);
  return widen(f, 11, 12, A, B);
}

IntervalPoly edge_radius_enclosure(const MovingPoint& p, const MovingPoint& q, const Interval& P,
                                   const Interval& Q) {
  const fixed::Vec<double, 1> d[1] = {fixed::difference<double>(p, q)};
  double A, B;
  magnitudes(d, 3, A, B);
  return Q * widen(fixed::dot(d[0], d[0]), 4, 3, A, B) - IntervalPoly(Interval(4) * P);
}

IntervalPoly triangle_radius_enclosure(const MovingPoint& p0, const MovingPoint& p1, const MovingPoint& p2,
                                       const Interval& P, const Interval& Q) {
  const fixed::Vec<double, 1> q[3] = {fixed::difference<double>(p0, p1), fixed::difference<double>(p0, p2),
                                      fixed::difference<double>(p1, p2)};
  const fixed::Poly<double, 2> la = fixed::dot(q[0], q[0]), lb = fixed::dot(q[1], q[1]),
                               lc = fixed::dot(q[2], q[2]);
  const fixed::Vec<double, 2> n = fixed::cross(q[0], q[1]);
  double A, B;
  magnitudes(q, 3, A, B);
  const IntervalPoly G = widen(la * lb * lc, 18, 27, A, B), H = widen(fixed::dot(n, n), 11, 12, A, B);
  return Q * G - (Interval(4) * P) * H;
}

IntervalPoly tetrahedron_radius_enclosure(const MovingPoint& p0, const MovingPoint& p1, const MovingPoint& p2,
                                          const MovingPoint& p3, const Interval& P, const Interval& Q) {
  const fixed::Vec<double, 1> q[3] = {fixed::difference<double>(p0, p1), fixed::difference<double>(p0, p2),
                                      fixed::difference<double>(p0, p3)};
  const fixed::Vec<double, 1>&a = q[0], &b = q[1], &c = q[2];
  const fixed::Vec<double, 2> bc = fixed::cross(b, c), ca = fixed::cross(c, a), ab = fixed::cross(a, b);
  const fixed::Poly<double, 2> la = fixed::dot(a, a), lb = fixed::dot(b, b), lc = fixed::dot(c, c);
  fixed::Vec<double, 4> N;
  for (std::size_t i = 0; i < 3; ++i)
    N[i] = la * bc[i] + lb * ca[i] + lc * ab[i];
  const fixed::Poly<double, 3> D = fixed::dot(a, bc);
  double A, B;
  magnitudes(q, 3, A, B);
  const IntervalPoly G = widen(fixed::dot(N, N), 31, 972, A, B), H = widen(D * D, 18, 36, A, B);
  return Q * G - (Interval(4) * P) * H;
}

} // namespace medusa::kinetic
