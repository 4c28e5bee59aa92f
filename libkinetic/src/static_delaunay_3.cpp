// The 3D static structures: CGAL's Delaunay_triangulation_3 and Fixed_alpha_shape_3.
#include "static_cgal.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Fixed_alpha_shape_3.h>
#include <CGAL/Fixed_alpha_shape_cell_base_3.h>
#include <CGAL/Fixed_alpha_shape_vertex_base_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <array>

namespace medusa::kinetic::detail {

namespace {

template <class K>
using Delaunay3 = CGAL::Delaunay_triangulation_3<
    K, CGAL::Triangulation_data_structure_3<CGAL::Triangulation_vertex_base_with_info_3<VertexId, K>>>;

} // namespace

template <>
std::vector<Simplex> delaunay_of_scaled<3>(const StaticInput& input, int k, int& dimension, bool& holds) {
  const CGAL::Gmpq zero(0);
  return triangulate<3, Delaunay3<Epick>>(scaled_points<3>(input, k), dimension, input, &zero,
                                          CGAL::Gmpq(1, CGAL::Gmpz(1) << k), &holds);
}

template <>
std::vector<Simplex> delaunay_of_exact<3>(const StaticInput& input, const CGAL::Gmpq& u, int& dimension,
                                          const CGAL::Gmpq* after, bool* holds) {
  return triangulate<3, Delaunay3<Epeck>>(exact_points<3>(input, u), dimension, input, after,
                                          after ? u - *after : CGAL::Gmpq(0), holds);
}

template <>
std::vector<Simplex> alpha_complex_of_exact<3>(const StaticInput& input, const CGAL::Gmpq& u,
                                               const CGAL::Gmpq& rho2, std::vector<Simplex>& tops) {
  using K = Epeck;
  using Vbb = CGAL::Triangulation_vertex_base_with_info_3<VertexId, K>;
  using Vb = CGAL::Fixed_alpha_shape_vertex_base_3<K, Vbb>;
  using Fb = CGAL::Fixed_alpha_shape_cell_base_3<K>;
  using Tds = CGAL::Triangulation_data_structure_3<Vb, Fb>;
  using Dt = CGAL::Delaunay_triangulation_3<K, Tds>;
  using Shape = CGAL::Fixed_alpha_shape_3<Dt>;

  const LabelledPoints<K, 3> pts = exact_points<3>(input, u);
  Dt dt(pts.begin(), pts.end());
  tops = top_simplices<3>(dt);
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
      std::size_t j = 0;
      for (int i = 0; i < 4; ++i)
        if (i != f->second)
          v[j++] = id(f->first->vertex(i));
      result.push_back(Simplex::from_range(v.begin(), v.end()));
    }
  for (auto c = shape.finite_cells_begin(); c != shape.finite_cells_end(); ++c)
    if (shape.classify(c) != Shape::EXTERIOR)
      result.push_back(top_simplex<3>(shape, c));
  return result;
}

} // namespace medusa::kinetic::detail
