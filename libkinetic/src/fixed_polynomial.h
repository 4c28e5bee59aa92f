// Polynomials whose degree is part of the type: the compiler unrolls every loop, so a certificate
// computed in plain doubles costs a few dozen nanoseconds (certificate_enclosure.h). Poly<NT>
// (polynomial.h) keeps a run-time degree for the exact and interval paths, where a coordinate that
// does not move lowers the degree.
#pragma once

#include "moving_point.h"

#include <array>

namespace medusa::kinetic::fixed {

template <class NT, int D> struct Poly { NT c[D + 1]; };

template <int A, int B> constexpr int max_of = A > B ? A : B;

template <class NT, int A, int B>
Poly<NT, max_of<A, B>> operator+(const Poly<NT, A>& f, const Poly<NT, B>& g) {
  Poly<NT, max_of<A, B>> r;
  for (int i = 0; i <= max_of<A, B>; ++i)
    r.c[i] = i > A ? g.c[i] : i > B ? f.c[i] : f.c[i] + g.c[i];
  return r;
}

template <class NT, int A, int B>
Poly<NT, max_of<A, B>> operator-(const Poly<NT, A>& f, const Poly<NT, B>& g) {
  Poly<NT, max_of<A, B>> r;
  for (int i = 0; i <= max_of<A, B>; ++i)
    r.c[i] = i > A ? -g.c[i] : i > B ? f.c[i] : f.c[i] - g.c[i];
  return r;
}

// Each coefficient is a sum of at most min(A, B) + 1 products, accumulated left to right (the order
// the error bounds of certificate_enclosure.cpp count).
template <class NT, int A, int B> Poly<NT, A + B> operator*(const Poly<NT, A>& f, const Poly<NT, B>& g) {
  Poly<NT, A + B> r;
  for (int k = 0; k <= A + B; ++k) {
    const int i0 = k > B ? k - B : 0, i1 = k < A ? k : A;
    NT s = f.c[i0] * g.c[k - i0];
    for (int i = i0 + 1; i <= i1; ++i)
      s += f.c[i] * g.c[k - i];
    r.c[k] = s;
  }
  return r;
}

template <class NT, int D> using Vec = std::array<Poly<NT, D>, 3>;

template <class NT, int A, int B> Poly<NT, A + B> dot(const Vec<NT, A>& x, const Vec<NT, B>& y) {
  return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}

template <class NT, int A, int B> Vec<NT, A + B> cross(const Vec<NT, A>& x, const Vec<NT, B>& y) {
  return {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
}

// q(u) - p(u), every coordinate of degree 1 (exact in double: coordinates are below 2^40).
template <class NT> Vec<NT, 1> difference(const MovingPoint& p, const MovingPoint& q) {
  Vec<NT, 1> r;
  for (int i = 0; i < 3; ++i)
    r[i] = Poly<NT, 1>{{NT(static_cast<double>(q.a[i] - p.a[i])), NT(static_cast<double>(q.b[i] - p.b[i]))}};
  return r;
}

} // namespace medusa::kinetic::fixed
