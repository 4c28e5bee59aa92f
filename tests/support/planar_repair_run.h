// The planar run that forces a static repair cutting through five cocircular cells (docs/MATH.md §5.4,
// 6.3), shared by the kinetic and medusa tests of planar degenerate groups.
#pragma once

#include "medusa/kinetic/trajectories.h"

#include <cstdint>
#include <vector>

namespace medusa::test {

// Frames t = 0, 100, 200. Vertex ids 0..12 (cell id - 1).
//
// The group: a rectangle p1 = (-104,17) (id 0), p2 = (-104,23) (1), p3 = (-96,17) (2), p4 = (-96,23)
// (3), all still, on the circle of centre (-100,20) and R^2 = 4^2 + 3^2 = 25; e (4) moves from
// (-100,11) to (-100,15) in slab 0, reaching the circle at t = 100, and stays there. Before t = 100 e
// is outside the circle: Del holds the rectangle split by CGAL's perturbation at t0+ and the ear p1 p3
// e. With lexicographic order p1 < p2 < p3 < p4, the perturbation of 4 cocircular points keeps the
// largest one an ear: triangles p2 p3 p4 and p1 p2 p3 (diagonal p2 p3). At t = 100 the five are
// cocircular (an empty circle: the other cells are more than 100 away) and stay so in slab 1: their
// in-circles vanish identically there, so no flip happens and the old triangulation {p1 p2 p3, p2 p3
// p4, p1 p3 e} is kept. The rebuild of a repair at t = 100 perturbs the order p1 < p2 < e < p3 < p4
// (e = (-100,15)): peeling the largest point as an ear each time gives p2 p3 p4 (p4 between p3 and
// p2 on the pentagon p1 e p3 p4 p2), then e p3 p2, then p1 e p2. So the repair removes p1 p2 p3 and p1
// p3 e and creates e p2 p3 and p1 e p2: it cuts through the 2-cell {p1, p2, e, p3, p4} of D(100), the
// only group, with g = R^2 = 25.
//
// The repair: a = (29,27) (5), b = (29,21) (6), c = (29,26) (7), d = (29,13) (8) reach the line x = 29
// together at t = 100, on the right end of the hull (found in a random walk of the engine tests).
// Just before, the edge ab has the triangles abd and abc; both are flat at t = 100, so the in-circle
// of ab changes sign there. Just after, a and b move to x = 29 - v while c and d stay on x = 29: the
// quadrilateral a d b c is not convex (a and b on one side of cd), no 2-2 flip applies and the engine
// repairs statically (docs/MATH.md §5.2 step 3), removing abd and abc and creating bcd. These triangles are
// flat at t = 100: a flat triangle lies on no circle, so its class is skipped (no group). Four still
// cells (9..12) fill the hull's inside.
inline kinetic::Trajectories planar_repair_with_pentagon() {
  kinetic::Trajectories t;
  t.dimension = 2;
  t.scale = 1;
  t.frame_times = {0, 100, 200};
  auto path = [&](std::int64_t id, std::vector<kinetic::GridPoint> p) { t.cells.push_back({id, 1, 0, p}); };
  auto still = [&](std::int64_t id, std::int64_t x, std::int64_t y) {
    path(id, {{x, y, 0}, {x, y, 0}, {x, y, 0}});
  };
  still(1, -104, 17);
  still(2, -104, 23);
  still(3, -96, 17);
  still(4, -96, 23);
  path(5, {{-100, 11, 0}, {-100, 15, 0}, {-100, 15, 0}});
  path(6, {{30, 25, 0}, {29, 27, 0}, {28, 27, 0}});
  path(7, {{29, 19, 0}, {29, 21, 0}, {28, 22, 0}});
  path(8, {{28, 24, 0}, {29, 26, 0}, {29, 25, 0}});
  path(9, {{30, 15, 0}, {29, 13, 0}, {29, 15, 0}});
  still(10, 20, 20);
  still(11, 22, 10);
  still(12, 21, 29);
  still(13, 14, 16);
  return t;
}

} // namespace medusa::test
