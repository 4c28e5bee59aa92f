// The certificates computed in plain double arithmetic, returned as interval coefficients
// that provably enclose the exact integer ones: the cheap first filter of docs/MATH.md §3.8, run for every
// facet at every frame (docs/MATH.md §2.3). An enclosure is wider than the one interval arithmetic gives,
// so a certificate it cannot settle is recomputed with intervals (certificate_polynomials.h).
#pragma once

#include "interval_filter.h"
#include "moving_point.h"

namespace medusa::kinetic {

// Encloses InS(p0, p1, p2, p3; y) (degree 5, certificate::in_sphere), in any rounding mode.
IntervalPoly in_sphere_enclosure(const MovingPoint& p0, const MovingPoint& p1, const MovingPoint& p2,
                                 const MovingPoint& p3, const MovingPoint& y);

// Encloses InC(p0, p1, p2; y) (degree 4, certificate::in_circle), in any rounding mode.
IntervalPoly in_circle_enclosure(const MovingPoint& p0, const MovingPoint& p1, const MovingPoint& p2,
                                 const MovingPoint& y);

// Encloses the radius certificates of certificate::edge_radius (degree 2), triangle_radius (degree 6)
// and tetrahedron_radius (degree 8) for rho^2 in P / Q; needs the rounding mode upward.
IntervalPoly edge_radius_enclosure(const MovingPoint& p, const MovingPoint& q, const Interval& P,
                                   const Interval& Q);
IntervalPoly triangle_radius_enclosure(const MovingPoint& p0, const MovingPoint& p1, const MovingPoint& p2,
                                       const Interval& P, const Interval& Q);
IntervalPoly tetrahedron_radius_enclosure(const MovingPoint& p0, const MovingPoint& p1, const MovingPoint& p2,
                                          const MovingPoint& p3, const Interval& P, const Interval& Q);

} // namespace medusa::kinetic
