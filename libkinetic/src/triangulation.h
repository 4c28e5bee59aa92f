// The combinatorial Delaunay triangulation augmented with the infinite vertex: top simplices
// (tetrahedra, or triangles in a planar run) as sorted vertex tuples (the infinite vertex is
// -1 and sorts first), facets (triangles, or edges in 2D) with their two apices, and the top
// simplices incident to each vertex. The dimension is the size of the simplices added. Geometry lives
// elsewhere: certificates decide validity, this structure only records the combinatorics (flips are set
// operations, docs/MATH.md §4.5).
#pragma once

#include "cell_triangulation.h"
#include "medusa/kinetic/flat_simplex_map.h"
#include "medusa/kinetic/simplex.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace medusa::kinetic::detail {

class Triangulation {
public:
  void clear();
  // A top simplex is known by its facets: t is present iff its facet without t[0] has apex t[0]. No
  // table of top simplices is kept, which saves a hash-table operation per added or removed one.
  bool has_top(const Simplex& t) const {
    const Apices* a = apices(t.facet(0));
    return a != nullptr && a->orientation_slot(t[0]) >= 0;
  }
  // Adds t with the sign (+1 or -1) of the orientation of its sorted vertices, 0 for an infinite t;
  // the sign is kept with t's facets (Apices).
  void add_top(const Simplex& t, int orientation);
  // Removes t; a facet left with no top simplex goes, and its certificate id (Apices::cert), if it
  // had one, is appended to dropped_certs for the caller to retire.
  void remove_top(const Simplex& t, std::vector<int>& dropped_certs);
  // The recorded orientation of the top simplex t (0 for an infinite one), and its replacement: a top
  // simplex that flattens and turns inside out while staying in Del keeps its vertices but not its
  // sign (Engine::reorient_kept). Both require t to be present.
  int orientation(const Simplex& t) const { return apices(t.facet(0))->orientation_with(t[0]); }
  void set_orientation(const Simplex& t, int orientation);
  // Starts loading the records that removing t will touch (FlatSimplexMap::prefetch).
  void prefetch_top(const Simplex& t) const;

  // The apices of facet f (the vertices completing it to its two top simplices); count is 2 in a
  // valid triangulation. With each apex v[k], the orientation given to the top simplex f + v[k]
  // when it was added: every certificate of the facet needs it (docs/MATH.md §3.2), and the facet's record
  // is at hand where the top simplex would take a look-up of its own.
  struct Apices {
    std::array<VertexId, 2> v{{0, 0}};
    std::array<signed char, 2> orientation{{0, 0}};
    std::int8_t count = 0; // small: the table holds a record per facet
    // The engine's Delaunay certificate of the facet (-1: none). Kept in the facet's record rather
    // than a table of its own: installing a certificate then takes one look-up, not two.
    int cert = -1;
    // The index of apex in v; -1 when it is not one.
    int orientation_slot(VertexId apex) const {
      for (int k = 0; k < count; ++k)
        if (v[static_cast<std::size_t>(k)] == apex)
          return k;
      return -1;
    }
    // 0 when apex is not one.
    int orientation_with(VertexId apex) const {
      const int k = orientation_slot(apex);
      return k < 0 ? 0 : orientation[static_cast<std::size_t>(k)];
    }
  };
  const Apices* apices(const Simplex& facet) const;
  Apices* apices(const Simplex& facet);
  // The record of a facet with two top simplices; InternalError otherwise.
  const Apices& two_sided(const Simplex& facet) const;
  VertexId other_apex(const Simplex& facet, VertexId apex) const {
    const Apices& a = two_sided(facet);
    return a.v[0] == apex ? a.v[1] : a.v[0];
  }

