// The alpha-complex state of every finite simplex of Del (edges and larger; docs/MATH.md §4.4, §4.5),
// as one part with its own invariants: shortness, membership in K, the radius certificate of the
// frontier, the number of top simplices holding the simplex, and the counts of its short cofaces and
// its cofaces in K, so that the frontier and membership rules are constant-time look-ups. The
// geometry (whether a simplex is short or Gabriel) is the engine's; this part keeps the flags and
// counts consistent with each other and with the triangulation.
//
// Invariants (first_violation): the simplices recorded are exactly the finite faces of Del (vertices
// aside), each with its count of top simplices; the coface counts equal a recount; a simplex in K is
// short and its facets are in K; exactly the frontier simplices hold a radius certificate.
#pragma once

#include "cell_triangulation.h"
#include "face.h"
#include "medusa/kinetic/flat_simplex_map.h"
#include "medusa/kinetic/simplex.h"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace medusa::kinetic::detail {

class FaceStates {
public:
  // The state of s, or nullptr when s is not recorded.
  Face* find(const Simplex& s) {
    auto it = states_.find(s);
    return it == states_.end() ? nullptr : &it->second;
  }
  const Face* find(const Simplex& s) const {
    auto it = states_.find(s);
    return it == states_.end() ? nullptr : &it->second;
  }
  // The state of a recorded simplex; InternalError otherwise.
  Face& at(const Simplex& s) { return states_.at(s); }
  const Face& at(const Simplex& s) const { return states_.at(s); }
  // The state of s, recorded anew (all flags clear) when it was not; true when it is new. Pointers
  // to states stay valid through additions within reserve_more's room, and until the next erase.
  std::pair<Face*, bool> add(const Simplex& s) {
    auto [it, fresh] = states_.try_emplace(s);
    return {&it->second, fresh};
  }
  void erase(const Simplex& s) { states_.erase(s); }
  void reserve_more(std::size_t n) { states_.reserve(states_.size() + n); }
  void prefetch(const Simplex& s) const { states_.prefetch(s); }
  void clear() { states_.clear(); }
  std::size_t size() const { return states_.size(); }
  // Calls f(simplex, state) for every recorded simplex, in table order; f may change the states but
  // not add or erase one.
  template <class F> void for_each(F&& f) {
    for (auto& slot : states_)
      f(slot.simplex(), slot.second);
  }
  template <class F> void for_each(F&& f) const {
    for (const auto& slot : states_)
      f(slot.simplex(), slot.second);
  }

  // Is s in K (a vertex: while its cell is alive)? Is s short (a vertex always is)? A simplex not
  // recorded is neither.
  bool in_k(const Simplex& s, const std::vector<char>& alive) const {
    if (s.size() == 1)
      return alive[static_cast<std::size_t>(s[0])] != 0;
    const Face* f = find(s);
    return f != nullptr && f->in_k;
  }
  bool is_short(const Simplex& s) const {
    if (s.size() == 1)
      return true;
    const Face* f = find(s);
    return f != nullptr && f->is_short;
  }

  // ---- the rules, on states given by state_of (this table's, or those of a change being applied)

  // Has s (a triangle or tetrahedron; false for an edge) a facet flagged long?
  template <class StateOf> static bool has_long_facet(const Simplex& s, StateOf&& state_of) {
    if (s.size() < 3)
      return false;
    for (std::size_t i = 0; i < s.size(); ++i)
      if (!state_of(s.facet(i))->is_short)
        return true;
    return false;
  }
  // The frontier (docs/MATH.md §4.4): maximal short simplices and minimal long ones. facet_short(x):
  // is facet x of s short.
  template <class FacetShort>
  static bool in_frontier(const Simplex& s, const Face& f, FacetShort&& facet_short) {
    if (f.is_short)
      return f.short_cofaces == 0;
    if (s.size() == 2)
      return true;
    for (std::size_t i = 0; i < s.size(); ++i)
      if (!facet_short(s.facet(i)))
        return false;
    return true;
  }
  // Adds the changes of c's shortness and membership (+1 gained, -1 lost, 0 unchanged) to the coface
  // counts of c's facets; state_of(x) gives the state of facet x, or nullptr (nothing to count).
  // Vertices keep no counts.
  template <class StateOf>
  static void count_in_facets(const Simplex& c, int short_delta, int k_delta, StateOf&& state_of) {
    if (c.size() <= 2 || (short_delta == 0 && k_delta == 0))
      return;
    for (std::size_t i = 0; i < c.size(); ++i)
      if (Face* f = state_of(c.facet(i))) {
        f->short_cofaces += short_delta;
        f->k_cofaces += k_delta;
      }
  }

  // The first of the invariants above that fails, or an empty string; alive[v]: is cell v alive.
  template <int D>
  std::string first_violation(const CellTriangulation<D>& cells, const std::vector<char>& alive) const;

private:
  FlatSimplexMap<Face, FiniteKeys> states_;
};

} // namespace medusa::kinetic::detail
