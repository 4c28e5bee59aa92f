// Collision checks: two cells at one position at a frame, or meeting inside a slab (MATH.md 2.5).
#include "engine.h"

#include "medusa/kinetic/error.h"

#include <algorithm>
#include <string>
#include <vector>

namespace medusa::kinetic::detail {

namespace {
__extension__ typedef __int128 Int128; // GCC and Clang: products of two grid differences
} // namespace

void Engine::check_collisions_at_frame(std::size_t k) const {
  std::vector<std::pair<GridPoint, std::size_t>> pos;
  for (std::size_t i = 0; i < traj.cells.size(); ++i)
    if (traj.cells[i].present(k))
      pos.emplace_back(traj.cells[i].at(k), i);
  std::sort(pos.begin(), pos.end());
  for (std::size_t i = 1; i < pos.size(); ++i)
    if (pos[i].first == pos[i - 1].first)
      throw GeometryError("cells " + std::to_string(traj.cells[pos[i - 1].second].cell_id) + " and " +
                          std::to_string(traj.cells[pos[i].second].cell_id) +
                          " are at the same position at frame " + std::to_string(k) + " (time " +
                          std::to_string(traj.frame_times[k]) + ")");
}

// Collision inside the slab (MATH.md 2.5): p_i(u) = p_j(u) for some u in (now, 1). Tested on the
// Delaunay edges at the slab start and on every edge when it is created: colliding cells are
// joined by a Delaunay edge just before they meet.
void Engine::check_collision(const Simplex& e) const {
  const MovingPoint &p = pt(e[0]), &q = pt(e[1]);
  // p - q = d(u) = da + u db vanishes at one u in (0, 1) iff every coordinate does so at the same u:
  // da_i = db_i = 0, or da_i / db_i = -u with |da_i| < |db_i| and opposite signs. Decided in
  // integers (|da|, |db| < 2^41, so the cross products fit in 128 bits); only a real collision
  // builds the rational root.
  int pivot = -1;
  for (int i = 0; i < 3; ++i) {
    const std::int64_t da = p.a[i] - q.a[i], db = p.b[i] - q.b[i];
    if (db == 0) {
      if (da != 0)
        return;
      continue;
    }
    if (da == 0 || (da > 0) == (db > 0) || (da > 0 ? da : -da) >= (db > 0 ? db : -db))
      return; // this coordinate vanishes at u <= 0 or u >= 1
    if (pivot < 0) {
      pivot = i;
    } else {
      const std::int64_t pa = p.a[pivot] - q.a[pivot], pb = p.b[pivot] - q.b[pivot];
      if (static_cast<Int128>(da) * pb != static_cast<Int128>(pa) * db)
        return;
    }
  }
  if (pivot < 0)
    return; // equal positions and velocities: excluded at the frame (check_collisions_at_frame)
  mpq_class root(mpz_class(-(p.a[pivot] - q.a[pivot])), mpz_class(p.b[pivot] - q.b[pivot]));
  root.canonicalize();
  if (!(now < SlabTime(Rational(root.get_mpq_t()))))
    return;
  double t = double(traj.frame_times[slab]) +
             root.get_d() * double(traj.frame_times[slab + 1] - traj.frame_times[slab]);
  throw GeometryError("cells " + std::to_string(traj.cells[static_cast<std::size_t>(e[0])].cell_id) +
                      " and " + std::to_string(traj.cells[static_cast<std::size_t>(e[1])].cell_id) +
                      " collide at time " + std::to_string(t));
}

void Engine::check_collisions_in_slab() const {
  // In the plane the Delaunay edges are the triangulation's facets, whose table is smaller than the
  // faces' (which holds the triangles too): this pass runs at every frame.
  if (dim == 2) {
    tri.for_each_facet([this](const Simplex& e, const detail::Triangulation::Apices&) {
      if (is_finite(e))
        check_collision(e);
    });
    return;
  }
  for (const auto& kv : faces)
    if (kv.first.size() == 2)
      check_collision(kv.first);
}

} // namespace medusa::kinetic::detail
