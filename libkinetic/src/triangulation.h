// The combinatorial Delaunay triangulation augmented with the infinite vertex: top simplices
// ("tets": tetrahedra, or triangles in a planar run) as sorted vertex tuples (the infinite vertex is
// -1 and sorts first), facets (triangles, or edges in 2D) with their two apices, and the top
// simplices incident to each vertex. The dimension is the size of the simplices added. Geometry lives
// elsewhere: certificates decide validity, this structure only records the combinatorics (flips are set
// operations, MATH.md 4.5).
#pragma once

#include "flat_simplex_map.h"
#include "medusa/kinetic/simplex.h"

#include <array>
#include <cstdint>
#include <vector>

namespace medusa::kinetic::detail {

constexpr VertexId infinite_vertex = -1;

inline bool is_finite(const Simplex& s) { return s[0] != infinite_vertex; }

class Triangulation {
public:
  void clear();
  bool has_tet(const Simplex& t) const { return tets_.count(t) != 0; }
  // Adds t with the sign (+1 or -1) of the orientation of its sorted vertices, 0 for an infinite t;
  // the sign is kept with t's facets (Apices).
  void add_tet(const Simplex& t, int orientation);
  void remove_tet(const Simplex& t);

  // The apices of facet f (the vertices completing it to its two tetrahedra); count is 2 in a
  // valid triangulation. With each apex v[k], the orientation given to the top simplex f + v[k]
  // when it was added: every certificate of the facet needs it (MATH.md 3.2), and the facet's record
  // is at hand where the top simplex would take a look-up of its own.
  struct Apices {
    std::array<VertexId, 2> v{{0, 0}};
    std::array<signed char, 2> orientation{{0, 0}};
    std::int8_t count = 0; // small: the table holds a record per facet
    // 0 when apex is not one.
    int orientation_with(VertexId apex) const {
      for (int k = 0; k < count; ++k)
        if (v[static_cast<std::size_t>(k)] == apex)
          return orientation[static_cast<std::size_t>(k)];
      return 0;
    }
  };
  const Apices* apices(const Simplex& facet) const;
  // The record of a facet with two top simplices; InternalError otherwise.
  const Apices& two_sided(const Simplex& facet) const;
  VertexId other_apex(const Simplex& facet, VertexId apex) const {
    const Apices& a = two_sided(facet);
    return a.v[0] == apex ? a.v[1] : a.v[0];
  }

  // The top simplices, iterable as simplices (`for (const Simplex& t : tri.tets())`).
  class TetRange {
  public:
    class iterator {
    public:
      explicit iterator(FlatSimplexMap<signed char>::const_iterator it) : it_(it) {}
      const Simplex& operator*() const { return it_->first; }
      iterator& operator++() {
        ++it_;
        return *this;
      }
      friend bool operator!=(const iterator& a, const iterator& b) { return a.it_ != b.it_; }

    private:
      FlatSimplexMap<signed char>::const_iterator it_;
    };
    explicit TetRange(const FlatSimplexMap<signed char>& m) : m_(m) {}
    iterator begin() const { return iterator(m_.begin()); }
    iterator end() const { return iterator(m_.end()); }
    std::size_t size() const { return m_.size(); }

  private:
    const FlatSimplexMap<signed char>& m_;
  };
  TetRange tets() const { return TetRange(tets_); }
  const FlatSimplexMap<Apices>& facets() const { return facets_; }
  // Tetrahedra containing every vertex of s.
  std::vector<Simplex> tets_containing(const Simplex& s) const;
  const std::vector<Simplex>& tets_of(VertexId v) const;

  // Calls f(t) for every top simplex t containing s, without allocating: the queries of the
  // frontier and membership rules (MATH.md 4.4, 4.5) run for every touched face of every event, so
  // they scan the shortest incident list of s's vertices.
  template <class F> void for_each_tet_containing(const Simplex& s, F&& f) const {
    const std::vector<Simplex>& list = shortest_incident_list(s);
    for (const Simplex& t : list)
      if (contains_all(t, s))
        f(t);
  }
  // Is s a face of some top simplex?
  bool contains_face(const Simplex& s) const {
    for (const Simplex& t : shortest_incident_list(s))
      if (contains_all(t, s))
        return true;
    return false;
  }

private:
  static bool contains_all(const Simplex& t, const Simplex& s) {
    for (VertexId v : s)
      if (!t.contains(v))
        return false;
    return true;
  }
  const std::vector<Simplex>& shortest_incident_list(const Simplex& s) const {
    const std::vector<Simplex>* best = &tets_of(s[0]);
    for (std::size_t i = 1; i < s.size(); ++i) {
      const std::vector<Simplex>& l = tets_of(s[i]);
      if (l.size() < best->size())
        best = &l;
    }
    return *best;
  }

  FlatSimplexMap<signed char> tets_; // the top simplices (a set: the values are unused)
  FlatSimplexMap<Apices> facets_;
  // Top simplices incident to each vertex, indexed by vertex id + 1 (the infinite vertex is -1).
  std::vector<std::vector<Simplex>> incident_;
};

} // namespace medusa::kinetic::detail
