// The combinatorial Delaunay triangulation held as cells: each top simplex (tetrahedron, or triangle
// in a planar run; the infinite vertex is -1) is a record of its sorted vertices, the top simplices
// across its facets, its facets' certificate ids and its orientation, reached by an index that stays
// valid while the cell lives. Changes are replacements of held cells (a flip is two cells by three,
// docs/MATH.md §4.5; a local insertion or deletion a star by another), glued to the cells around
// them without a look-up by vertices. This is the shape of CGAL's Triangulation_data_structure_3 /
// _2, kept in arrays (cells are reused through a free list) so that a certificate or a queue entry can
// name (cell, facet) by two integers. Geometry lives elsewhere: certificates decide validity, this
// structure only records the combinatorics. "Cell" is CGAL's word for a top simplex here, not a
// CompuCell3D cell (a vertex).
#pragma once

#include "medusa/kinetic/simplex.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace medusa::kinetic::detail {

constexpr VertexId infinite_vertex = -1;

inline bool is_finite(const Simplex& s) { return s[0] != infinite_vertex; }

using CellIndex = std::int32_t;
constexpr CellIndex no_cell = -1;

template <int D> class CellTriangulation {
public:
  static_assert(D == 2 || D == 3, "a run is planar or 3D");
  static constexpr std::size_t top_size = D + 1;
  static constexpr int dimension = D;

  // A top simplex to add and the sign of the orientation of its sorted vertices (0 if infinite).
  struct NewTop {
    Simplex top;
    int orientation = 0;
  };

  void clear();
  // Replaces everything by `tops`, which must form a closed pseudo-manifold (every facet in exactly
  // two of them); InternalError otherwise, leaving the triangulation as it was. Cells are numbered in
  // the order given; every facet starts without a certificate.
  void assign(const std::vector<NewTop>& tops);
  // Replaces the cells `removed` (distinct, alive) by `added`. The added top simplices must close the
  // hole exactly: each facet on the boundary of `removed` is a facet of exactly one added simplex, and
  // every other facet of an added simplex is shared by exactly two of them; InternalError otherwise,
  // leaving the triangulation as it was. Boundary facets keep their certificate ids; facets inside
  // `removed` go, and their ids are appended to dropped_certs in the order of `removed`, each facet
  // with the later of its two cells. The new cells' indices are written to `created`, one per added simplex,
  // if given.
  void replace(const std::vector<CellIndex>& removed, const std::vector<NewTop>& added,
               std::vector<int>& dropped_certs, std::vector<CellIndex>* created = nullptr);

  // The flip through c's i-th facet f (docs/MATH.md §4.5): c and its neighbour across f become the D
  // top simplices (f - x) + p + q, one for each vertex x of f in order, where p is c's vertex off f
  // and q the neighbour's; a 2-3 flip in 3D, a 2-2 flip in the plane. The edge pq must not be in the
  // triangulation. `orientations` are those of the new cells, in the same order, and the new cells
  // are written to `created`. f goes, and its certificate id is appended to dropped_certs; every other
  // facet keeps its id. The same as replace() of {c, neighbour} by those simplices, without a look-up.
  void flip(CellIndex c, int i, const std::array<int, D>& orientations, std::vector<int>& dropped_certs,
            std::array<CellIndex, D>& created);
  // The 3-2 flip of the edge ab of c through its i-th and j-th vertices (3D only): the three top
  // simplices around ab, X_k without the k-th of the ring r0 < r1 < r2 of their other vertices,
  // become r0 r1 r2 a and r0 r1 r2 b (`orientations` and `created` in that order). The triangle
  // r0 r1 r2 must not be in the triangulation; InternalError if ab is not of degree 3. The triangles
  // a b r go, their ids appended to dropped_certs as replace() of X_0, X_1, X_2 in that order would.
  void flip_edge(CellIndex c, int i, int j, const std::array<int, 2>& orientations,
                 std::vector<int>& dropped_certs, std::array<CellIndex, 2>& created);

  std::size_t size() const { return live_count_; }
  bool alive(CellIndex c) const {
    return c >= 0 && static_cast<std::size_t>(c) < cells_.size() && cells_[index(c)].live;
  }
  VertexId vertex(CellIndex c, int i) const { return cells_[index(c)].v[slot(i)]; }
  // Built in registers from the sorted record (Simplex::from_sorted): every certificate and touched
  // face names its simplex this way, and a sort would read back as words what it wrote one by one.
  Simplex top(CellIndex c) const {
    const Cell& cell = cells_[index(c)];
    std::array<VertexId, 4> v{{-1, -1, -1, -1}};
    std::copy(cell.v.begin(), cell.v.end(), v.begin());
    return Simplex::from_sorted(v, top_size);
  }
  // The facet of c without its i-th vertex.
  Simplex facet(CellIndex c, int i) const {
    const Cell& cell = cells_[index(c)];
    std::array<VertexId, 4> v{{-1, -1, -1, -1}};
    for (std::size_t j = 0; j + 1 < top_size; ++j)
      v[j] = cell.v[j < slot(i) ? j : j + 1];
    return Simplex::from_sorted(v, top_size - 1);
  }
  CellIndex neighbor(CellIndex c, int i) const { return cells_[index(c)].n[slot(i)]; }
  // The index of the facet shared with c in c's i-th neighbour.
  int mirror_index(CellIndex c, int i) const;
  // The vertex of c's i-th neighbour that is not on their shared facet.
  VertexId apex_across(CellIndex c, int i) const { return vertex(neighbor(c, i), mirror_index(c, i)); }
  // The position of v among c's sorted vertices, -1 if it is not one.
  int index_of(CellIndex c, VertexId v) const {
    const Cell& cell = cells_[index(c)];
    for (std::size_t i = 0; i < top_size; ++i)
      if (cell.v[i] == v)
        return static_cast<int>(i);
    return -1;
  }
  // Whether c is a living cell with every vertex of s among its vertices.
  bool holds(CellIndex c, const Simplex& s) const {
    if (!alive(c))
      return false;
    for (VertexId x : s)
      if (index_of(c, x) < 0)
        return false;
    return true;
  }
  // The index of the facet f of c: the position of c's one vertex off f (c must hold f).
  int facet_index(CellIndex c, const Simplex& f) const {
    for (int i = 0; i <= D; ++i)
      if (!f.contains(vertex(c, i)))
        return i;
    return -1;
  }
  // The two apices of c's i-th facet (the vertices completing it to its two top simplices): c's own
  // first, then the one across; with each, the orientation of its top simplex. This is all a facet's
  // certificates read of the triangulation (docs/MATH.md §3.2).
  struct Apices {
    std::array<VertexId, 2> v{};
    std::array<signed char, 2> orientation{};
    // The orientation of the top simplex of the facet and apex; 0 when apex is not one.
    int orientation_with(VertexId apex) const {
      return apex == v[0] ? orientation[0] : apex == v[1] ? orientation[1] : 0;
    }
    bool has(VertexId apex) const { return apex == v[0] || apex == v[1]; }
  };
  Apices apices(CellIndex c, int i) const {
    const CellIndex n = neighbor(c, i);
    const Cell& other = cells_[index(n)];
    int j = 0;
    while (other.n[slot(j)] != c)
      ++j;
    return {{vertex(c, i), other.v[slot(j)]}, {cells_[index(c)].orientation, other.orientation}};
  }
  int orientation(CellIndex c) const { return cells_[index(c)].orientation; }
  void set_orientation(CellIndex c, int orientation);
  // The certificate id of c's i-th facet (-1: none), held by both cells of the facet.
  int cert(CellIndex c, int i) const { return cells_[index(c)].cert[slot(i)]; }
  void set_cert(CellIndex c, int i, int id);

  // A cell containing v, no_cell if v is in none.
  CellIndex cell_of(VertexId v) const {
    const std::size_t k = static_cast<std::size_t>(v + 1);
    return k < vertex_cell_.size() ? vertex_cell_[k] : no_cell;
  }
  // The cell whose vertices are t's, no_cell if t is not a top simplex.
  CellIndex find(const Simplex& t) const;
  // A cell containing every vertex of s (s non-empty), no_cell if there is none: s is a face of the
  // triangulation iff there is one.
  CellIndex cell_containing(const Simplex& s) const {
    const VertexId centre = s[s.size() - 1]; // the largest: finite unless s is the infinite vertex
    const CellIndex start = cell_of(centre);
    return start == no_cell ? no_cell : cell_containing_from(start, centre, s);
  }
  // The same by a walk over the star of s's vertex `centre` from a cell `start` that contains it.
  CellIndex cell_containing_from(CellIndex start, VertexId centre, const Simplex& s) const {
    CellIndex found = no_cell;
    walk_star(start, centre, s, [&](CellIndex c) {
      found = c;
      return true;
    });
    return found;
  }
  // The number of cell records, living and free: indices of living cells are below it.
  std::size_t capacity() const { return cells_.size(); }
  // Every facet forgets its certificate id (a frame builds them all again, docs/MATH.md §2.3).
  void clear_certs() {
    for (Cell& cell : cells_)
      cell.cert.fill(-1);
  }
  // Calls f(c) for every cell c containing every vertex of s (s non-empty): one such cell is found by
  // a walk over the star of a vertex of s (a finite one when s has one: the infinite vertex's star
  // is the whole hull), and the others from it (for_each_cell_containing_from). f must not start
  // another walk.
  template <class F> void for_each_cell_containing(const Simplex& s, F&& f) const {
    if (const CellIndex start = cell_containing(s); start != no_cell)
      for_each_cell_containing_from(start, s, f);
  }
  // The same from a cell `start` that contains s: a walk across the facets that contain s, which
  // reaches exactly the cells containing s (their union is a closed ball round s's interior, or its
  // boundary, in a triangulated sphere), without testing any other cell. Round a ridge (an edge in
  // 3D, a vertex in the plane) that walk is a ring, circulated without marks (circulate).
  template <class F> void for_each_cell_containing_from(CellIndex start, const Simplex& s, F&& f) const {
    if (s.size() + 2 == top_size) {
      circulate(start, s, f);
      return;
    }
    walk(
        start, [&](const Cell& cell, std::size_t i) { return !s.contains(cell.v[i]); }, // the facet holds s
        [&](CellIndex c) {
          f(c);
          return false;
        });
  }
  // The finite cofaces of s (one dimension up) from a cell `start` that contains s, sorted, each
  // once: s plus one vertex of each finite cell containing s (a vertex may come from several).
  void finite_cofaces_from(CellIndex start, const Simplex& s, std::vector<Simplex>& out) const {
    out.clear();
    for_each_cell_containing_from(start, s, [&](CellIndex c) {
      const Cell& cell = cells_[index(c)];
      if (cell.v[0] == -1) // sorted: the infinite vertex comes first
        return;
      for (VertexId v : cell.v)
        if (!s.contains(v))
          out.push_back(s.with(v));
    });
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }
  // Calls f(c) for every living cell, in index order.
  template <class F> void for_each_cell(F&& f) const {
    for (std::size_t c = 0; c < cells_.size(); ++c)
      if (cells_[c].live)
        f(static_cast<CellIndex>(c));
  }

  // The first of its invariants that fails, or an empty string: each living cell has sorted distinct
  // vertices, orientation 0 iff infinite, a living neighbour across each facet that shares the facet,
  // names it back and holds the same certificate id; each vertex's cell contains it, and every vertex
  // of a cell has one; the Euler characteristic is that of the sphere S^D (docs/MATH.md §2.1).
  std::string first_violation() const;

private:
  struct Cell {
    std::array<VertexId, top_size> v{};  // sorted ascending
    std::array<CellIndex, top_size> n{}; // n[i]: across the facet without v[i]
    std::array<int, top_size> cert{};    // the certificate id of facet i, -1 if none
    signed char orientation = 0;
    bool live = false;
  };
  // A facet to glue while replacing: its vertices, the cell and facet index it belongs to, and the
  // cell across it outside the replaced ones, or the added facet it pairs with (an index into
  // facets_).
  struct Gluing {
    Simplex facet;
    CellIndex cell = no_cell;
    int index = 0;
    CellIndex outside = no_cell;
    int outside_index = 0;
    int cert = -1;
    int partner = -1;
  };

  // The cell across a facet of a flipped cell, the facet's index in it and the facet's certificate id.
  struct Outside {
    CellIndex cell = no_cell;
    int mirror = 0;
    int cert = -1;
  };

  static std::size_t index(CellIndex c) { return static_cast<std::size_t>(c); }
  static std::size_t slot(int i) { return static_cast<std::size_t>(i); }
  static constexpr std::size_t no_position = static_cast<std::size_t>(-1);
  // The position of c in the `removed` of the replacement being planned, no_position if absent.
  std::size_t removed_position(CellIndex c) const;
  // Calls f(c) for the cells c of the star of s's vertex `centre`, from the cell `start` holding
  // it, that contain s, until f returns true; returns whether it did.
  template <class F> bool walk_star(CellIndex start, VertexId centre, const Simplex& s, F&& f) const;
  // Calls visit(c) on each cell c reached from `start` across the facets crosses(cell, i) lets it
  // cross (the cell's i-th), each once, until visit returns true; returns whether it did. Cells
  // reached are marked with the walk's epoch.
  template <class Crosses, class Visit> bool walk(CellIndex start, Crosses&& crosses, Visit&& visit) const;
  // for_each_cell_containing_from round a ridge s (an edge in 3D, a vertex in the plane): the cells
  // holding it form a cycle, each with exactly two facets holding s, entered through one and left
  // through the other, so the walk needs no marks and no stack. It visits them in the walk's order:
  // from start across the later of its two facets, round to the cell across the earlier.
  template <class F> void circulate(CellIndex start, const Simplex& s, F&& f) const {
    CellIndex previous = start, c = start;
    std::size_t visited = 0;
    do {
      f(c);
      const Cell& cell = cells_[index(c)];
      std::array<CellIndex, top_size> across{};
      std::size_t k = 0;
      for (std::size_t i = 0; i < top_size; ++i)
        if (!s.contains(cell.v[i]))
          across[k++] = cell.n[i];
      if (k != 2 || ++visited > cells_.size())
        throw_broken_ring(start, s);
      const CellIndex next = c == start ? across[1] : across[0] == previous ? across[1] : across[0];
      previous = c;
      c = next;
    } while (c != start);
  }
  [[noreturn]] void throw_broken_ring(CellIndex start, const Simplex& s) const;
  // Starts a walk: every cell has a mark, and none is the new epoch.
  void next_epoch() const {
    if (marks_.size() < cells_.size())
      marks_.resize(cells_.size(), 0);
    if (++epoch_ == 0) { // wrapped: no mark may look current
      std::fill(marks_.begin(), marks_.end(), 0);
      epoch_ = 1;
    }
  }
  // The index of the facet of e across which c lies; InternalError if c is not e's neighbour.
  int back_index(CellIndex e, CellIndex c) const;
  CellIndex allocate();
  void point_vertices_at(CellIndex c);
  // Fills facets_/boundary_ for replace() and checks that the added simplices close the hole exactly;
  // changes nothing.
  void plan_gluing(const std::vector<CellIndex>& removed, const std::vector<NewTop>& added);

  std::vector<Cell> cells_;
  std::vector<CellIndex> free_;
  std::size_t live_count_ = 0;
  // A cell containing each vertex, indexed by vertex id + 1 (the infinite vertex is -1).
  std::vector<CellIndex> vertex_cell_;
  // Scratch of replace() and of the star walks, kept to avoid an allocation per flip.
  std::vector<Gluing> facets_, boundary_;
  std::vector<std::pair<CellIndex, std::size_t>> order_; // the removed cells and their positions
  std::vector<VertexId> lost_;                           // the removed cells' vertices
  std::vector<CellIndex> made_;                          // the added cells
  // The star walks of const look-ups mark cells: one walk at a time (the engine is single-threaded).
  // marks_[c]: the last walk that reached cell c, apart from the cells so that a walk reads only
  // the cells it enters and the marks of their neighbours.
  mutable std::vector<std::uint32_t> marks_;
  mutable std::vector<CellIndex> walk_;
  mutable std::uint32_t epoch_ = 0;
};

template <int D>
template <class F>
bool CellTriangulation<D>::walk_star(CellIndex start, VertexId centre, const Simplex& s, F&& f) const {
  return walk(
      start,
      [&](const Cell& cell, std::size_t i) { return cell.v[i] != centre; }, // the facet holds the centre
      [&](CellIndex c) { return holds(c, s) && f(c); });
}

template <int D>
template <class Crosses, class Visit>
bool CellTriangulation<D>::walk(CellIndex start, Crosses&& crosses, Visit&& visit) const {
  next_epoch();
  walk_.assign(1, start);
  marks_[index(start)] = epoch_;
  while (!walk_.empty()) {
    const CellIndex c = walk_.back();
    walk_.pop_back();
    if (visit(c))
      return true;
    const Cell& cell = cells_[index(c)];
    for (std::size_t i = 0; i < top_size; ++i) {
      if (!crosses(cell, i))
        continue;
      std::uint32_t& mark = marks_[index(cell.n[i])];
      if (mark != epoch_) {
        mark = epoch_;
        walk_.push_back(cell.n[i]);
      }
    }
  }
  return false;
}

extern template class CellTriangulation<2>;
extern template class CellTriangulation<3>;

} // namespace medusa::kinetic::detail
