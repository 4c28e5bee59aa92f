#include "medusa/periodic/torus_alpha_complex.h"

#include "torus_alpha_lifts.h"

#include <algorithm>

namespace medusa::periodic {

bool periodic_triangulation_applies(int dim, const io::PeriodicDomain& domain) {
  for (int a = 0; a < dim; ++a)
    if (!domain.periodic[static_cast<std::size_t>(a)] ||
        domain.period[static_cast<std::size_t>(a)] != domain.period[0])
      return false;
  return true;
}

TorusAlphaComplex torus_alpha_complex(int dim, const io::PeriodicDomain& domain,
                                      const std::vector<TorusPoint>& points,
                                      const kinetic::SquaredRadius& rho2, bool force_tiled) {
  // Every periodic coordinate wrapped into [origin, origin + L) (exact rational floor).
  std::vector<TorusPoint> wrapped = points;
  for (TorusPoint& t : wrapped)
    for (std::size_t a = 0; a < 3; ++a) {
      if (!domain.periodic[a])
        continue;
      const mpq_class shifted = (t.position[a] - domain.origin[a]) / mpq_class(domain.period[a]);
      mpz_class turns;
      mpz_fdiv_q(turns.get_mpz_t(), shifted.get_num_mpz_t(), shifted.get_den_mpz_t());
      t.position[a] -= mpq_class(turns * domain.period[a]);
    }
  // Dyadic coordinates (the audit picks dyadic times) are scaled to integers: if doubles then hold
  // them and their copies exactly, CGAL's Epick decides exactly and fast; Epeck otherwise.
  io::PeriodicDomain scaled_domain = domain;
  mpq_class r2(rho2.num, rho2.den);
  std::size_t bits = 0;
  bool integral = true;
  for (const TorusPoint& t : wrapped)
    for (const mpq_class& x : t.position) {
      if (mpz_popcount(x.get_den_mpz_t()) != 1) {
        integral = false;
        break;
      }
      bits = std::max(bits, mpz_sizeinbase(x.get_den_mpz_t(), 2) - 1);
    }
  if (integral) {
    const mpz_class factor = mpz_class(1) << bits;
    // The largest coordinate of a point or of a copy (at most two periods away), scaled.
    mpq_class largest = 0;
    for (const TorusPoint& t : wrapped)
      for (const mpq_class& x : t.position)
        largest = std::max(largest, mpq_class(abs(x)));
    largest += 2 * std::max({domain.period[0], domain.period[1], domain.period[2]});
    largest *= factor;
    integral = largest < mpq_class(mpz_class(1) << 50);
    if (integral) {
      for (TorusPoint& t : wrapped)
        for (mpq_class& x : t.position)
          x *= factor;
      for (std::size_t a = 0; a < 3; ++a) {
        scaled_domain.origin[a] = mpz_class(domain.origin[a] * factor).get_si();
        scaled_domain.period[a] = mpz_class(domain.period[a] * factor).get_si();
      }
      r2 *= factor * factor;
    }
  }
  TorusAlphaComplex result;
  if (!force_tiled && periodic_triangulation_applies(dim, domain)) {
    result.oracle = TorusOracle::periodic_triangulation;
    result.complex = dim == 3 ? detail::periodic_triangulation_alpha<3>(scaled_domain, wrapped, r2, integral)
                              : detail::periodic_triangulation_alpha<2>(scaled_domain, wrapped, r2, integral);
  } else {
    result.oracle = TorusOracle::tiled_copies;
    result.complex =
        dim == 3
            ? detail::tiled_copies_alpha<3>(scaled_domain, wrapped, r2, integral, result.full_dimensional)
            : detail::tiled_copies_alpha<2>(scaled_domain, wrapped, r2, integral, result.full_dimensional);
  }
  return result;
}

} // namespace medusa::periodic
