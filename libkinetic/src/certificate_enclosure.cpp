// Certified enclosures of the certificate polynomials from one pass in plain doubles.
//
// Why the bound holds. Every input coordinate x(u) = a + b u has integer a, b below 2^42 in
// magnitude, exact in double. Let A and B bound |a| and |b| over all inputs, so each input is
// bounded coefficientwise by M(u) = A + B u. Each operation on polynomials rounds each coefficient
// with relative error at most u = 2^-52 (any IEEE rounding mode). By induction over the expression
// (Higham, Accuracy and Stability, lemma 3.3): if the computed coefficients of f and g are within
// gamma_df * fbar and gamma_dg * gbar of the exact ones, where fbar and gbar are the coefficients of
// the same expression with every input replaced by M and every minus by a plus, then
//   f +- g is within gamma_(max(df, dg) + 1) * (fbar + gbar),
//   f * g, whose coefficients are sums of at most m products, is within gamma_(df + dg + m) * fbar*gbar,
// with gamma_n = n u / (1 - n u). For the expressions below (the formulas of
// certificate_polynomials.h, evaluated in the same order) the depth D and the absolute polynomial
// are, coefficientwise:
//   |q|^2 for a difference q: depth 4, bound 3 M^2 (2 M^2 over x, y: depth 3);
//   a cross product or a 2x2 minor: depth 3, bound 2 M^2; a triple product: depth 7, bound 6 M^3;
//   in-sphere: four terms |q_i|^2 * triple (depth 14, 18 M^5), their signed sum (17, 72 M^5);
//   in-circle: three terms |q_i|^2 * minor (9, 4 M^4), their signed sum (11, 12 M^4);
//   edge radius: G = |q|^2, H = 1;
//   triangle radius: G = |a|^2 |b|^2 |c|^2 (18, 27 M^6), H = |a x b|^2 (11, 12 M^4);
//   tetrahedron radius: N_i = sum |a|^2 (b x c)_i (12, 18 M^4), G = |N|^2 (31, 972 M^8),
//     D = det(a, b, c) (7, 6 M^3), H = D^2 (18, 36 M^6).
// So coefficient k of a degree-n result is within gamma_D * S * C(n, k) A^(n-k) B^k of the exact one
// (S the constant above). We widen by (D + 8) u * S * C(n, k) A^(n-k) B^k: gamma_D <= (D + 1) u, and
// rounding the endpoints c -+ e moves each by at most u (|c| + e), about u S C(n, k) A^(n-k) B^k, and
// computing e itself loses at most a relative (1 - u)^8 (at most 8 rounded products of positive
// numbers): the remaining 7 u cover both with room to spare (checked independently in review).
// The radius certificates Q G - 4 P H (edges Q G - 4 P) then combine the two enclosures with the interval P
// and Q in interval arithmetic, which needs the rounding mode upward (CGAL::Protect_FPU_rounding).
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
