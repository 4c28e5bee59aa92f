#include "torus_alpha_from_tops.h"
#include "torus_alpha_geometry.h"
#include "torus_alpha_lifts.h"

#include "medusa/core/error.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_2.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_traits_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <map>

namespace medusa::periodic::detail {

namespace {

template <class K> typename K::FT number(const mpq_class& x) {
  if constexpr (std::is_same_v<K, Epick>)
    return x.get_d(); // an integer below 2^50 (the caller's `integral`)
  else
    return typename K::FT(x);
}

template <class K> typename K::Point_2 point_of(const std::array<mpq_class, 3>& x) {
  return typename K::Point_2(number<K>(x[0]), number<K>(x[1]));
}

std::vector<kinetic::VertexId> ids_of(const std::vector<TorusPoint>& points) {
  std::vector<kinetic::VertexId> ids;
  for (const TorusPoint& t : points)
    ids.push_back(t.id);
  return ids;
}

template <class K>
std::vector<kinetic::Simplex> periodic_alpha(const io::PeriodicDomain& domain,
                                             const std::vector<TorusPoint>& points, const mpq_class& rho2) {
  using Point = typename K::Point_2;
  using Gt = CGAL::Periodic_2_Delaunay_triangulation_traits_2<K>;
  using P2DT2 = CGAL::Periodic_2_Delaunay_triangulation_2<Gt>;
  const std::array<mpq_class, 3> lo = {mpq_class(domain.origin[0]), mpq_class(domain.origin[1]),
                                       mpq_class(domain.origin[2])};
  std::array<mpq_class, 3> hi = lo;
  for (mpq_class& x : hi)
    x += mpq_class(domain.period[0]);
  const Point a = point_of<K>(lo), b = point_of<K>(hi);
  P2DT2 tri(typename Gt::Iso_rectangle_2(a, b));
  // The periodic triangulation keeps each point once (in the domain); its lifts carry offsets.
  std::map<Point, kinetic::VertexId, typename K::Less_xy_2> id_of;
  std::vector<Point> pts;
  for (const TorusPoint& t : points) {
    pts.push_back(point_of<K>(t.position));
    if (!id_of.emplace(pts.back(), t.id).second)
      throw InternalError("periodic audit: two cells at one position");
  }
  tri.insert(pts.begin(), pts.end(), false);
  // Before it can be a one-sheeted covering of the torus, CGAL triangulates the 9 copies of the
  // points in the square of side 3L; every triangle of it is a lift of a triangle of Del on the
  // torus, so reading all of them gives the same complex.
  std::vector<std::vector<LiftedVertex<Point>>> tops;
  for (auto c = tri.faces_begin(); c != tri.faces_end(); ++c) {
    std::vector<LiftedVertex<Point>> top;
    for (const auto& pp : tri.periodic_triangle(c)) {
      LiftedVertex<Point> v;
      v.id = id_of.at(pp.first);
      v.offset = {pp.second.x(), pp.second.y(), 0};
      v.p = tri.point(pp);
      top.push_back(v);
    }
    tops.push_back(std::move(top));
  }
  return alpha_from_tops(tops, TorusGeometry<K, 2>(rho2), ids_of(points),
                         [](const std::vector<const LiftedVertex<Point>*>&) { return true; });
}

template <class K>
std::vector<kinetic::Simplex> tiled_alpha(const io::PeriodicDomain& domain,
                                          const std::vector<TorusPoint>& points, const mpq_class& rho2,
                                          bool& full_dimensional) {
  using Point = typename K::Point_2;
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>;
  using Dt = CGAL::Delaunay_triangulation_2<K, CGAL::Triangulation_data_structure_2<Vb>>;
  std::vector<LiftedVertex<Point>> lifted;
  std::vector<std::pair<Point, std::size_t>> input;
  const std::array<int, 3> reach = {domain.periodic[0] ? 1 : 0, domain.periodic[1] ? 1 : 0, 0};
  for (const TorusPoint& t : points)
    for (int i = -reach[0]; i <= reach[0]; ++i)
      for (int j = -reach[1]; j <= reach[1]; ++j)
        for (int k = -reach[2]; k <= reach[2]; ++k) {
          LiftedVertex<Point> v;
          v.id = t.id;
          v.offset = {i, j, k};
          std::array<mpq_class, 3> x = t.position;
          for (std::size_t a = 0; a < 3; ++a)
            x[a] += v.offset[a] * mpq_class(domain.period[a]);
          v.p = point_of<K>(x);
          input.emplace_back(v.p, lifted.size());
          lifted.push_back(v);
        }
  Dt dt(input.begin(), input.end());
  full_dimensional = dt.dimension() == 2;
  std::vector<std::vector<LiftedVertex<Point>>> tops;
  if (full_dimensional)
    for (auto c = dt.finite_faces_begin(); c != dt.finite_faces_end(); ++c) {
      std::vector<LiftedVertex<Point>> top;
      for (int i = 0; i < 3; ++i)
        top.push_back(lifted[c->vertex(i)->info()]);
      tops.push_back(std::move(top));
    }
  // Only a face with a vertex in the middle copy sees all its cofaces of the periodic set within
  // 4 rho < L of it (docs/MATH.md §8.7).
  return alpha_from_tops(tops, TorusGeometry<K, 2>(rho2), ids_of(points),
                         [](const std::vector<const LiftedVertex<Point>*>& face) {
                           for (const auto* v : face)
                             if (v->offset == Offset{0, 0, 0})
                               return true;
                           return false;
                         });
}

} // namespace

template <>
std::vector<kinetic::Simplex> periodic_triangulation_alpha<2>(const io::PeriodicDomain& domain,
                                                              const std::vector<TorusPoint>& points,
                                                              const mpq_class& rho2, bool integral) {
  return integral ? periodic_alpha<Epick>(domain, points, rho2) : periodic_alpha<Epeck>(domain, points, rho2);
}

template <>
std::vector<kinetic::Simplex>
tiled_copies_alpha<2>(const io::PeriodicDomain& domain, const std::vector<TorusPoint>& points,
                      const mpq_class& rho2, bool integral, bool& full_dimensional) {
  return integral ? tiled_alpha<Epick>(domain, points, rho2, full_dimensional)
                  : tiled_alpha<Epeck>(domain, points, rho2, full_dimensional);
}

} // namespace medusa::periodic::detail
