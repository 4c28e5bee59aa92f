// The planar static structures: CGAL's Delaunay_triangulation_2 and Alpha_shape_2 on the points'
// x and y.
#include "static_cgal.h"

#include <CGAL/Alpha_shape_2.h>
#include <CGAL/Alpha_shape_face_base_2.h>
#include <CGAL/Alpha_shape_vertex_base_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

namespace medusa::kinetic::detail {

namespace {

template <class K>
using Delaunay2 = CGAL::Delaunay_triangulation_2<
    K, CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_with_info_2<VertexId, K>>>;

} // namespace

template <>
std::vector<Simplex> delaunay_of_scaled<2>(const StaticInput& input, int k, int& dimension, bool& holds) {
  const CGAL::Gmpq zero(0);
  return triangulate<2, Delaunay2<Epick>>(scaled_points<2>(input, k), dimension, input, &zero,
                                          CGAL::Gmpq(1, CGAL::Gmpz(1) << k), &holds);
}

template <>
std::vector<Simplex> delaunay_of_exact<2>(const StaticInput& input, const CGAL::Gmpq& u, int& dimension,
                                          const CGAL::Gmpq* after, bool* holds) {
  return triangulate<2, Delaunay2<Epeck>>(exact_points<2>(input, u), dimension, input, after,
                                          after ? u - *after : CGAL::Gmpq(0), holds);
}

template <>
std::vector<Simplex> alpha_complex_of_exact<2>(const StaticInput& input, const CGAL::Gmpq& u,
                                               const CGAL::Gmpq& rho2, std::vector<Simplex>& tops) {
  using K = Epeck;
  using Vbb = CGAL::Triangulation_vertex_base_with_info_2<VertexId, K>;
  using Vb = CGAL::Alpha_shape_vertex_base_2<K, Vbb>;
  using Fb = CGAL::Alpha_shape_face_base_2<K>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
  using Dt = CGAL::Delaunay_triangulation_2<K, Tds>;
  using Shape = CGAL::Alpha_shape_2<Dt>;

  const LabelledPoints<K, 2> pts = exact_points<2>(input, u);
  Dt dt(pts.begin(), pts.end());
  tops = top_simplices<2>(dt);
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
      result.push_back(top_simplex<2>(shape, f));
  return result;
}

} // namespace medusa::kinetic::detail
