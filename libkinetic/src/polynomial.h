// Small dense univariate polynomials in the slab parameter u, with a fixed capacity (degree <= 8,
// the largest certificate degree of docs/MATH.md §3.1). The same template computes a certificate exactly
// (NT = mpz_class) and as a certified enclosure (NT = CGAL::Interval_nt_advanced), so the formula is
// written once (certificate_polynomials.h).
#pragma once

#include <array>
#include <cassert>

namespace medusa::kinetic {

// C(n, k) for n <= 8 (the largest certificate degree), as doubles: Bernstein conversions and error
// bounds of degree-n polynomials.
inline constexpr double binomial[9][9] = {{1},
                                          {1, 1},
                                          {1, 2, 1},
                                          {1, 3, 3, 1},
                                          {1, 4, 6, 4, 1},
                                          {1, 5, 10, 10, 5, 1},
                                          {1, 6, 15, 20, 15, 6, 1},
                                          {1, 7, 21, 35, 35, 21, 7, 1},
                                          {1, 8, 28, 56, 70, 56, 28, 8, 1}};

template <class NT> class Poly {
public:
  static constexpr int max_degree = 8;

  Poly() : deg_(-1) {}
  explicit Poly(const NT& constant) : deg_(0) { c_[0] = constant; }
  // The linear polynomial a + b u.
  Poly(const NT& a, const NT& b) : deg_(1) {
    c_[0] = a;
    c_[1] = b;
  }

  // The zero polynomial with room for coefficients up to u^d, to be filled in.
  static Poly zero_of_degree(int d) {
    assert(d <= max_degree);
    Poly r;
    r.deg_ = d;
    for (int i = 0; i <= d; ++i)
      r.c_[i] = NT(0);
    return r;
  }

  int degree_bound() const { return deg_; } // highest stored index (coefficients may be zero)

  // f / u^m for f whose coefficients of u^0 .. u^(m-1) are zero (the caller knows it: a root of
  // multiplicity m at a slab start): the coefficients from u^m on, moved down.
  Poly shifted_down(int m) const {
    assert(m >= 0);
    Poly r;
    r.deg_ = deg_ - m < -1 ? -1 : deg_ - m;
    for (int i = 0; i <= r.deg_; ++i)
      r.c_[i] = c_[i + m];
    return r;
  }
  const NT& operator[](int i) const { return c_[i]; }
  NT& operator[](int i) { return c_[i]; }

  friend Poly operator+(const Poly& f, const Poly& g) {
    Poly r;
    r.deg_ = f.deg_ > g.deg_ ? f.deg_ : g.deg_;
    for (int i = 0; i <= r.deg_; ++i)
      r.c_[i] = (i <= f.deg_ ? f.c_[i] : NT(0)) + (i <= g.deg_ ? g.c_[i] : NT(0));
    return r;
  }
  friend Poly operator-(const Poly& f, const Poly& g) {
    Poly r;
    r.deg_ = f.deg_ > g.deg_ ? f.deg_ : g.deg_;
    for (int i = 0; i <= r.deg_; ++i)
      r.c_[i] = (i <= f.deg_ ? f.c_[i] : NT(0)) - (i <= g.deg_ ? g.c_[i] : NT(0));
    return r;
  }
  friend Poly operator*(const Poly& f, const Poly& g) {
    Poly r;
    if (f.deg_ < 0 || g.deg_ < 0)
      return r;
    r.deg_ = f.deg_ + g.deg_;
    assert(r.deg_ <= max_degree);
    for (int i = 0; i <= r.deg_; ++i)
      r.c_[i] = NT(0);
    for (int i = 0; i <= f.deg_; ++i)
      for (int j = 0; j <= g.deg_; ++j)
        r.c_[i + j] += f.c_[i] * g.c_[j];
    return r;
  }
  friend Poly operator*(const NT& s, const Poly& f) {
    Poly r = f;
    for (int i = 0; i <= r.deg_; ++i)
      r.c_[i] = s * f.c_[i];
    return r;
  }
  Poly operator-() const {
    Poly r = *this;
    for (int i = 0; i <= r.deg_; ++i)
      r.c_[i] = -c_[i];
    return r;
  }

private:
  std::array<NT, max_degree + 1> c_{};
  int deg_;
};

} // namespace medusa::kinetic
