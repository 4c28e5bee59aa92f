#include "static_delaunay_2.h"

#include <CGAL/Alpha_shape_2.h>
#include <CGAL/Alpha_shape_face_base_2.h>
#include <CGAL/Alpha_shape_vertex_base_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <array>
#include <cmath>
#include <utility>

namespace medusa::kinetic::detail {

namespace {

using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;

Epeck::FT exact(const CGAL::Gmpq& q) { return Epeck::FT(mpq_class(q.mpq())); }

template <class Dt> Simplex triangle_of(const Dt& dt, typename Dt::Face_handle f) {
  std::array<VertexId, 3> v;
  for (int i = 0; i < 3; ++i)
    v[i] = dt.is_infinite(f->vertex(i)) ? -1 : f->vertex(i)->info();
  return Simplex::from_range(v.begin(), v.end());
}

template <class Dt> std::vector<Simplex> all_triangles(const Dt& dt) {
  std::vector<Simplex> result;
  if (dt.dimension() < 2)
    return result;
  for (auto f = dt.all_faces_begin(); f != dt.all_faces_end(); ++f)
    result.push_back(triangle_of(dt, f));
  return result;
}

template <class K>
std::vector<Simplex> triangulate(const std::vector<std::pair<typename K::Point_2, VertexId>>& pts,
                                 int& dimension) {
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<VertexId, K>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb>;
  using Dt = CGAL::Delaunay_triangulation_2<K, Tds>;
  Dt dt(pts.begin(), pts.end());
  dimension = dt.dimension();
  return all_triangles(dt);
}

std::vector<std::pair<Epeck::Point_2, VertexId>> exact_points(const StaticInput& input, const CGAL::Gmpq& u) {
  std::vector<std::pair<Epeck::Point_2, VertexId>> pts;
  for (std::size_t i = 0; i < input.ids.size(); ++i) {
    const MovingPoint& m = input.motion[i];
    auto c = [&](int a) { return CGAL::Gmpq(CGAL::Gmpz(m.a[a])) + u * CGAL::Gmpq(CGAL::Gmpz(m.b[a])); };
    pts.emplace_back(Epeck::Point_2(exact(c(0)), exact(c(1))), input.ids[i]);
  }
  return pts;
}

} // namespace

std::vector<Simplex> delaunay_2_scaled(const StaticInput& input, int k, int& dimension) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<std::pair<K::Point_2, VertexId>> pts;
  for (std::size_t i = 0; i < input.ids.size(); ++i) {
    const MovingPoint& m = input.motion[i];
    pts.emplace_back(K::Point_2(std::ldexp(double(m.a[0]), k) + double(m.b[0]),
                                std::ldexp(double(m.a[1]), k) + double(m.b[1])),
                     input.ids[i]);
  }
  return triangulate<K>(pts, dimension);
}

std::vector<Simplex> delaunay_2_at(const StaticInput& input, const CGAL::Gmpq& u, int& dimension) {
  return triangulate<Epeck>(exact_points(input, u), dimension);
}

std::vector<Simplex> static_alpha_complex_2(const StaticInput& input, const CGAL::Gmpq& u,
                                            const CGAL::Gmpq& rho2, std::vector<Simplex>& triangles) {
  using K = Epeck;
  using Vbb = CGAL::Triangulation_vertex_base_with_info_2<VertexId, K>;
  using Vb = CGAL::Alpha_shape_vertex_base_2<K, Vbb>;
  using Fb = CGAL::Alpha_shape_face_base_2<K>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
  using Dt = CGAL::Delaunay_triangulation_2<K, Tds>;
  using Shape = CGAL::Alpha_shape_2<Dt>;

  std::vector<std::pair<K::Point_2, VertexId>> pts = exact_points(input, u);
  Dt dt(pts.begin(), pts.end());
  triangles = all_triangles(dt);
  // GENERAL mode: the alpha complex itself, lower-dimensional simplices included (REGULARIZED
  // would drop the edges and vertices that bound no triangle).
  Shape shape(dt, exact(rho2), Shape::GENERAL);
  std::vector<Simplex> result;
  auto id = [&](typename Dt::Vertex_handle v) { return v->info(); };
  for (auto v = shape.finite_vertices_begin(); v != shape.finite_vertices_end(); ++v)
    if (shape.classify(v) != Shape::EXTERIOR)
      result.push_back(Simplex{id(v)});
  for (auto e = shape.finite_edges_begin(); e != shape.finite_edges_end(); ++e)
    if (shape.classify(*e) != Shape::EXTERIOR)
      result.push_back(
          Simplex{id(e->first->vertex(Dt::cw(e->second))), id(e->first->vertex(Dt::ccw(e->second)))});
  for (auto f = shape.finite_faces_begin(); f != shape.finite_faces_end(); ++f)
    if (shape.classify(f) != Shape::EXTERIOR)
      result.push_back(triangle_of(shape, f));
  return result;
}

} // namespace medusa::kinetic::detail
