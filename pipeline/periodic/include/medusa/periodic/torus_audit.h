// The audit of a periodic run (--audit): the complex on the torus, as the canonical filter passes it
// on, checked against the static alpha complex on the torus (torus_alpha_complex.h) between events
// and after every frame (docs/MATH.md §8.7).
#pragma once

#include "medusa/kinetic/observer.h"
#include "medusa/periodic/periodic_cover.h"
#include "medusa/periodic/torus_alpha_complex.h"

#include <cstddef>
#include <set>
#include <string>
#include <vector>

namespace medusa::periodic {

struct TorusAuditStatistics {
  std::size_t checks = 0;                                   // audits run
  std::size_t periodic_triangulation = 0, tiled_copies = 0; // by oracle
  std::size_t compared = 0;                                 // complexes equal simplex for simplex
  std::size_t betti_only = 0; // cospherical positions: the complexes differ, the Betti numbers agree
  std::size_t skipped = 0;    // no room between two events, or points in fewer dimensions
};

// Sits between the canonical filter and the next observer, passing everything on. Throws
// InternalError ("audit failed on the torus ...") when the complex differs from the static one and,
// where cospherical cells let the two triangulations differ, when their Betti numbers differ too.
class TorusAudit : public kinetic::Observer {
public:
  TorusAudit(const PeriodicCover& cover, const io::PeriodicDomain& domain, const kinetic::SquaredRadius& rho2,
             int dimension, std::size_t stride, kinetic::Observer& next)
      : cover_(cover), domain_(domain), rho2_(rho2), dim_(dimension), stride_(stride == 0 ? 1 : stride),
        next_(next) {}

  void initial(const kinetic::EventTime& t0, const std::vector<kinetic::Simplex>& complex) override;
  void batch(const kinetic::EventTime& time, const std::vector<kinetic::Step>& steps) override;
  void frame(std::size_t k, const kinetic::EventTime& time) override;
  void finish(const kinetic::EventTime& t_end) override;

  const TorusAuditStatistics& statistics() const { return stats_; }

private:
  // Audits the complex held since (slab_, u_) at a rational time before `slab`, `u` (the next event).
  void audit_until(std::size_t slab, double u);
  bool audit_at(const mpq_class& q, bool last_try);

  const PeriodicCover& cover_;
  const io::PeriodicDomain& domain_;
  kinetic::SquaredRadius rho2_;
  int dim_;
  std::size_t stride_;
  kinetic::Observer& next_;
  std::set<kinetic::Simplex> complex_;
  std::size_t slab_ = 0;
  double u_ = 0.0;
  bool due_ = false;
  std::size_t batches_ = 0;
  TorusAuditStatistics stats_;
};

// One line for the user: how many audits, against which construction, decided how.
std::string describe(const TorusAuditStatistics& stats);

// Betti numbers over Z/2 of a simplicial complex (closed under faces), degrees 0 .. max dimension.
std::vector<std::size_t> betti_numbers_z2(const std::vector<kinetic::Simplex>& complex);

} // namespace medusa::periodic