  // The top simplices, iterable as simplices (`for (const Simplex& t : tri.tops())`), in no
  // meaningful order: each is listed from its one facet whose apex is its smallest vertex.
  class TopRange {
  public:
    class iterator {
    public:
      using Slots = FlatSimplexMap<Apices>::const_iterator;
      iterator(Slots it, Slots end) : it_(it), end_(end) { settle(); }
      const Simplex& operator*() const { return current_; }
      iterator& operator++() {
        ++k_;
        settle();
        return *this;
      }
      friend bool operator!=(const iterator& a, const iterator& b) { return a.it_ != b.it_ || a.k_ != b.k_; }

    private:
      // Advances to the next (facet, apex) pair whose apex sorts before the facet's vertices.
      void settle() {
        for (; it_ != end_; ++it_, k_ = 0)
          for (; k_ < it_->second.count; ++k_) {
            const VertexId apex = it_->second.v[static_cast<std::size_t>(k_)];
            if (apex < it_->first[0]) {
              std::array<VertexId, 4> w{};
              w[0] = apex;
              std::copy(it_->first.begin(), it_->first.end(), w.begin() + 1);
              current_ = Simplex::from_range(w.begin(), w.begin() + 1 + it_->first.size());
              return;
            }
          }
      }
      Slots it_, end_;
      int k_ = 0;
      Simplex current_;
    };
    TopRange(const FlatSimplexMap<Apices>& m, std::size_t n) : m_(m), n_(n) {}
    iterator begin() const { return iterator(m_.begin(), m_.end()); }
    iterator end() const { return iterator(m_.end(), m_.end()); }
    std::size_t size() const { return n_; }

  private:
    const FlatSimplexMap<Apices>& m_;
    std::size_t n_;
  };
  TopRange tops() const { return TopRange(facets_, top_count_); }
  const FlatSimplexMap<Apices>& facets() const { return facets_; }
  // Calls f(facet, record) for every facet, in table order; f may change the records but not add or
  // remove a top simplex.
  template <class F> void for_each_facet(F&& f) {
    for (auto& [facet, record] : facets_)
      f(facet, record);
  }
  template <class F> void for_each_facet(F&& f) const {
    for (const auto& [facet, record] : facets_)
      f(facet, record);
  }
  // The top simplices containing every vertex of s.
  std::vector<Simplex> tops_containing(const Simplex& s) const;
  // The finite (k+1)-cofaces of a finite k-simplex s, sorted, each once.
  std::vector<Simplex> finite_cofaces(const Simplex& s) const;
  const std::vector<Simplex>& tops_of(VertexId v) const;

  // Calls f(t) for every top simplex t containing s, without allocating: the queries of the
  // frontier and membership rules (docs/MATH.md §4.4, §4.5) run for every touched face of every event, so
  // they scan the shortest incident list of s's vertices.
  template <class F> void for_each_top_containing(const Simplex& s, F&& f) const {
    const std::vector<Simplex>& list = shortest_incident_list(s);
    for (const Simplex& t : list)
      if (contains_all(t, s))
        f(t);
  }
  // The first of its invariants that fails, or an empty string: every facet has two top simplices,
  // and each top simplex holds the same orientation (0 iff infinite) at every facet; each top
  // simplex is listed once at each of its vertices and nowhere else; the Euler characteristic is that
  // of the sphere S^dimension (the augmented triangulation of docs/MATH.md §2.1).
  std::string first_violation(int dimension) const;
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
    const std::vector<Simplex>* best = &tops_of(s[0]);
    for (std::size_t i = 1; i < s.size(); ++i) {
      const std::vector<Simplex>& l = tops_of(s[i]);
      if (l.size() < best->size())
        best = &l;
    }
    return *best;
  }

  std::size_t top_count_ = 0;
  FlatSimplexMap<Apices> facets_;
  // The last facet looked up and its record: installing a facet's certificate reads the record
  // three times (the certificate, its polynomial, its cache key). Any change of the table may move
  // records, so add_top, remove_top and clear forget it.
  mutable Simplex memo_key_;
  mutable const Apices* memo_ = nullptr;
  // Top simplices incident to each vertex, indexed by vertex id + 1 (the infinite vertex is -1).
  std::vector<std::vector<Simplex>> incident_;
};

} // namespace medusa::kinetic::detail
