// The degenerate groups of a static repair (docs/MATH.md §6.3, second bullet): the non-simplicial faces of
// the Delaunay subdivision at t* in the repaired region, with g(P) <= rho^2. One routine serves both
// dimensions d of the run (3, or 2 for planar runs): the top simplices ("tets") have d + 1 vertices,
// their facets d, and the cocircularity test across a facet is the in-sphere (in-circle in 2D).
//
// Construction. At a repair at t* both the old triangulation (valid on (t*-e, t*)) and the new one
// (Del(t*+), 5.4) are Delaunay at t* itself (closed conditions), so both refine the Delaunay
// subdivision D(t*); the subdivision is their common coarsening. Its d-dimensional cells are the
// maximal sets of points on a common empty sphere (circle in 2D). Two top simplices of the new
// triangulation sharing a facet lie in the same cell of D(t*) iff their d + 2 points are cospherical
// (cocircular) at t* (in-sphere, in-circle, exactly 0 at t*): if they are, the circumsphere of one
// (empty at t*) passes through the apex of the other; if they are not, the two spheres differ and the
// facet is a facet of D(t*). So a union-find over the top simplices of Del(t*+), joining across facets
// whose in-sphere vanishes *at* t* (exact sign, never doubles), starting from the top simplices
// created by the repair, yields exactly the cells of D(t*) that meet the repaired region (a
// triangulation of a convex cell has a connected dual graph, so the search also reaches the
// unchanged part of a cell the repair cut through). Cells with >= d + 2 points are the d-dimensional
// groups; g = R^2 of their sphere (circle), decided by the radius certificate of any top simplex of
// the cell that is not flat at t* (its circumsphere is the cell's).
//
// 3D. A tetrahedron that is flat at t* (orientation exactly 0) has four concyclic points when it is
// Delaunay at t* between two finite cells, and then its in-sphere with every fifth point vanishes: it
// merges with both sides. The 2-dimensional non-simplicial faces (>= 4 concyclic coplanar points)
// are faces of the 3-dimensional cells: every Delaunay cell containing such a face P contains P's
// circle, so it has >= 5 cospherical points (unless the whole point set is planar, which is reported
// as an error elsewhere, 5.7). They are found on the boundary of each cell: boundary triangles of the
// cell sharing an edge lie in one facet of the convex cell iff their four points are coplanar at t*
// (orientation exactly 0). For such a face P, g(P) = R(P)^2 if P is Gabriel, else min over its
// Delaunay cofaces, which are the (one or two) finite cells on either side of P. P is Gabriel iff no
// apex of a triangle of P (in Del(t*+)) lies strictly inside the ball of P's circle (Lemma 4.2
// extended to the subdivision: these apices are the vertices of the cells around P; by the cap lemma
// 4.4 the other points of a cell containing P are inside B_P all together or not at all, so the
// apices next to P decide). The remaining 2-dimensional case is a flat tetrahedron at t* on the hull
// (an infinite cell on both sides): the four points form a hull face with no finite coface, g =
// R(P)^2 if P is Gabriel against every point, else P contributes nothing. Edges and triangles are
// always simplicial, so there is nothing else.
//
// 2D. The groups are the 2-dimensional cells alone (>= 4 cocircular points, g = R^2 of the circle).
// A triangle flat at t* (three points momentarily collinear) lies on no circle: its in-circle with a
// fourth point vanishes only if that point is on the same line, so a flat triangle joins only flat
// triangles, and a class of triangles all flat at t* spans no circle, is no cell of D(t*), and is
// skipped. There are no lower-dimensional non-simplicial faces: a 1-dimensional face of D(t*) holding
// three points would hold them on a segment a..m..b, and three collinear points are never concyclic;
// worse, for every point z of the bisector of ab, |z - m|^2 = h^2 + d^2 < h^2 + |ab|^2/4 = |z - a|^2
// (h the distance from z to the line, d < |ab|/2 that from m to the midpoint), so the Voronoi regions
// of a and b do not even meet and ab is no edge at all. The same holds for three collinear points on
// the hull (the planar analogue of the flat hull tetrahedron above): they form no face. So every
// edge and vertex of D(t*) is simplicial.
//
// Where planar groups come from: a cocircular moment of generic motion is always resolved by 2-2 flips
// (four points on a circle at t* form a strictly convex quadrilateral), so a planar repair is forced
// by momentarily collinear points, and the cells it meets are sets that stay cocircular through the
// new slab (identically-zero in-circles, 5.3) whose triangulation the global rebuild re-chooses.
// The triangles flat at t* of such a repair are where "Delaunay at t*" holds only in the limit; they
// lie on no circle and are skipped as above, and the cocircular cells away from them are found as in
// 3D (tests/kinetic/test_kinetic_degenerate_groups_2d.cpp has an example derived on paper).
#include "engine.h"

#include "certificate_polynomials.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <set>
#include <unordered_map>
#include <vector>

