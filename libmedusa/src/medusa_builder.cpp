#include "medusa/medusa/medusa_builder.h"

#include "cell_ids.h"
#include "medusa/core/error.h"
#include "vertex_text.h"

#include <algorithm>
#include <array>
#include <string>

namespace medusa {

namespace {

using kinetic::Simplex;

std::string where(const VirtualTime& t) {
  return "batch " + std::to_string(t.batch) + " rank " + std::to_string(t.rank);
}

std::vector<VertexId> vertices_of(const Simplex& s) { return std::vector<VertexId>(s.begin(), s.end()); }

// sigma + {p}, sorted.
std::vector<VertexId> join(const Simplex& sigma, VertexId p) {
  std::vector<VertexId> v = vertices_of(sigma);
  v.insert(std::upper_bound(v.begin(), v.end(), p), p);
  return v;
}

// Increasing dimension, then lexicographic: the order of docs/MATH.md §6.4 for births and instant cells.
bool canonical_less(const std::vector<VertexId>& a, const std::vector<VertexId>& b) {
  if (a.size() != b.size())
    return a.size() < b.size();
  return a < b;
}

// A facet of a new cell that is neither in K nor among the step's instant cells: the stream is
// inconsistent.
template <class Facet, class Of>
[[noreturn]] void throw_missing_facet(const Facet& facet, const Of& of, const VirtualTime& when) {
  throw InternalError("medusa builder: facet " + vertex_text(facet) + " of " + vertex_text(of) +
                      " is not present at " + where(when));
}

VirtualTime virtual_time(const kinetic::EventTime& t, std::size_t rank) {
  VirtualTime v;
  v.batch = static_cast<std::uint32_t>(t.batch);
  v.rank = static_cast<std::uint32_t>(rank);
  v.time = t.time;
  return v;
}

} // namespace

void MedusaBuilder::set_run(const RunInfo& info, const kinetic::Trajectories& input) {
  sink_.run(info, input);
}

void MedusaBuilder::check_order(const kinetic::EventTime& time, const char* what) {
  if (!started_)
    throw InternalError(std::string("medusa builder: ") + what + " before the initial complex");
  if (finished_)
    throw InternalError(std::string("medusa builder: ") + what + " after finish");
  if (time.batch <= last_batch_)
    throw InternalError(std::string("medusa builder: ") + what + " at batch " + std::to_string(time.batch) +
                        " does not follow batch " + std::to_string(last_batch_));
  if (time.batch > max_batch)
    throw InputError("the run has more than " + std::to_string(max_batch) +
                     " event batches, the most a medusa's virtual times hold");
}

CellFacets MedusaBuilder::facets_of(const std::vector<VertexId>& vertices, const InstantMap& instant,
                                    const VirtualTime& when) const {
  CellFacets facets;
  if (vertices.size() < 2)
    return facets;
  facets.reserve(vertices.size());
  std::vector<VertexId> facet(vertices.size() - 1);
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    std::copy(vertices.begin(), vertices.begin() + static_cast<std::ptrdiff_t>(i), facet.begin());
    std::copy(vertices.begin() + static_cast<std::ptrdiff_t>(i) + 1, vertices.end(),
              facet.begin() + static_cast<std::ptrdiff_t>(i));
    if (facet.size() <= 4) {
      auto it = active_.find(Simplex::from_range(facet.begin(), facet.end()));
      if (it != active_.end()) {
        facets.push_back(static_cast<std::uint32_t>(it->second.id));
        continue;
      }
    }
    auto it = instant.find(facet);
    if (it == instant.end())
      throw_missing_facet(facet, vertices, when);
    facets.push_back(static_cast<std::uint32_t>(it->second));
  }
  return facets;
}

