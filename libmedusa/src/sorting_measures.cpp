#include "medusa/medusa/sorting_measures.h"

#include "medusa/core/error.h"
#include "medusa/medusa/complex_index.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <unordered_map>

namespace medusa {
namespace {

__extension__ typedef unsigned __int128 Wide;

constexpr std::size_t poll_every = 4096;

void call(const std::function<void()>& poll) {
  if (poll)
    poll();
}

// The slice interval [first, end) of a cell: the slices of samples s (K(b_s+), then K(t_end-)) that
// contain it, i.e. birth batch < born_before(s) and death batch >= dies_from(s) (docs/MATH.md §6.6).
struct SliceRange {
  std::size_t first = 0;
  std::size_t end = 0;
};

class Slices {
public:
  explicit Slices(const Medusa& m) {
    for (const BatchRecord& b : m.batches)
      bounds_.push_back(b.batch + 1);
    bounds_.push_back(m.end.batch);
    for (std::size_t s = 1; s < bounds_.size(); ++s)
      if (bounds_[s] < bounds_[s - 1])
        throw InternalError("sorting measures: batches out of order");
  }
  std::size_t size() const { return bounds_.size(); }
  SliceRange of(const Cell& c) const {
    if (c.birth.batch >= c.death.batch)
      return {};
    const auto first = std::upper_bound(bounds_.begin(), bounds_.end(), c.birth.batch) - bounds_.begin();
    const auto end = std::upper_bound(bounds_.begin(), bounds_.end(), c.death.batch) - bounds_.begin();
    return {static_cast<std::size_t>(first), static_cast<std::size_t>(end)};
  }

private:
  std::vector<std::uint64_t> bounds_; // born_before = dies_from of each slice
};

// Union-find with union by size and no path compression, so that unions can be undone in reverse
// order (offline dynamic connectivity). Tracks the number of unions and the largest set per group
// (the whole complex, or one cell type).
class RollbackUnionFind {
public:
  RollbackUnionFind(std::size_t n, std::size_t groups)
      : parent_(n), size_(n, 1), unions_(groups, 0), largest_(groups, 1) {
    std::iota(parent_.begin(), parent_.end(), std::size_t{0});
  }
  std::size_t find(std::size_t x) const {
    while (parent_[x] != x)
      x = parent_[x];
    return x;
  }
  void unite(std::size_t a, std::size_t b, std::size_t group) {
    a = find(a);
    b = find(b);
    if (a == b)
      return;
    if (size_[a] < size_[b])
      std::swap(a, b);
    history_.push_back({b, group, largest_[group]});
    parent_[b] = a;
    size_[a] += size_[b];
    ++unions_[group];
    largest_[group] = std::max(largest_[group], size_[a]);
  }
  std::size_t mark() const { return history_.size(); }
  void undo_to(std::size_t mark) {
    while (history_.size() > mark) {
      const Step s = history_.back();
      history_.pop_back();
      const std::size_t a = parent_[s.child];
      size_[a] -= size_[s.child];
      parent_[s.child] = s.child;
      --unions_[s.group];
      largest_[s.group] = s.largest;
    }
  }
  std::size_t unions(std::size_t group) const { return unions_[group]; }
  std::size_t largest(std::size_t group) const { return largest_[group]; }

private:
  struct Step {
    std::size_t child;
    std::size_t group;
    std::size_t largest;
  };
  std::vector<std::size_t> parent_, size_;
  std::vector<std::size_t> unions_, largest_;
  std::vector<Step> history_;
};

// An edge of one of two forests: forest 0 is K_t (group 0), forest 1 the union of the subcomplexes
// K_t^X, which share no vertex (group: the type index).
struct Edge {
  std::size_t a = 0, b = 0;
  std::size_t forest = 0;
  std::size_t group = 0;
};

// Segment tree over the slices: each edge interval is stored at O(log S) nodes; a depth-first walk
// applies a node's unions on entry and undoes them on exit, so at leaf s exactly the edges of slice s
// are united.
class ConnectivityOverTime {
public:
  explicit ConnectivityOverTime(std::size_t slices)
      : slices_(slices), nodes_(4 * std::max<std::size_t>(slices, 1)) {}
  void add(std::size_t lo, std::size_t hi, const Edge& e) { add(1, 0, slices_, lo, hi, e); }
  template <class Leaf> void walk(std::vector<RollbackUnionFind>& uf, Leaf&& leaf) {
    if (slices_ > 0)
      walk(1, 0, slices_, uf, leaf);
  }

private:
  void add(std::size_t node, std::size_t l, std::size_t r, std::size_t lo, std::size_t hi, const Edge& e) {
    if (hi <= l || r <= lo)
      return;
    if (lo <= l && r <= hi) {
      nodes_[node].push_back(e);
      return;
    }
    const std::size_t mid = l + (r - l) / 2;
    add(2 * node, l, mid, lo, hi, e);
    add(2 * node + 1, mid, r, lo, hi, e);
  }
  template <class Leaf>
  void walk(std::size_t node, std::size_t l, std::size_t r, std::vector<RollbackUnionFind>& uf, Leaf& leaf) {
    const std::size_t marks[2] = {uf[0].mark(), uf[1].mark()};
    for (const Edge& e : nodes_[node])
      uf[e.forest].unite(e.a, e.b, e.group);
    if (r - l == 1) {
      leaf(l, uf);
    } else {
      const std::size_t mid = l + (r - l) / 2;
      walk(2 * node, l, mid, uf, leaf);
      walk(2 * node + 1, mid, r, uf, leaf);
    }
    uf[0].undo_to(marks[0]);
    uf[1].undo_to(marks[1]);
  }
  std::size_t slices_;
  std::vector<std::vector<Edge>> nodes_;
};

Wide lcm_up_to(std::size_t n, bool& overflow) {
  Wide l = 1;
  overflow = false;
  for (std::size_t k = 2; k <= n; ++k) {
    const Wide g = std::gcd(static_cast<std::uint64_t>(l % k), static_cast<std::uint64_t>(k));
    const Wide factor = k / g;
    if (l > (~Wide{0} >> 8) / factor) {
      overflow = true;
      return 1;
    }
    l *= factor;
  }
  return l;
}

// Sums of same/deg over the cells of each type. Exact while L = lcm(1..max degree) keeps every sum an
// integer multiple of 1/L below 2^124: then nothing is rounded until the mean. Beyond that (a cell
// with more than about 75 neighbours), a histogram of (deg, same) per type, summed at each sample, so
// each mean is a sum of at most (max degree)^2 rounded terms and no rounding accumulates over time.
class FractionSums {
public:
  FractionSums(std::size_t types, std::size_t max_degree, std::size_t cells)
      : exact_(types, 0), histogram_(types) {
    bool overflow = false;
    L_ = lcm_up_to(max_degree, overflow);
    use_exact_ = !overflow && L_ <= (~Wide{0} >> 4) / (static_cast<Wide>(cells + 1) * (max_degree + 1));
  }
  void change(std::size_t type, std::size_t same, std::size_t deg, int sign) {
    if (use_exact_) {
      const Wide part = static_cast<Wide>(same) * (L_ / deg);
      exact_[type] = sign > 0 ? exact_[type] + part : exact_[type] - part;
      return;
    }
    auto& bins = histogram_[type];
    const std::uint64_t key = (static_cast<std::uint64_t>(deg) << 32) | same;
    const long long count = (bins[key] += sign);
    if (count == 0)
      bins.erase(key);
  }
  // The mean of same/deg over the cells of the given types, `count` of them (NaN when 0).
  double mean(std::size_t first_type, std::size_t end_type, std::size_t count) const {
    if (count == 0)
      return std::numeric_limits<double>::quiet_NaN();
    if (use_exact_) {
      Wide sum = 0;
      for (std::size_t t = first_type; t < end_type; ++t)
        sum += exact_[t];
      return static_cast<double>(static_cast<long double>(sum) / (static_cast<long double>(L_) * count));
    }
    long double sum = 0;
    for (std::size_t t = first_type; t < end_type; ++t)
      for (const auto& [key, n] : histogram_[t])
        sum += static_cast<long double>(n) * static_cast<long double>(key & 0xffffffffu) /
               static_cast<long double>(key >> 32);
    return static_cast<double>(sum / count);
  }

private:
  Wide L_ = 1;
  bool use_exact_ = true;
  std::vector<Wide> exact_;
  std::vector<std::unordered_map<std::uint64_t, long long>> histogram_;
};

} // namespace

double SortingMeasures::heterotypic_fraction() const {
  return edges == 0 ? std::numeric_limits<double>::quiet_NaN()
                    : static_cast<double>(heterotypic_edges) / static_cast<double>(edges);
}

double SortingMeasures::mean_cluster_size() const {
  return clusters == 0 ? std::numeric_limits<double>::quiet_NaN()
                       : static_cast<double>(cells) / static_cast<double>(clusters);
}

std::vector<SortingSample> sorting_over_time(const Medusa& medusa, const std::function<void()>& poll) {
  const std::size_t V = medusa.input.cells.size();
  std::vector<int> types;
  for (const kinetic::Trajectory& t : medusa.input.cells)
    types.push_back(t.type);
  std::sort(types.begin(), types.end());
  types.erase(std::unique(types.begin(), types.end()), types.end());
  std::vector<std::size_t> type_of(V);
  for (std::size_t v = 0; v < V; ++v)
    type_of[v] = static_cast<std::size_t>(
        std::lower_bound(types.begin(), types.end(), medusa.input.cells[v].type) - types.begin());
  const std::size_t T = types.size();

  const Slices slices(medusa);
  const std::size_t S = slices.size();
  // Changes per slice: the cells entering at slice s and those leaving (their interval ends at s).
  std::vector<std::vector<const Cell*>> enter(S + 1), leave(S + 1);
  ConnectivityOverTime connectivity(S);
  auto vertex_of = [&](VertexId v, const Cell& c) {
    if (v < 0 || static_cast<std::size_t>(v) >= V)
      throw InternalError("sorting measures: cell " + std::to_string(c.id) + " has vertex " +
                          std::to_string(v) + " outside the input");
    return static_cast<std::size_t>(v);
  };
  for (const Cell& c : medusa.cells) {
    if (c.dim() > 1)
      continue;
    const SliceRange r = slices.of(c);
    if (r.first >= r.end)
      continue;
    enter[r.first].push_back(&c);
    leave[r.end].push_back(&c);
    if (c.dim() == 1) {
      const std::size_t a = vertex_of(c.vertices[0], c), b = vertex_of(c.vertices[1], c);
      connectivity.add(r.first, r.end, {a, b, 0, 0});
      if (type_of[a] == type_of[b])
        connectivity.add(r.first, r.end, {a, b, 1, type_of[a]});
    } else {
      vertex_of(c.vertices[0], c);
    }
  }
  call(poll);

  // The same-type fraction of a cell is same/deg; their sum over a type is kept exactly as an integer
  // multiple of 1/L, L = lcm(1..max degree), so that no rounding accumulates over the slices.
  std::vector<std::size_t> deg(V, 0), same(V, 0);
  std::size_t max_degree = 0;
  for (std::size_t s = 0; s < S; ++s) {
    for (const Cell* c : leave[s])
      if (c->dim() == 1)
        for (VertexId v : c->vertices)
          --deg[static_cast<std::size_t>(v)];
    for (const Cell* c : enter[s])
      if (c->dim() == 1)
        for (VertexId v : c->vertices)
          max_degree = std::max(max_degree, ++deg[static_cast<std::size_t>(v)]);
  }
  FractionSums sums(T, max_degree, V);
  std::fill(deg.begin(), deg.end(), 0);

  std::vector<SortingSample> out(S);
  std::size_t all_edges = 0, all_hetero = 0;
  std::vector<std::size_t> cells(T, 0), with(T, 0), touch(T, 0), hetero(T, 0);
  auto contribution = [&](std::size_t v, int sign) {
    if (deg[v] == 0)
      return;
    const std::size_t t = type_of[v];
    with[t] = sign > 0 ? with[t] + 1 : with[t] - 1;
    sums.change(t, same[v], deg[v], sign);
  };
  auto change_edge = [&](const Cell& c, int sign) {
    const std::size_t a = static_cast<std::size_t>(c.vertices[0]),
                      b = static_cast<std::size_t>(c.vertices[1]);
    const std::size_t ta = type_of[a], tb = type_of[b];
    const bool differ = ta != tb;
    auto step = [sign](std::size_t& x) { x = sign > 0 ? x + 1 : x - 1; };
    step(all_edges);
    step(touch[ta]);
    if (differ) {
      step(all_hetero);
      step(touch[tb]);
      step(hetero[ta]);
      step(hetero[tb]);
    }
    for (std::size_t v : {a, b}) {
      contribution(v, -1);
      step(deg[v]);
      if (!differ)
        step(same[v]);
      contribution(v, +1);
    }
  };
  for (std::size_t s = 0; s < S; ++s) {
    for (const Cell* c : leave[s])
      if (c->dim() == 1)
        change_edge(*c, -1);
    for (const Cell* c : leave[s])
      if (c->dim() == 0)
        --cells[type_of[static_cast<std::size_t>(c->vertices[0])]];
    for (const Cell* c : enter[s])
      if (c->dim() == 0)
        ++cells[type_of[static_cast<std::size_t>(c->vertices[0])]];
    for (const Cell* c : enter[s])
      if (c->dim() == 1)
        change_edge(*c, +1);

    SortingSample& sample = out[s];
    sample.measures.resize(T + 1);
    SortingMeasures& whole = sample.measures[0];
    whole.edges = all_edges;
    whole.heterotypic_edges = all_hetero;
    for (std::size_t t = 0; t < T; ++t) {
      SortingMeasures& m = sample.measures[t + 1];
      m.type = types[t];
      m.cells = cells[t];
      m.edges = touch[t];
      m.heterotypic_edges = hetero[t];
      m.cells_with_neighbours = with[t];
      m.same_type_fraction = sums.mean(t, t + 1, with[t]);
      whole.cells += cells[t];
      whole.cells_with_neighbours += with[t];
    }
    whole.same_type_fraction = sums.mean(0, T, whole.cells_with_neighbours);
    if (s % poll_every == 0)
      call(poll);
  }

  std::vector<RollbackUnionFind> forests{RollbackUnionFind(V, 1), RollbackUnionFind(V, T)};
  std::size_t visited = 0;
  connectivity.walk(forests, [&](std::size_t s, const std::vector<RollbackUnionFind>& f) {
    for (std::size_t g = 0; g <= T; ++g) {
      SortingMeasures& m = out[s].measures[g];
      const RollbackUnionFind& u = f[g == 0 ? 0 : 1];
      const std::size_t group = g == 0 ? 0 : g - 1;
      m.clusters = m.cells - u.unions(group);
      m.largest_cluster = m.cells == 0 ? 0 : u.largest(group);
    }
    if (++visited % poll_every == 0)
      call(poll);
  });

  for (std::size_t i = 0; i < medusa.batches.size(); ++i) {
    out[i].batch = medusa.batches[i].batch;
    out[i].time = medusa.batches[i].time;
  }
  out.back().batch = medusa.end.batch;
  out.back().before = true;
  out.back().time = medusa.end.time;
  std::unordered_map<std::uint64_t, std::size_t> by_batch;
  for (std::size_t i = 0; i < medusa.batches.size(); ++i)
    by_batch.emplace(medusa.batches[i].batch, i);
  for (std::size_t k = 0; k < medusa.input.frames(); ++k) {
    if (k + 1 == medusa.input.frames()) {
      out.back().frames.push_back(k);
      continue;
    }
    auto it = by_batch.find(frame_batch(medusa, k));
    if (it == by_batch.end())
      throw InternalError("sorting measures: frame " + std::to_string(k) + " maps to no batch");
    out[it->second].frames.push_back(k);
  }
  return out;
}

} // namespace medusa
