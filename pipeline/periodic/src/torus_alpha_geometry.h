// The exact decisions of alpha_from_tops (torus_alpha_from_tops.h) on the points of the kernel that
// triangulated them: Epick on integer coordinates that doubles hold exactly, Epeck otherwise.
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <gmpxx.h>

#include <type_traits>
#include <vector>

namespace medusa::periodic::detail {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;

template <class K, int D> struct TorusGeometry {
  using Point = std::conditional_t<D == 3, typename K::Point_3, typename K::Point_2>;
  using ExactPoint = std::conditional_t<D == 3, Epeck::Point_3, Epeck::Point_2>;

  explicit TorusGeometry(const mpq_class& r2) : rho2(r2), rho2_exact(r2), rho2_double(r2.get_d()) {}

  static ExactPoint exact(const Point& p) {
    if constexpr (std::is_same_v<K, Epeck>)
      return p;
    else if constexpr (D == 3)
      return ExactPoint(p.x(), p.y(), p.z());
    else
      return ExactPoint(p.x(), p.y());
  }

  // The smallest circumsphere (circle) of the points has radius at most rho.
  bool is_short(const std::vector<const Point*>& p) const {
    if constexpr (std::is_same_v<K, Epick>) {
      // Integer coordinates: squared distances are within a relative 1e-15 of the truth; an edge
      // longer than 2 rho by far more than that rules the face out (its radius is at least half).
      for (std::size_t i = 0; i < p.size(); ++i)
        for (std::size_t j = i + 1; j < p.size(); ++j)
          if (CGAL::squared_distance(*p[i], *p[j]) > 4 * rho2_double * (1 + 1e-9))
            return false;
    }
    std::vector<ExactPoint> e;
    for (const Point* x : p)
      e.push_back(exact(*x));
    Epeck::FT r;
    if constexpr (D == 3)
      r = e.size() == 2   ? CGAL::squared_radius(e[0], e[1])
          : e.size() == 3 ? CGAL::squared_radius(e[0], e[1], e[2])
                          : CGAL::squared_radius(e[0], e[1], e[2], e[3]);
    else
      r = e.size() == 2 ? CGAL::squared_radius(e[0], e[1]) : CGAL::squared_radius(e[0], e[1], e[2]);
    return r <= rho2_exact;
  }

  // q lies strictly inside the smallest circumsphere (circle) of the points (an exact predicate).
  bool strictly_inside(const std::vector<const Point*>& p, const Point& q) const {
    if constexpr (D == 3) {
      if (p.size() == 2)
        return CGAL::side_of_bounded_sphere(*p[0], *p[1], q) == CGAL::ON_BOUNDED_SIDE;
      if (p.size() == 3)
        return CGAL::side_of_bounded_sphere(*p[0], *p[1], *p[2], q) == CGAL::ON_BOUNDED_SIDE;
      return CGAL::side_of_bounded_sphere(*p[0], *p[1], *p[2], *p[3], q) == CGAL::ON_BOUNDED_SIDE;
    } else {
      if (p.size() == 2)
        return CGAL::side_of_bounded_circle(*p[0], *p[1], q) == CGAL::ON_BOUNDED_SIDE;
      return CGAL::side_of_bounded_circle(*p[0], *p[1], *p[2], q) == CGAL::ON_BOUNDED_SIDE;
    }
  }

  mpq_class rho2;
  Epeck::FT rho2_exact;
  double rho2_double;
};

} // namespace medusa::periodic::detail
