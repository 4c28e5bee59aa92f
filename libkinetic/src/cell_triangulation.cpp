#include "cell_triangulation.h"

#include "kinetic_traits.h"
#include "medusa/core/error.h"

#include <algorithm>
#include <limits>
#include <set>
#include <sstream>
#include <utility>

namespace medusa::kinetic::detail {

namespace {

// Past this many facets a change's scratch is not kept for the next one.
constexpr std::size_t max_kept_scratch = 4096;

[[noreturn]] void broken(const std::string& what) { throw InternalError("cell triangulation: " + what); }

template <class T> std::string text(const T& x) {
  std::ostringstream os;
  os << x;
  return os.str();
}

} // namespace

template <int D> void CellTriangulation<D>::clear() {
  cells_.clear();
  free_.clear();
  vertex_cell_.clear();
  live_count_ = 0;
}

template <int D> int CellTriangulation<D>::mirror_index(CellIndex c, int i) const {
  return back_index(neighbor(c, i), c);
}

template <int D> int CellTriangulation<D>::back_index(CellIndex e, CellIndex c) const {
  const Cell& other = cells_[index(e)];
  for (std::size_t j = 0; j < top_size; ++j)
    if (other.n[j] == c)
      return static_cast<int>(j);
  broken("cell " + std::to_string(c) + " is not its neighbour's neighbour");
}

template <int D> void CellTriangulation<D>::throw_broken_ring(CellIndex start, const Simplex& s) const {
  std::ostringstream os;
  os << "the cells holding " << s << " from cell " << start << " do not form a ring";
  broken(os.str());
}

template <int D> void CellTriangulation<D>::set_orientation(CellIndex c, int orientation) {
  cells_[index(c)].orientation = static_cast<signed char>(orientation);
}

template <int D> void CellTriangulation<D>::set_cert(CellIndex c, int i, int id) {
  const int j = mirror_index(c, i);
  cells_[index(c)].cert[slot(i)] = id;
  cells_[index(neighbor(c, i))].cert[slot(j)] = id;
}

template <int D> CellIndex CellTriangulation<D>::find(const Simplex& t) const {
  return t.size() == top_size ? cell_containing(t) : no_cell;
}

template <int D> std::size_t CellTriangulation<D>::removed_position(CellIndex c) const {
  const auto it = std::lower_bound(order_.begin(), order_.end(), std::make_pair(c, std::size_t{0}));
  return it != order_.end() && it->first == c ? it->second : no_position;
}

template <int D> CellIndex CellTriangulation<D>::allocate() {
  if (!free_.empty()) {
    const CellIndex c = free_.back();
    free_.pop_back();
    return c;
  }
  if (cells_.size() >= static_cast<std::size_t>(std::numeric_limits<CellIndex>::max()))
    broken("more than 2^31 cells");
  cells_.emplace_back();
  return static_cast<CellIndex>(cells_.size() - 1);
}

template <int D> void CellTriangulation<D>::point_vertices_at(CellIndex c) {
  for (VertexId v : cells_[index(c)].v) {
    const std::size_t k = static_cast<std::size_t>(v + 1);
    if (k >= vertex_cell_.size())
      vertex_cell_.resize(k + 1, no_cell);
    vertex_cell_[k] = c;
  }
}

template <int D>
void CellTriangulation<D>::plan_gluing(const std::vector<CellIndex>& removed,
                                       const std::vector<NewTop>& added) {
  for (const NewTop& t : added)
    if (t.top.size() != top_size)
      broken("simplex " + text(t.top) + " is not a top simplex");
  order_.clear();
  for (std::size_t k = 0; k < removed.size(); ++k)
    order_.emplace_back(removed[k], k);
  std::sort(order_.begin(), order_.end());
  for (std::size_t k = 0; k < order_.size(); ++k)
    if (!alive(order_[k].first) || (k > 0 && order_[k].first == order_[k - 1].first))
      broken("cell " + std::to_string(order_[k].first) + " removed twice or not alive");

  boundary_.clear();
  for (CellIndex r : removed) {
    const Cell& cell = cells_[index(r)];
    for (std::size_t i = 0; i < top_size; ++i)
      if (removed_position(cell.n[i]) == no_position) {
        Gluing g;
        g.facet = facet(r, static_cast<int>(i));
        g.outside = cell.n[i];
        g.outside_index = mirror_index(r, static_cast<int>(i));
        g.cert = cell.cert[i];
        boundary_.push_back(g);
      }
  }
  facets_.clear();
  facets_.reserve(added.size() * top_size); // the first triangulation adds them all: no doubling
  for (std::size_t k = 0; k < added.size(); ++k)
    for (std::size_t i = 0; i < top_size; ++i) {
      Gluing g;
      g.facet = added[k].top.facet(i);
      g.cell = static_cast<CellIndex>(k); // the position in `added` until the cells exist
      g.index = static_cast<int>(i);
      facets_.push_back(g);
    }
  // Each added facet pairs with another added one or with one boundary facet, never both, and each
  // boundary facet with one added facet: matched by sorting both lists. (Flips do not come here:
  // flip() and flip_edge() glue by index.)
  const auto match = [&](Gluing& g, const Gluing* outside, std::size_t partner, std::size_t count) {
    if (count != 1)
      broken("facet " + text(g.facet) + " would have " + std::to_string(count + 1) + " top simplices");
    if (outside != nullptr) {
      g.outside = outside->outside;
      g.outside_index = outside->outside_index;
      g.cert = outside->cert;
    } else {
      g.partner = static_cast<int>(partner);
    }
  };
  const auto uncovered = [&](const Gluing& b) {
    broken("boundary facet " + text(b.facet) + " is not covered by the added simplices");
  };
  const auto by_facet = [](const Gluing& a, const Gluing& b) { return a.facet < b.facet; };
  std::sort(boundary_.begin(), boundary_.end(), by_facet);
  std::sort(facets_.begin(), facets_.end(), by_facet);
  for (std::size_t k = 1; k < boundary_.size(); ++k)
    if (boundary_[k].facet == boundary_[k - 1].facet)
      broken("facet " + text(boundary_[k].facet) + " is twice on the boundary of the removed cells");
  std::size_t b = 0;
  for (std::size_t k = 0; k < facets_.size();) {
    std::size_t e = k + 1;
    while (e < facets_.size() && facets_[e].facet == facets_[k].facet)
      ++e;
    if (b < boundary_.size() && boundary_[b].facet < facets_[k].facet)
      uncovered(boundary_[b]);
    const bool outside = b < boundary_.size() && boundary_[b].facet == facets_[k].facet;
    const std::size_t count = e - k - 1 + (outside ? 1 : 0);
    match(facets_[k], outside ? &boundary_[b] : nullptr, k + 1, count);
    if (!outside)
      match(facets_[k + 1], nullptr, k, count);
    b += outside ? 1 : 0;
    k = e;
  }
  if (b < boundary_.size())
    uncovered(boundary_[b]);
}

template <int D>
void CellTriangulation<D>::replace(const std::vector<CellIndex>& removed, const std::vector<NewTop>& added,
                                   std::vector<int>& dropped_certs, std::vector<CellIndex>* created) {
  plan_gluing(removed, added);
  // Facets inside the removed cells go with the later of their two cells, in the order of `removed`.
  for (std::size_t k = 0; k < removed.size(); ++k) {
    const Cell& cell = cells_[index(removed[k])];
    for (std::size_t i = 0; i < top_size; ++i)
      if (removed_position(cell.n[i]) < k && cell.cert[i] >= 0)
        dropped_certs.push_back(cell.cert[i]);
  }
  lost_.clear();
  for (CellIndex r : removed) {
    lost_.insert(lost_.end(), cells_[index(r)].v.begin(), cells_[index(r)].v.end());
    cells_[index(r)].live = false;
    free_.push_back(r);
  }
  live_count_ -= removed.size();

  std::vector<CellIndex>& made = made_;
  made.resize(added.size());
  for (std::size_t k = 0; k < added.size(); ++k) {
    made[k] = allocate();
    Cell& cell = cells_[index(made[k])];
    cell = Cell{};
    std::copy(added[k].top.begin(), added[k].top.end(), cell.v.begin());
    cell.orientation = static_cast<signed char>(added[k].orientation);
    cell.live = true;
    point_vertices_at(made[k]);
  }
  live_count_ += added.size();
  for (std::size_t k = 0; k < facets_.size(); ++k) {
    const Gluing& g = facets_[k];
    Cell& cell = cells_[index(made[index(g.cell)])];
    if (g.outside != no_cell) {
      cell.n[slot(g.index)] = g.outside;
      cell.cert[slot(g.index)] = g.cert;
      cells_[index(g.outside)].n[slot(g.outside_index)] = made[index(g.cell)];
    } else if (static_cast<std::size_t>(g.partner) > k) {
      const Gluing& h = facets_[static_cast<std::size_t>(g.partner)];
      Cell& other = cells_[index(made[index(h.cell)])];
      cell.n[slot(g.index)] = made[index(h.cell)];
      other.n[slot(h.index)] = made[index(g.cell)];
      cell.cert[slot(g.index)] = other.cert[slot(h.index)] = -1;
    }
  }
  // A vertex of a removed cell that no added simplex holds keeps a cell of the boundary, or none.
  for (VertexId v : lost_) {
    const CellIndex c = vertex_cell_[static_cast<std::size_t>(v + 1)];
    if (alive(c) && index_of(c, v) >= 0)
      continue;
    CellIndex keep = no_cell;
    for (const Gluing& g : boundary_)
      if (keep == no_cell && index_of(g.outside, v) >= 0)
        keep = g.outside;
    vertex_cell_[static_cast<std::size_t>(v + 1)] = keep;
  }
  if (created != nullptr)
    created->assign(made.begin(), made.end());
  // The scratch of a static change is as large as the change (a first triangulation of a million
  // cells: a gigabyte): let go rather than held for the rest of the run.
  if (facets_.capacity() > max_kept_scratch) {
    std::vector<Gluing>().swap(facets_);
    std::vector<Gluing>().swap(boundary_);
    std::vector<std::pair<CellIndex, std::size_t>>().swap(order_);
    std::vector<VertexId>().swap(lost_);
    std::vector<CellIndex>().swap(made_);
  }
}

template <int D>
void CellTriangulation<D>::flip(CellIndex c, int i, const std::array<int, D>& orientations,
                                std::vector<int>& dropped_certs, std::array<CellIndex, D>& created) {
  const CellIndex nb = neighbor(c, i);
  const Cell old_c = cells_[index(c)], old_n = cells_[index(nb)];
  const VertexId p = old_c.v[slot(i)], q = old_n.v[slot(mirror_index(c, i))];
  std::array<VertexId, D> f{};
  for (std::size_t k = 0, m = 0; k < top_size; ++k)
    if (k != slot(i))
      f[m++] = old_c.v[k];
  // The cells outside across (f - x) + p and (f - x) + q.
  const auto outside = [&](const Cell& from, CellIndex from_index, VertexId x) {
    const std::size_t k = slot(index_of(from_index, x));
    return Outside{from.n[k], back_index(from.n[k], from_index), from.cert[k]};
  };
  std::array<Outside, D> across_p{}, across_q{};
  for (std::size_t k = 0; k < D; ++k) {
    across_p[k] = outside(old_n, nb, f[k]); // (f - x) + q, opposite p in the new cell
    across_q[k] = outside(old_c, c, f[k]);  // (f - x) + p, opposite q
  }
  if (old_c.cert[slot(i)] >= 0)
    dropped_certs.push_back(old_c.cert[slot(i)]);
  created[0] = c;
  created[1] = nb;
  if constexpr (D == 3) {
    created[2] = allocate();
    ++live_count_;
  }
  for (std::size_t k = 0; k < D; ++k) {
    Cell& t = cells_[index(created[k])];
    t = Cell{};
    std::size_t n = 0;
    for (std::size_t m = 0; m < D; ++m)
      if (m != k)
        t.v[n++] = f[m];
    t.v[n++] = p;
    t.v[n++] = q;
    std::sort(t.v.begin(), t.v.end());
    t.orientation = static_cast<signed char>(orientations[k]);
    t.live = true;
    for (std::size_t s = 0; s < top_size; ++s) {
      const VertexId w = t.v[s];
      if (w == p || w == q) {
        const Outside& o = w == p ? across_p[k] : across_q[k];
        t.n[s] = o.cell;
        t.cert[s] = o.cert;
        cells_[index(o.cell)].n[slot(o.mirror)] = created[k];
      } else {
        t.n[s] = created[static_cast<std::size_t>(std::find(f.begin(), f.end(), w) - f.begin())];
        t.cert[s] = -1;
      }
    }
    point_vertices_at(created[k]);
  }
}

template <int D>
void CellTriangulation<D>::flip_edge(CellIndex c, int i, int j, const std::array<int, 2>& orientations,
                                     std::vector<int>& dropped_certs, std::array<CellIndex, 2>& created) {
  if constexpr (D != 3) {
    broken("a 3-2 flip in a planar triangulation");
  } else {
    const VertexId a = vertex(c, i), b = vertex(c, j);
    // c's other two vertices u, w; the neighbours across the facets without them share the third.
    std::array<int, 2> other{};
    for (int k = 0, m = 0; k < 4; ++k)
      if (k != i && k != j)
        other[static_cast<std::size_t>(m++)] = k;
    const CellIndex without_u = neighbor(c, other[0]), without_w = neighbor(c, other[1]);
    const VertexId u = vertex(c, other[0]), w = vertex(c, other[1]);
    const VertexId z = apex_across(c, other[0]);
    if (z != apex_across(c, other[1]) || neighbor(without_u, index_of(without_u, w)) != without_w)
      broken("the edge " + text(Simplex{a, b}) + " of a 3-2 flip is not of degree 3");
    std::array<VertexId, 3> ring{u, w, z};
    std::sort(ring.begin(), ring.end());
    // X_k, the cell without ring[k].
    std::array<CellIndex, 3> x{};
    for (std::size_t k = 0; k < 3; ++k)
      x[k] = ring[k] == z ? c : ring[k] == u ? without_u : without_w;
    // Across the facet of X_k without `apex`: the facet (ring - r_k) + the other of a, b.
    const auto outside = [&](std::size_t k, VertexId apex) {
      const Cell& from = cells_[index(x[k])];
      const std::size_t s = slot(index_of(x[k], apex));
      return Outside{from.n[s], back_index(from.n[s], x[k]), from.cert[s]};
    };
    std::array<Outside, 3> for_a{}, for_b{}; // the new cell with a takes X_k's facet without b
    for (std::size_t k = 0; k < 3; ++k) {
      for_a[k] = outside(k, b);
      for_b[k] = outside(k, a);
    }
    for (std::size_t k = 1; k < 3; ++k)
      for (std::size_t s = 0; s < top_size; ++s) {
        const Cell& from = cells_[index(x[k])];
        if ((from.n[s] == x[0] || (k == 2 && from.n[s] == x[1])) && from.cert[s] >= 0)
          dropped_certs.push_back(from.cert[s]);
      }
    created = {x[0], x[1]};
    cells_[index(x[2])].live = false;
    free_.push_back(x[2]);
    --live_count_;
    for (std::size_t t = 0; t < 2; ++t) {
      const VertexId apex = t == 0 ? a : b;
      const std::array<Outside, 3>& across = t == 0 ? for_a : for_b;
      Cell& cell = cells_[index(created[t])];
      cell = Cell{};
      cell.v = {ring[0], ring[1], ring[2], apex};
      std::sort(cell.v.begin(), cell.v.end());
      cell.orientation = static_cast<signed char>(orientations[t]);
      cell.live = true;
      for (std::size_t s = 0; s < top_size; ++s) {
        const VertexId v = cell.v[s];
        if (v == apex) {
          cell.n[s] = created[1 - t];
          cell.cert[s] = -1;
        } else {
          const Outside& o =
              across[static_cast<std::size_t>(std::find(ring.begin(), ring.end(), v) - ring.begin())];
          cell.n[s] = o.cell;
          cell.cert[s] = o.cert;
          cells_[index(o.cell)].n[slot(o.mirror)] = created[t];
        }
      }
      point_vertices_at(created[t]);
    }
  }
}

template <int D> void CellTriangulation<D>::assign(const std::vector<NewTop>& tops) {
  CellTriangulation<D> fresh;
  std::vector<int> none;
  fresh.replace({}, tops, none);
  *this = std::move(fresh);
}

template <int D> std::string CellTriangulation<D>::first_violation() const {
  std::set<Simplex> faces[top_size];
  for (std::size_t c = 0; c < cells_.size(); ++c) {
    const Cell& cell = cells_[c];
    if (!cell.live)
      continue;
    const CellIndex ci = static_cast<CellIndex>(c);
    const Simplex t = top(ci);
    if (!std::is_sorted(cell.v.begin(), cell.v.end()) ||
        std::adjacent_find(cell.v.begin(), cell.v.end()) != cell.v.end())
      return "cell " + std::to_string(c) + " has vertices " + text(t) + ", not sorted and distinct";
    if ((cell.orientation == 0) != (cell.v[0] == -1) || cell.orientation < -1 || cell.orientation > 1)
      return "top simplex " + text(t) + " has orientation " + std::to_string(cell.orientation);
    for (std::size_t i = 0; i < top_size; ++i) {
      const CellIndex m = cell.n[i];
      if (!alive(m))
        return "top simplex " + text(t) + " has no living neighbour across facet " + std::to_string(i);
      const Cell& other = cells_[index(m)];
      int back = -1;
      for (std::size_t j = 0; j < top_size; ++j)
        if (other.n[j] == ci)
          back = back == -1 ? static_cast<int>(j) : -2;
      if (back < 0)
        return "top simplex " + text(t) + " is not named back once by its neighbour " + text(top(m));
      if (top(m).facet(slot(back)) != t.facet(i))
        return "top simplices " + text(t) + " and " + text(top(m)) +
               " are neighbours without sharing a facet";
      if (other.cert[slot(back)] != cell.cert[i])
        return "facet " + text(t.facet(i)) + " holds two certificate ids";
      const CellIndex vc = cell_of(cell.v[i]);
      if (!alive(vc) || index_of(vc, cell.v[i]) < 0)
        return "vertex " + std::to_string(cell.v[i]) + " has no cell containing it";
    }
    // Every face, for the Euler characteristic.
    for (unsigned mask = 1; mask < (1u << top_size); ++mask) {
      std::array<VertexId, top_size> w{};
      std::size_t n = 0;
      for (std::size_t i = 0; i < top_size; ++i)
        if (mask & (1u << i))
          w[n++] = cell.v[i];
      faces[n - 1].insert(Simplex::from_range(w.begin(), w.begin() + static_cast<std::ptrdiff_t>(n)));
    }
  }
  for (std::size_t k = 0; k < vertex_cell_.size(); ++k) {
    const CellIndex c = vertex_cell_[k];
    if (c != no_cell && (!alive(c) || index_of(c, static_cast<VertexId>(k) - 1) < 0))
      return "vertex " + std::to_string(static_cast<long>(k) - 1) + " names cell " + std::to_string(c) +
             ", which does not contain it";
  }
  if (live_count_ == 0)
    return "";
  if (!KineticTraits<D>::euler_characteristic_holds(faces[0].size(), faces[1].size(), faces[2].size(),
                                                    faces[D].size()))
    return "the Euler characteristic is not that of the sphere S^" + std::to_string(D);
  return "";
}

template class CellTriangulation<2>;
template class CellTriangulation<3>;

} // namespace medusa::kinetic::detail
