// The degenerate groups of a static repair (docs/MATH.md §6.3, second bullet): the non-simplicial faces of
// the Delaunay subdivision D(t*) in the repaired region, with g(P) <= rho^2. One routine serves 3D and
// planar runs: a union-find over the top simplices of Del(t*+), joined across facets whose in-sphere
// (in-circle) vanishes exactly at t*, starting from the top simplices the repair created, yields the
// cells of D(t*) that meet the repair; in 3D the coplanar faces on their boundaries are the
// 2-dimensional groups, and classes of top simplices flat at t* span no sphere and are skipped.
// Why this finds exactly the groups, and g(P) for each: docs/MATH.md §6.7
// (tests/kinetic/test_kinetic_degenerate_groups_2d.cpp has a planar example derived on paper).
#pragma once

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

template <class K> int Engine<K>::orientation_at_now(const Simplex& t) {
  return sign_at_now([&](auto tag) { return orientation_poly<decltype(tag)>(t); });
}

// Are the d + 2 points of the finite top simplex t and the point y on one sphere (circle) at now? The
// sign convention of the determinant does not matter for the zero test.
template <class K> bool Engine<K>::cospherical_at_now(const Simplex& t, VertexId y) {
  return sign_at_now([&](auto tag) {
           using NT = decltype(tag);
           return K::template in_sphere<NT>(K::join(t), y, moving());
         }) == 0;
}

// Is the face with these coplanar vertices (>= 3, not collinear) within rho, g(P) <= rho^2? `apices`
// are the points that may lie inside its circle's ball (docs/MATH.md §6.3, Lemma 4.2), `cofaces` the finite
// tetrahedra around it, whose circumspheres are those of its Delaunay cofaces.
template <class K>
bool Engine<K>::face_group_within_rho(const std::vector<VertexId>& p, const std::vector<VertexId>& apices,
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
template <class K> bool Engine<K>::concyclic_at_now(const Simplex& t) {
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

template <class K>
std::vector<DegenerateGroup> Engine<K>::degenerate_groups(const std::vector<Simplex>& removed,
                                                          const std::vector<Simplex>& added) {
  std::set<std::vector<VertexId>> result;

  // d-dimensional cells of D(t*): search Del(t*+) from the created top simplices across facets whose
  // d + 2 points are cospherical (cocircular) at t*.
  UnionFind uf;
  std::unordered_map<Simplex, std::size_t, SimplexHash> index;
  std::vector<Simplex> tops;
  std::vector<Simplex> unvisited;
  auto visit = [&](const Simplex& t) {
    auto [it, fresh] = index.emplace(t, tops.size());
    if (fresh) {
      uf.add();
      tops.push_back(t);
      unvisited.push_back(t);
    }
    return it->second;
  };
  for (const Simplex& t : added)
    if (is_finite(t) && has_top(t))
      visit(t);
  std::unordered_map<Simplex, int, SimplexHash> cospherical; // facet -> in-sphere at t* == 0
  while (!unvisited.empty()) {
    Simplex t = unvisited.back();
    unvisited.pop_back();
    const std::size_t ti = index.at(t);
    for (std::size_t i = 0; i < t.size(); ++i) {
      Simplex f = t.facet(i);
      VertexId y = other_apex(f, t[i]);
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
  for (std::size_t i = 0; i < tops.size(); ++i)
    cells[uf.find(i)].push_back(tops[i]);

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
    if constexpr (dim == 2)
      continue; // every lower-dimensional face of D(t*) is simplicial in the plane (header comment)
    // 2-faces of the cell with >= 4 points: boundary triangles joined across coplanar edges.
    std::set<Simplex> in_cell(cell.begin(), cell.end());
    std::vector<Simplex> boundary;
    for (const Simplex& t : cell)
      for (std::size_t i = 0; i < 4; ++i) {
        Simplex f = t.facet(i);
        if (!in_cell.count(f.with(other_apex(f, t[i]))))
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
        for (const Simplex& t : tops_containing(f)) {
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
  if constexpr (dim == 2)
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
