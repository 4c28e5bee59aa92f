// The certificate polynomials of docs/MATH.md §3.1, written once for any number type NT (exact mpz_class
// or a certified interval type) and any point type (moving points, or points at one time enclosure).
// All are translation invariant and computed from coordinates relative to the first point (docs/MATH.md
// §1.5), so every input difference is an exact integer.
#pragma once

#include "interval_filter.h"
#include "moving_point.h"
#include "polynomial.h"

#include <array>
#include <type_traits>

namespace medusa::kinetic::certificate {

template <class NT> using Vec = std::array<Poly<NT>, 3>;

// q(u) - p(u) as three polynomials of degree <= 1; a coordinate in which p and q move alike is a
// constant, so the certificates of points at rest (frozen at a slab start) are static determinants.
template <class NT> Vec<NT> difference(const MovingPoint& p, const MovingPoint& q) {
  Vec<NT> r;
  for (int i = 0; i < 3; ++i) {
    const NT a(static_cast<double>(q.a[i] - p.a[i]));
    r[i] = q.b[i] == p.b[i] ? Poly<NT>(a) : Poly<NT>(a, NT(static_cast<double>(q.b[i] - p.b[i])));
  }
  return r;
}

// A moving point at one time u of its slab, u known by an enclosure (the current event time): the
// certificates below, given such points, are their polynomials' values on that enclosure, as
// intervals. This serves the tests that need a sign at one time only (Gabriel, docs/MATH.md §3.4 and
// §4.5): a handful of interval operations on scalars instead of the whole polynomial, in the same
// order, so the interval is the one the constant polynomial would hold. The caller holds a
// CGAL::Protect_FPU_rounding guard.
struct PointAtTime {
  const MovingPoint* p;
  Interval u;
};

// What a formula computes on points of type Pt: a polynomial in u for moving points, a value on the
// time enclosure for points at one time.
template <class NT, class Pt> using Value = std::conditional_t<std::is_same_v<Pt, PointAtTime>, NT, Poly<NT>>;
template <class NT, class Pt> using ValueVec = std::array<Value<NT, Pt>, 3>;

// q(u) - p(u) = (q.a - p.a) + u (q.b - p.b) on the enclosure of u: integer differences first, as for
// moving points (docs/MATH.md §1.5).
template <class NT> std::array<NT, 3> difference(const PointAtTime& p, const PointAtTime& q) {
  static_assert(std::is_same_v<NT, Interval>, "a point at a time enclosure has interval coordinates");
  std::array<NT, 3> r;
  for (int i = 0; i < 3; ++i) {
    const Interval a(static_cast<double>(q.p->a[i] - p.p->a[i]));
    r[i] = q.p->b[i] == p.p->b[i] ? a : a + p.u * Interval(static_cast<double>(q.p->b[i] - p.p->b[i]));
  }
  return r;
}

template <class NT> Poly<NT> dot(const Vec<NT>& x, const Vec<NT>& y) {
  return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}

template <class NT> Vec<NT> cross(const Vec<NT>& x, const Vec<NT>& y) {
  return {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
}

template <class NT> Poly<NT> det3(const Vec<NT>& x, const Vec<NT>& y, const Vec<NT>& z) {
  return dot(x, cross(y, z));
}

// The same on values at one time.
template <class NT> NT dot(const std::array<NT, 3>& x, const std::array<NT, 3>& y) {
  return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}

template <class NT> std::array<NT, 3> cross(const std::array<NT, 3>& x, const std::array<NT, 3>& y) {
  return {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
}

template <class NT>
NT det3(const std::array<NT, 3>& x, const std::array<NT, 3>& y, const std::array<NT, 3>& z) {
  return dot(x, cross(y, z));
}

// O(p0,p1,p2,p3) = det[p1-p0; p2-p0; p3-p0]: the sign of CGAL::orientation. Degree <= 3.
template <class NT, class Pt>
Value<NT, Pt> orientation(const Pt& p0, const Pt& p1, const Pt& p2, const Pt& p3) {
  return det3(difference<NT>(p0, p1), difference<NT>(p0, p2), difference<NT>(p0, p3));
}

// InS(p0,p1,p2,p3; y) = det[(p_i - y, |p_i - y|^2)], degree <= 5. For O(p0..p3) > 0 it is < 0 iff y
// is strictly inside the circumsphere (docs/MATH.md §0).
template <class NT, class Pt>
Value<NT, Pt> in_sphere(const Pt& p0, const Pt& p1, const Pt& p2, const Pt& p3, const Pt& y) {
  const ValueVec<NT, Pt> q[4] = {difference<NT>(y, p0), difference<NT>(y, p1), difference<NT>(y, p2),
                                 difference<NT>(y, p3)};
  Value<NT, Pt> w[4];
  for (int i = 0; i < 4; ++i)
    w[i] = dot(q[i], q[i]);
  // Expansion along the last column: det = sum_i (-1)^(i+3) w_i det(minor_i), with the minors as
  // triple products sharing two cross products, det(a, b, c) = (a x b).c = a.(b x c): this runs for
  // every facet at every frame (docs/MATH.md §2.3).
  const ValueVec<NT, Pt> c01 = cross(q[0], q[1]), c23 = cross(q[2], q[3]);
  Value<NT, Pt> result = w[3] * dot(c01, q[2]) - w[2] * dot(c01, q[3]);
  result = result + w[1] * dot(q[0], c23);
  return result - w[0] * dot(q[1], c23);
}

// Planar certificates (docs/MATH.md §3.2 in dimension 2): the points move in the plane z = const, so only
// x and y enter.

// O2(p0,p1,p2) = det[p1-p0; p2-p0] over (x, y): the sign of CGAL::orientation for Point_2
// (positive counterclockwise). Degree <= 2.
template <class NT, class Pt> Value<NT, Pt> orientation_2(const Pt& p0, const Pt& p1, const Pt& p2) {
  const ValueVec<NT, Pt> a = difference<NT>(p0, p1), b = difference<NT>(p0, p2);
  return a[0] * b[1] - a[1] * b[0];
}

// InC(p0,p1,p2; y) = det[(p_i - y, |p_i - y|^2)]_{i=0..2} over (x, y), degree <= 4. For O2(p0,p1,p2) > 0
// it is > 0 iff y is strictly inside the circumcircle (the sign of CGAL::side_of_oriented_circle):
// the opposite convention to in_sphere, as for every lifted determinant of odd size.
template <class NT, class Pt> Value<NT, Pt> in_circle(const Pt& p0, const Pt& p1, const Pt& p2, const Pt& y) {
  const ValueVec<NT, Pt> q[3] = {difference<NT>(y, p0), difference<NT>(y, p1), difference<NT>(y, p2)};
  Value<NT, Pt> w[3];
  for (int i = 0; i < 3; ++i)
    w[i] = q[i][0] * q[i][0] + q[i][1] * q[i][1];
  auto minor = [&](int i, int j) { return q[i][0] * q[j][1] - q[i][1] * q[j][0]; };
  // Expansion along the last column: det = w_0 m_12 - w_1 m_02 + w_2 m_01.
  return w[0] * minor(1, 2) - w[1] * minor(0, 2) + w[2] * minor(0, 1);
}

// R1: Q|p-q|^2 - 4P <= 0 iff the edge is short (R <= rho, rho^2 = P/Q). Degree <= 2.
template <class NT, class Pt> Value<NT, Pt> edge_radius(const Pt& p, const Pt& q, const NT& P, const NT& Q) {
  ValueVec<NT, Pt> d = difference<NT>(p, q);
  return Q * dot(d, d) - Value<NT, Pt>(NT(4) * P);
}

// R2: Q|a|^2|b|^2|a-b|^2 - 4P|a x b|^2, the degree-6 form (docs/MATH.md §3.3).
template <class NT, class Pt>
Value<NT, Pt> triangle_radius(const Pt& p0, const Pt& p1, const Pt& p2, const NT& P, const NT& Q) {
  ValueVec<NT, Pt> a = difference<NT>(p0, p1), b = difference<NT>(p0, p2), c = difference<NT>(p1, p2);
  ValueVec<NT, Pt> n = cross(a, b);
  return Q * (dot(a, a) * dot(b, b) * dot(c, c)) - (NT(4) * P) * dot(n, n);
}

// R3: Q|N|^2 - 4P D^2 with N = |a|^2 (b x c) + |b|^2 (c x a) + |c|^2 (a x b), D = det(a,b,c). Degree <= 8.
template <class NT, class Pt>
Value<NT, Pt> tetrahedron_radius(const Pt& p0, const Pt& p1, const Pt& p2, const Pt& p3, const NT& P,
                                 const NT& Q) {
  ValueVec<NT, Pt> a = difference<NT>(p0, p1), b = difference<NT>(p0, p2), c = difference<NT>(p0, p3);
  ValueVec<NT, Pt> bc = cross(b, c), ca = cross(c, a), ab = cross(a, b);
  Value<NT, Pt> la = dot(a, a), lb = dot(b, b), lc = dot(c, c);
  ValueVec<NT, Pt> N;
  for (int i = 0; i < 3; ++i)
    N[i] = la * bc[i] + lb * ca[i] + lc * ab[i];
  Value<NT, Pt> D = dot(a, bc);
  return Q * dot(N, N) - (NT(4) * P) * (D * D);
}

// G1: (x-p).(x-q) >= 0 iff x is not strictly inside the diametral ball of pq. Degree <= 2.
template <class NT, class Pt> Value<NT, Pt> gabriel_edge(const Pt& p, const Pt& q, const Pt& x) {
  return dot(difference<NT>(p, x), difference<NT>(q, x));
}

// G2: |n|^2 |X|^2 - X.(w x n) >= 0 iff x is not strictly inside the smallest circumball of p0p1p2,
// with a = p1-p0, b = p2-p0, n = a x b, w = |a|^2 b - |b|^2 a, X = x - p0. Degree <= 6.
template <class NT, class Pt>
Value<NT, Pt> gabriel_triangle(const Pt& p0, const Pt& p1, const Pt& p2, const Pt& x) {
  ValueVec<NT, Pt> a = difference<NT>(p0, p1), b = difference<NT>(p0, p2), X = difference<NT>(p0, x);
  ValueVec<NT, Pt> n = cross(a, b);
  Value<NT, Pt> la = dot(a, a), lb = dot(b, b);
  ValueVec<NT, Pt> w;
  for (int i = 0; i < 3; ++i)
    w[i] = la * b[i] - lb * a[i];
  return dot(n, n) * dot(X, X) - dot(X, cross(w, n));
}

} // namespace medusa::kinetic::certificate
