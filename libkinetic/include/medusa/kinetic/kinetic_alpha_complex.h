// The kinetic Delaunay triangulation and fixed-radius alpha complex of moving cell centres
// (docs/MATH.md §2-§5). Run it over a whole set of trajectories; it reports every change to an Observer.
#pragma once

#include "medusa/kinetic/observer.h"
#include "medusa/kinetic/trajectories.h"

#include <gmpxx.h>

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace medusa::kinetic {

// rho^2 in grid units as an exact rational P/Q (docs/MATH.md §1.4).
struct SquaredRadius {
  mpz_class num = 1;
  mpz_class den = 1;
};

// Parses a decimal radius (e.g. "3.1") in physical units into rho_g^2 = (S rho)^2, exactly.
SquaredRadius squared_radius_from_decimal(const std::string& rho, std::int64_t scale);

struct KineticOptions {
  SquaredRadius rho2;
  bool audit = false;           // check the structure against static CGAL computations (audit())
  std::size_t audit_stride = 1; // audit after every audit_stride-th event batch, and at every frame
};

struct KineticStatistics {
  std::size_t batches = 0, frame_batches = 0;
  std::size_t flips23 = 0, flips32 = 0, hull_flips = 0, radius_events = 0;
  // Radius touches: R = rho at an instant without a change of shortness (a root of even
  // multiplicity, or at a frame), where a face's Gabriel test may flip (docs/MATH.md §3.9, corrected).
  std::size_t radius_touches = 0;
  std::size_t flips22 = 0; // planar runs: finite 2-2 flips (hull flips are counted in hull_flips)
  std::size_t insertions = 0, deletions = 0, static_rebuilds = 0;
  // Insertions and deletions made as local changes (Bowyer-Watson; the star of a leaving cell filled
  // with the Delaunay triangulation of its link); the others rebuilt Del statically.
  std::size_t local_insertions = 0, local_deletions = 0;
  std::size_t repairs_at_algebraic_times = 0; // static repairs inside a slab (docs/MATH.md §5.4)
  // Frames repaired because a top simplex flat there was not positively oriented just after it
  // (turned inside out, or flat for the whole new slab), or was next to a degenerate hull facet.
  std::size_t frames_repaired_for_flat_simplices = 0;
  std::size_t hull_ridges_folded_at_now = 0; // failed at creation: facets folded at a vanishing certificate
  // Hull certificates touching zero (a root of even multiplicity) next to a hull facet whose cells are
  // collinear then: the batch repairs there (Engine::resolve_hull_touches; docs/MATH.md §3.9, corrected).
  std::size_t hull_touches_repaired = 0;
  std::size_t hull_ridges_folding =
      0; // coplanar hull ridges whose facets fold inside a slab (fold tests fired)
  std::size_t cospherical_cells_flattening = 0; // orientation tests of identically cospherical facets fired
  // Hull flips refused because their new top simplex is flat at now without turning there
  // (Engine::flat_without_turning_at_now); the batch then ends in a static repair.
  std::size_t hull_flips_refused_touching = 0;
  // Top simplices a static rebuild kept that had turned inside out through a flat instant.
  std::size_t reoriented = 0;
  std::size_t certificates_built = 0; // certificates created (Delaunay and radius)
  // The same certificates by formula (docs/MATH.md §3.2-§3.4); the four add up to certificates_built.
  std::size_t built_in_sphere = 0; // in-sphere (in-circle in 2D) of a facet with two finite apices
  std::size_t built_hull = 0;      // orientation of a facet at the hull (the infinite vertex involved)
  std::array<std::size_t, 3> built_radius{}; // radius of an edge, a triangle, a tetrahedron
  std::size_t filter_settled = 0;            // settled by the interval Bernstein filter
  std::size_t double_filter_settled =
      0;                            // of which on the enclosure from plain doubles (certificate_enclosure.h)
  std::size_t interval_settled = 0; // settled in doubles by certified root isolation (root_isolation.h)
  std::size_t double_isolation_settled = 0; // of which on the enclosure from plain doubles
  std::size_t interval_scheduled =
      0; // failure times isolated in doubles, on intervals or on exact coefficients
  // vanish exactly at their slab start (u = 0), proven by one exact static determinant, and settled
  // in doubles after dividing out u (CC3D's lattice at MCS 0, docs/MATH.md §5.5)
  std::size_t start_zero_settled = 0;
  std::size_t start_zero_tests = 0;     // exact static determinants evaluated for this (zero or not)
  std::size_t exact_settled = 0;        // needed the exact polynomial (GMP, root isolation)
  std::size_t exact_filter_settled = 0; // of which settled by the filter on exact coefficients
  std::size_t exact_delaunay = 0, exact_radius = 0; // of which Delaunay / radius certificates
  std::size_t exact_scheduled = 0;                  // of which had a failure time in the slab
  std::size_t invalid_at_creation = 0;              // of which were invalid just after creation
  std::size_t root_cache_hits = 0; // exact certificates whose roots came from the slab's cache
  std::size_t sign_evaluations = 0, sign_evaluations_exact = 0;
  // Event times whose isolating intervals overlapped and stayed stuck in doubles (docs/MATH.md §3.7): roots
  // given their exact polynomial rounded to intervals, and comparisons left to algebraic reals.
  std::size_t times_sharpened = 0, times_compared_algebraically = 0;
  // Of the comparisons left stuck in doubles, those of two roots of proportional exact polynomials
  // (e.g. one certificate on translated copies of its cells, docs/MATH.md §8.6), decided without
  // algebraic reals.
  std::size_t times_compared_as_one_polynomial = 0;
  // Reported batch times whose rounding to the 2^-32 MCS grid needed an exact comparison (docs/MATH.md
  // §3.12): the time lay within rounding noise of a grid point.
  std::size_t times_reported_exactly = 0;
  std::size_t audits = 0, audits_compared_with_cgal = 0;
  std::vector<double> seconds_per_frame;

  // Flips of every kind (2-3 and 3-2 in 3D, 2-2 in the plane, hull flips in either).
  std::size_t flips() const { return flips23 + flips32 + flips22 + hull_flips; }
  // Every certificate failure processed (flips of each kind, radius events) and every insertion or
  // deletion of a cell at a frame.
  std::size_t events() const { return flips() + radius_events + insertions + deletions; }
};

class KineticAlphaComplex {
public:
  KineticAlphaComplex(const Trajectories& trajectories, KineticOptions options);
  ~KineticAlphaComplex();
  KineticAlphaComplex(const KineticAlphaComplex&) = delete;
  KineticAlphaComplex& operator=(const KineticAlphaComplex&) = delete;

  // Processes the whole run, reporting to the observer.
  void run(Observer& observer);

  const KineticStatistics& statistics() const;

  // The alpha complex at the current moment (finite simplices, sorted by dimension then vertices);
  // callable from inside Observer callbacks, where it is the state after the reported batch.
  std::vector<Simplex> current_complex() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace medusa::kinetic
