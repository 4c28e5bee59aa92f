#include "static_delaunay.h"

#include "static_delaunay_2.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Fixed_alpha_shape_3.h>
#include <CGAL/Fixed_alpha_shape_cell_base_3.h>
#include <CGAL/Fixed_alpha_shape_vertex_base_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <cmath>
#include <cstdlib>
#include <utility>

namespace medusa::kinetic::detail {

namespace {

// Epeck's exact number type is gmpxx's mpq_class.
CGAL::Exact_predicates_exact_constructions_kernel::FT exact(const CGAL::Gmpq& q) {
  return CGAL::Exact_predicates_exact_constructions_kernel::FT(mpq_class(q.mpq()));
}

template <class Dt> Simplex tet_of(const Dt& dt, typename Dt::Cell_handle c) {
  std::array<VertexId, 4> v;
  for (int i = 0; i < 4; ++i)
    v[i] = dt.is_infinite(c->vertex(i)) ? -1 : c->vertex(i)->info();
  return Simplex::from_range(v.begin(), v.end());
}

template <class Dt> std::vector<Simplex> all_tets(const Dt& dt) {
  std::vector<Simplex> result;
  if (dt.dimension() < 3)
    return result;
  for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c)
    result.push_back(tet_of(dt, c));
  return result;
}

template <class K>
std::vector<Simplex> triangulate(const std::vector<std::pair<typename K::Point_3, VertexId>>& pts,
                                 int& dimension) {
  using Vb = CGAL::Triangulation_vertex_base_with_info_3<VertexId, K>;
  using Tds = CGAL::Triangulation_data_structure_3<Vb>;
  using Dt = CGAL::Delaunay_triangulation_3<K, Tds>;
  Dt dt(pts.begin(), pts.end());
  dimension = dt.dimension();
  return all_tets(dt);
}

} // namespace

std::vector<Simplex> delaunay_just_after(int dim, const StaticInput& input, const CGAL::Gmpq& u,
                                         int& dimension) {
  // delta = 2^-k with the largest k <= 24 such that every coordinate 2^k a + b is an exact double;
  // invalid certificates left by a too large delta are repaired by flips at 0+ by the caller.
  double amax = 1, bmax = 1;
  for (const MovingPoint& m : input.motion)
    for (int i = 0; i < 3; ++i) {
      amax = std::max(amax, std::fabs(double(m.a[i])));
      bmax = std::max(bmax, std::fabs(double(m.b[i])));
    }
  int k = 24;
  while (k > 0 && std::ldexp(amax, k) + bmax >= std::ldexp(1.0, 52))
    --k;
  if (u == 0 && k >= 8 && dim == 2)
    return delaunay_2_scaled(input, k, dimension);
  if (u == 0 && k >= 8) {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    std::vector<std::pair<K::Point_3, VertexId>> pts;
    for (std::size_t i = 0; i < input.ids.size(); ++i) {
      const MovingPoint& m = input.motion[i];
      pts.emplace_back(K::Point_3(std::ldexp(double(m.a[0]), k) + double(m.b[0]),
                                  std::ldexp(double(m.a[1]), k) + double(m.b[1]),
                                  std::ldexp(double(m.a[2]), k) + double(m.b[2])),
                       input.ids[i]);
    }
    return triangulate<K>(pts, dimension);
  }
  // Exact rational points at u + 2^-40 (used at interior rational times and for huge coordinates).
  return delaunay_at(dim, input, u + CGAL::Gmpq(1, CGAL::Gmpz(1) << 40), dimension);
}

std::vector<Simplex> delaunay_at(int dim, const StaticInput& input, const CGAL::Gmpq& u, int& dimension) {
  if (dim == 2)
    return delaunay_2_at(input, u, dimension);
  using K = CGAL::Exact_predicates_exact_constructions_kernel;
  std::vector<std::pair<K::Point_3, VertexId>> pts;
  for (std::size_t i = 0; i < input.ids.size(); ++i) {
    const MovingPoint& m = input.motion[i];
    auto c = [&](int a) { return CGAL::Gmpq(CGAL::Gmpz(m.a[a])) + u * CGAL::Gmpq(CGAL::Gmpz(m.b[a])); };
    pts.emplace_back(K::Point_3(exact(c(0)), exact(c(1)), exact(c(2))), input.ids[i]);
  }
  return triangulate<K>(pts, dimension);
}

std::vector<Simplex> static_alpha_complex(int dim, const StaticInput& input, const CGAL::Gmpq& u,
                                          const CGAL::Gmpq& rho2, std::vector<Simplex>& tets) {
  if (dim == 2)
    return static_alpha_complex_2(input, u, rho2, tets);
  using K = CGAL::Exact_predicates_exact_constructions_kernel;
  using Vbb = CGAL::Triangulation_vertex_base_with_info_3<VertexId, K>;
  using Vb = CGAL::Fixed_alpha_shape_vertex_base_3<K, Vbb>;
  using Fb = CGAL::Fixed_alpha_shape_cell_base_3<K>;
  using Tds = CGAL::Triangulation_data_structure_3<Vb, Fb>;
  using Dt = CGAL::Delaunay_triangulation_3<K, Tds>;
  using Shape = CGAL::Fixed_alpha_shape_3<Dt>;

  std::vector<std::pair<K::Point_3, VertexId>> pts;
  for (std::size_t i = 0; i < input.ids.size(); ++i) {
    const MovingPoint& m = input.motion[i];
    auto c = [&](int a) { return CGAL::Gmpq(CGAL::Gmpz(m.a[a])) + u * CGAL::Gmpq(CGAL::Gmpz(m.b[a])); };
    pts.emplace_back(K::Point_3(exact(c(0)), exact(c(1)), exact(c(2))), input.ids[i]);
  }
  Dt dt(pts.begin(), pts.end());
  tets = all_tets(dt);
  Shape shape(dt, exact(rho2));
  std::vector<Simplex> result;
  auto id = [&](typename Dt::Vertex_handle v) { return v->info(); };
  for (auto v = shape.finite_vertices_begin(); v != shape.finite_vertices_end(); ++v)
    if (shape.classify(v) != Shape::EXTERIOR)
      result.push_back(Simplex{id(v)});
  for (auto e = shape.finite_edges_begin(); e != shape.finite_edges_end(); ++e)
    if (shape.classify(*e) != Shape::EXTERIOR)
      result.push_back(Simplex{id(e->first->vertex(e->second)), id(e->first->vertex(e->third))});
  for (auto f = shape.finite_facets_begin(); f != shape.finite_facets_end(); ++f)
    if (shape.classify(*f) != Shape::EXTERIOR) {
      std::array<VertexId, 3> v;
      int j = 0;
      for (int i = 0; i < 4; ++i)
        if (i != f->second)
          v[j++] = id(f->first->vertex(i));
      result.push_back(Simplex::from_range(v.begin(), v.end()));
    }
  for (auto c = shape.finite_cells_begin(); c != shape.finite_cells_end(); ++c)
    if (shape.classify(c) != Shape::EXTERIOR)
      result.push_back(tet_of(dt, c));
  return result;
}

} // namespace medusa::kinetic::detail