namespace medusa::kinetic::detail {

namespace {

// Union-find over dense indices.
struct UnionFind {
  std::vector<std::size_t> parent;
  std::size_t add() {
    parent.push_back(parent.size());
    return parent.size() - 1;
  }
  std::size_t find(std::size_t i) {
    while (parent[i] != i)
      i = parent[i] = parent[parent[i]];
    return i;
  }
  void unite(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }
};

std::vector<DegenerateGroup> to_groups(const std::set<std::vector<VertexId>>& vertex_sets) {
  std::vector<DegenerateGroup> groups;
  for (const auto& g : vertex_sets)
    groups.push_back(DegenerateGroup{g});
  return groups;
}

} // namespace

int Engine::orientation_at_now(const Simplex& t) {
  return sign_at_now([&](auto tag) { return orientation_poly<decltype(tag)>(t); });
}

// Are the d + 2 points of the finite top simplex t and the point y on one sphere (circle) at now? The
// sign convention of the determinant does not matter for the zero test.
bool Engine::cospherical_at_now(const Simplex& t, VertexId y) {
  return sign_at_now([&](auto tag) {
           using NT = decltype(tag);
           return t.size() == 3 ? certificate::in_circle<NT>(pt(t[0]), pt(t[1]), pt(t[2]), pt(y))
                                : certificate::in_sphere<NT>(pt(t[0]), pt(t[1]), pt(t[2]), pt(t[3]), pt(y));
         }) == 0;
}

// Is the face with these coplanar vertices (>= 3, not collinear) within rho, g(P) <= rho^2? `apices`
// are the points that may lie inside its circle's ball (docs/MATH.md §6.3, Lemma 4.2), `cofaces` the finite
// tetrahedra around it, whose circumspheres are those of its Delaunay cofaces.
bool Engine::face_group_within_rho(const std::vector<VertexId>& p, const std::vector<VertexId>& apices,
                                   const std::vector<Simplex>& cofaces) {
  // Three points of P on its circle: the first two and any third one not collinear with them (all
  // points of P lie on one circle, so no three are collinear and p[2] will do).
  const VertexId a = p[0], b = p[1], c = p[2];
  bool gabriel = true;
  for (VertexId x : apices) {
    if (std::find(p.begin(), p.end(), x) != p.end())
      continue;
    int g = sign_at_now([&](auto tag) {
      using NT = decltype(tag);
      return certificate::gabriel_triangle<NT>(pt(a), pt(b), pt(c), pt(x));
    });
    if (g < 0) {
      gabriel = false;
      break;
    }
  }
  if (gabriel)
    return sign_at_now([&](auto tag) {
             using NT = decltype(tag);
             return certificate::triangle_radius<NT>(pt(a), pt(b), pt(c), pick(P, Pi, tag), pick(Q, Qi, tag));
           }) <= 0;
  for (const Simplex& t : cofaces)
    if (is_finite(t) && orientation_at_now(t) != 0 && sign_at_now([&](auto tag) {
                                                        return radius_poly<decltype(tag)>(t, pick(P, Pi, tag),
                                                                                          pick(Q, Qi, tag));
                                                      }) <= 0)
      return true;
  return false;
}

// Are the four points of t (coplanar at now) on one circle? Coplanar points are concyclic iff the
// fourth has power 0 with respect to the smallest circumsphere of the other three (docs/MATH.md §3.4), which
// needs those three not collinear (|n|^2 != 0; three collinear points are never concyclic with a
// fourth, and then some other triple is not collinear unless all four are, which is not concyclic).
bool Engine::concyclic_at_now(const Simplex& t) {
  for (std::size_t i = 0; i < 4; ++i) {
    Simplex tri3 = t.facet(i);
    if (collinear_at_now(tri3))
      continue;
    return sign_at_now([&](auto tag) {
             using NT = decltype(tag);
             return certificate::gabriel_triangle<NT>(pt(tri3[0]), pt(tri3[1]), pt(tri3[2]), pt(t[i]));
           }) == 0;
  }
  return false;
}

std::vector<DegenerateGroup> Engine::degenerate_groups(const std::vector<Simplex>& removed,
                                                       const std::vector<Simplex>& added) {
  std::set<std::vector<VertexId>> result;

  // d-dimensional cells of D(t*): search Del(t*+) from the created top simplices across facets whose
  // d + 2 points are cospherical (cocircular) at t*.
  UnionFind uf;
  std::unordered_map<Simplex, std::size_t, SimplexHash> index;
  std::vector<Simplex> tets;
  std::vector<Simplex> todo;
  auto visit = [&](const Simplex& t) {
    auto [it, fresh] = index.emplace(t, tets.size());
    if (fresh) {
      uf.add();
      tets.push_back(t);
      todo.push_back(t);
    }
    return it->second;
  };
  for (const Simplex& t : added)
    if (is_finite(t) && tri.has_tet(t))
      visit(t);
  std::unordered_map<Simplex, int, SimplexHash> cospherical; // facet -> in-sphere at t* == 0
  while (!todo.empty()) {
    Simplex t = todo.back();
    todo.pop_back();
    const std::size_t ti = index.at(t);
    for (std::size_t i = 0; i < t.size(); ++i) {
      Simplex f = t.facet(i);
      VertexId y = tri.other_apex(f, t[i]);
      if (y == infinite_vertex)
        continue;
      auto [it, fresh] = cospherical.emplace(f, 0);
      if (fresh)
        it->second = cospherical_at_now(t, y);
      if (it->second)
        uf.unite(ti, visit(f.with(y)));
    }
  }
  std::map<std::size_t, std::vector<Simplex>> cells;
  for (std::size_t i = 0; i < tets.size(); ++i)
    cells[uf.find(i)].push_back(tets[i]);

  std::vector<std::vector<VertexId>> found; // every degenerate face, within rho or not
  for (const auto& [root, cell] : cells) {
    std::set<VertexId> vs;
    for (const Simplex& t : cell)
      vs.insert(t.begin(), t.end());
    if (vs.size() < top_size() + 1) {
      // A single top simplex: simplicial. In 3D a tetrahedron flat at t* between two infinite cells may
      // be a concyclic hull face, handled below.
      continue;
    }
    // g = R_S^2 (docs/MATH.md §6.3): any top simplex of the cell that is not flat at t* has S as
    // circumsphere. A class of top simplices all flat at t* is no cell of D(t*) (d + 2 or more points
    // momentarily in one hyperplane, where every in-sphere vanishes): it spans no sphere and is skipped.
    const Simplex* solid = nullptr;
    for (const Simplex& t : cell)
      if (orientation_at_now(t) != 0) {
        solid = &t;
        break;
      }
    if (!solid)
      continue;
    std::vector<VertexId> cell_vertices(vs.begin(), vs.end());
    found.push_back(cell_vertices);
    if (sign_at_now([&](auto tag) {
          return radius_poly<decltype(tag)>(*solid, pick(P, Pi, tag), pick(Q, Qi, tag));
        }) <= 0)
      result.insert(cell_vertices);
    if (dim == 2)
      continue; // every lower-dimensional face of D(t*) is simplicial in the plane (header comment)
    // 2-faces of the cell with >= 4 points: boundary triangles joined across coplanar edges.
    std::set<Simplex> in_cell(cell.begin(), cell.end());
    std::vector<Simplex> boundary;
    for (const Simplex& t : cell)
      for (std::size_t i = 0; i < 4; ++i) {
        Simplex f = t.facet(i);
        if (!in_cell.count(f.with(tri.other_apex(f, t[i]))))
          boundary.push_back(f);
      }
    std::sort(boundary.begin(), boundary.end());
    boundary.erase(std::unique(boundary.begin(), boundary.end()), boundary.end());
    UnionFind faces_uf;
    for (std::size_t i = 0; i < boundary.size(); ++i)
      faces_uf.add();
    for (std::size_t i = 0; i < boundary.size(); ++i)
      for (std::size_t j = i + 1; j < boundary.size(); ++j) {
        std::set<VertexId> u(boundary[i].begin(), boundary[i].end());
        u.insert(boundary[j].begin(), boundary[j].end());
        if (u.size() != 4)
          continue; // not sharing an edge
        Simplex four = Simplex::from_range(u.begin(), u.end());
        if (orientation_at_now(four) == 0)
          faces_uf.unite(i, j);
      }
    std::map<std::size_t, std::vector<Simplex>> face_parts;
    for (std::size_t i = 0; i < boundary.size(); ++i)
      face_parts[faces_uf.find(i)].push_back(boundary[i]);
    for (const auto& [froot, part] : face_parts) {
      std::set<VertexId> fv;
      for (const Simplex& f : part)
        fv.insert(f.begin(), f.end());
      if (fv.size() < 4)
        continue;
      std::vector<VertexId> face(fv.begin(), fv.end());
      found.push_back(face);
      std::vector<VertexId> apices;
      std::vector<Simplex> cofaces;
      for (const Simplex& f : part)
        for (const Simplex& t : tri.tets_containing(f)) {
          cofaces.push_back(t);
          for (VertexId v : t)
            if (v != infinite_vertex && !fv.count(v))
              apices.push_back(v);
        }
      if (face_group_within_rho(face, apices, cofaces))
        result.insert(face);
    }
  }

  // Tetrahedra flat at t* on either side that no cell above contains: four concyclic points form a
  // hull face with only infinite cofaces; Gabriel is then tested against every present point. In 2D a
  // triangle flat at t* is three collinear points, never concyclic: nothing to add.
  if (dim == 2)
    return to_groups(result);
  auto inside_found = [&](const Simplex& t) {
    for (const auto& g : found)
      if (std::includes(g.begin(), g.end(), t.begin(), t.end()))
        return true;
    return false;
  };
  for (const auto* list : {&removed, &added})
    for (const Simplex& t : *list) {
      if (!is_finite(t) || inside_found(t) || orientation_at_now(t) != 0 || !concyclic_at_now(t))
        continue;
      std::vector<VertexId> face(t.begin(), t.end());
      found.push_back(face);
      if (face_group_within_rho(face, alive_ids(), {}))
        result.insert(face);
    }

  return to_groups(result);
}

} // namespace medusa::kinetic::detail