void MedusaBuilder::birth(const Simplex& s, const VirtualTime& when) {
  if (active_.count(s))
    throw InternalError("medusa builder: simplex " + vertex_text(s) + " enters K at " + where(when) +
                        " but is already in K");
  // Every facet is checked, and the id taken, before any count changes; the records stay where they are until
  // s is inserted (the table may then move them).
  std::array<Active*, 4> facets{};
  const std::size_t n = s.size() > 1 ? s.size() : 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Simplex f = s.facet(i);
    auto it = active_.find(f);
    if (it == active_.end())
      throw_missing_facet(f, s, when);
    facets[i] = &it->second;
  }
  Active a;
  a.id = static_cast<std::uint32_t>(take_cell_id(next_id_));
  a.birth = when;
  for (std::size_t i = 0; i < n; ++i)
    ++facets[i]->cofaces;
  active_.try_emplace(s).first->second = a;
}

void MedusaBuilder::death(const Simplex& s, const VirtualTime& when) {
  auto it = active_.find(s);
  if (it == active_.end())
    throw InternalError("medusa builder: simplex " + vertex_text(s) + " leaves K at " + where(when) +
                        " but is not in K");
  if (it->second.cofaces != 0)
    throw InternalError("medusa builder: simplex " + vertex_text(s) + " leaves K at " + where(when) +
                        " while a coface stays");
  Cell c;
  c.id = it->second.id;
  c.vertices.assign(s.begin(), s.end());
  c.birth = it->second.birth;
  c.death = when;
  c.kind = CellKind::regular;
  active_.erase(it);
  // The facets are active: each still counts s among its cofaces (birth).
  if (s.size() > 1) {
    c.facets.reserve(s.size());
    for (std::size_t i = 0; i < s.size(); ++i) {
      Active& f = active_.find(s.facet(i))->second;
      c.facets.push_back(f.id);
      --f.cofaces;
    }
  }
  sink_.cell(c);
}

void MedusaBuilder::initial(const kinetic::EventTime& t0, const std::vector<Simplex>& complex) {
  if (started_)
    throw InternalError("medusa builder: second initial complex");
  started_ = true;
  last_batch_ = t0.batch;
  BatchRecord b;
  b.batch = t0.batch;
  b.slab = t0.slab;
  b.u = t0.u;
  b.time = t0.time;
  b.at_frame = t0.at_frame;
  b.ranks = 0;
  sink_.batch(b);
  // docs/MATH.md §6.2: the initial complex is born at (0, 0).
  std::vector<Simplex> sorted = complex;
  std::sort(sorted.begin(), sorted.end());
  active_.reserve(sorted.size());
  const VirtualTime when = virtual_time(t0, 0);
  for (const Simplex& s : sorted)
    birth(s, when);
}

void MedusaBuilder::step(const kinetic::Step& st, const VirtualTime& when) {
  // docs/MATH.md §6.4: births, then instant cells, then deaths; births and instant cells in increasing
  // dimension because their facets may be born (or be instant) at the same rank.
  std::vector<Simplex> entered = st.entered;
  std::sort(entered.begin(), entered.end());
  for (const Simplex& s : entered)
    birth(s, when);

  std::map<std::vector<VertexId>, CellKind> instants;
  auto add = [&](std::vector<VertexId> v, CellKind kind) { instants.emplace(std::move(v), kind); };
  // Flip (docs/MATH.md §6.3): the simplex of the flip group (the 4-simplex of a 2-3 / 3-2 flip, the
  // 3-simplex of a planar 2-2 flip) when R_S <= rho and the old top simplices are in L_{r-1};
  // libkinetic decides this and reports it as in_alpha.
  if (st.flip && st.flip->in_alpha) {
    std::vector<VertexId> v(st.flip->vertices.begin(), st.flip->vertices.end());
    std::sort(v.begin(), v.end());
    add(std::move(v), CellKind::flip);
  }
  // Joins (docs/MATH.md §6.3): sigma + {p} for sigma leaving K at an insertion of p, entering at a deletion.
  if (st.kind == kinetic::StepKind::insertion || st.kind == kinetic::StepKind::deletion) {
    const auto& sigmas = st.kind == kinetic::StepKind::insertion ? st.left : st.entered;
    for (const Simplex& s : sigmas)
      if (!s.contains(st.vertex))
        add(join(s, st.vertex), CellKind::join);
  }
  // Degenerate groups (docs/MATH.md §6.3): every subset in neither L_{r-1} nor L_r. Here the active map
  // holds exactly L_{r-1} u L_r (births done, deaths not yet).
  for (const kinetic::DegenerateGroup& g : st.groups) {
    std::vector<VertexId> gv = g.vertices;
    std::sort(gv.begin(), gv.end());
    if (gv.size() > 20)
      throw InternalError("medusa builder: degenerate group " + vertex_text(gv) + " at " + where(when) +
                          " has more than 20 vertices");
    const std::uint32_t subsets = 1u << gv.size();
    for (std::uint32_t mask = 1; mask < subsets; ++mask) {
      std::vector<VertexId> v;
      for (std::size_t i = 0; i < gv.size(); ++i)
        if (mask & (1u << i))
          v.push_back(gv[i]);
      if (v.size() <= 4 && active_.count(Simplex::from_range(v.begin(), v.end())))
        continue;
      add(std::move(v), CellKind::repair);
    }
  }
  std::vector<std::pair<std::vector<VertexId>, CellKind>> ordered(instants.begin(), instants.end());
  std::sort(ordered.begin(), ordered.end(),
            [](const auto& a, const auto& b) { return canonical_less(a.first, b.first); });
  InstantMap instant_ids;
  for (auto& [vertices, kind] : ordered) {
    if (vertices.size() <= 4 && active_.count(Simplex::from_range(vertices.begin(), vertices.end())))
      throw InternalError("medusa builder: instant cell " + vertex_text(vertices) + " at " + where(when) +
                          " is also a simplex of K");
    Cell c;
    c.facets = facets_of(vertices, instant_ids, when);
    c.id = take_cell_id(next_id_);
    c.vertices = vertices;
    c.birth = when;
    c.death = when;
    c.kind = kind;
    instant_ids.emplace(vertices, c.id);
    sink_.cell(c);
  }

  // Deaths in decreasing dimension, so that no simplex leaves while a coface is still active.
  std::vector<Simplex> left = st.left;
  std::sort(left.begin(), left.end());
  for (auto it = left.rbegin(); it != left.rend(); ++it)
    death(*it, when);
}

void MedusaBuilder::batch(const kinetic::EventTime& time, const std::vector<kinetic::Step>& steps) {
  check_order(time, "batch");
  last_batch_ = time.batch;
  std::size_t last_rank = 0;
  for (const kinetic::Step& st : steps) {
    if (st.rank <= last_rank)
      throw InternalError("medusa builder: step rank " + std::to_string(st.rank) + " at batch " +
                          std::to_string(time.batch) + " does not follow rank " + std::to_string(last_rank));
    last_rank = st.rank;
    step(st, virtual_time(time, st.rank));
  }
  BatchRecord b;
  b.batch = time.batch;
  b.slab = time.slab;
  b.u = time.u;
  b.time = time.time;
  b.at_frame = time.at_frame;
  b.ranks = static_cast<std::uint32_t>(last_rank);
  sink_.batch(b);
}

void MedusaBuilder::frame(std::size_t k, const kinetic::EventTime& time) {
  if (!started_ || finished_)
    throw InternalError("medusa builder: frame " + std::to_string(k) + " outside the run");
  FrameRecord f;
  f.frame = k;
  f.batch = time.batch;
  f.time = time.time;
  sink_.frame(f);
}

void MedusaBuilder::finish(const kinetic::EventTime& t_end) {
  check_order(t_end, "finish");
  finished_ = true;
  // docs/MATH.md §6.2: every active cell dies at the final virtual time (t_end, rank 0), so that the query
  // K(t_end-) of 6.6 (rank 0, closed right end) returns them.
  const VirtualTime end = virtual_time(t_end, 0);
  std::vector<Simplex> simplices;
  simplices.reserve(active_.size());
  for (const auto& [s, a] : active_)
    simplices.push_back(s);
  std::sort(simplices.begin(), simplices.end());
  for (auto it = simplices.rbegin(); it != simplices.rend(); ++it)
    death(*it, end);
  sink_.finish(end);
}

} // namespace medusa
