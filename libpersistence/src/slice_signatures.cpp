#include "medusa/persistence/slice_signatures.h"

#include "medusa/core/error.h"
#include "medusa/persistence/boundary_matrix.h"

#include <algorithm>
#include <string>
#include <tuple>

namespace medusa::persistence {
namespace {

constexpr std::size_t poll_every = 4096;

void call(const std::function<void()>& poll) {
  if (poll)
    poll();
}

// The cells of the union complex: members that lie in some slice K(b+) or K(b-), i.e. whose birth
// batch is before their death batch (docs/MATH.md §6.8). Instant cells and cells living inside one
// batch lie in no slice; the kept set is closed under facets because facet lifetimes contain
// their cofaces' (docs/MATH.md §6.4).
std::vector<std::size_t> union_cells(const std::vector<Cell>& cells, const std::vector<char>& member) {
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const Cell& c = cells[i];
    if (c.id != i)
      throw InternalError("slice signatures: cell at position " + std::to_string(i) + " has id " +
                          std::to_string(c.id));
    if ((member.empty() || member[i]) && c.birth.batch < c.death.batch)
      kept.push_back(i);
  }
  return kept;
}

// The coned filtration of docs/MATH.md §6.8: the union complex in birth order, the apex w, then the
// cone w*c of every cell c in order of decreasing death. Returns the filtration and, per kept cell in
// birth order, its birth and (for the cone part) death batches.
struct Coned {
  Filtration filtration;
  std::vector<std::uint64_t> births; // birth batch per forward index (non-decreasing)
  std::vector<std::uint64_t> deaths; // death batch per cone index (non-increasing)
  std::vector<std::size_t> cone_of;  // filtration index of w*c per forward index of c
};

Coned coned_filtration(const std::vector<Cell>& cells, std::vector<std::size_t> kept,
                       const std::function<void()>& poll) {
  const std::size_t n = kept.size();
  std::vector<std::size_t> by_death = kept;
  // Facets before cofaces: a facet is born no later and dies no earlier (docs/MATH.md §6.4), and at the
  // same batch it has the lower dimension.
  std::sort(kept.begin(), kept.end(), [&](std::size_t a, std::size_t b) {
    const Cell &x = cells[a], &y = cells[b];
    return std::make_tuple(x.birth.batch, x.dim(), x.id) < std::make_tuple(y.birth.batch, y.dim(), y.id);
  });
  std::sort(by_death.begin(), by_death.end(), [&](std::size_t a, std::size_t b) {
    const Cell &x = cells[a], &y = cells[b];
    return std::make_tuple(y.death.batch, x.dim(), x.id) < std::make_tuple(x.death.batch, y.dim(), y.id);
  });
  call(poll);
  constexpr std::int64_t absent = -1;
  std::vector<std::int64_t> forward_index(cells.size(), absent), cone_index(cells.size(), absent);
  for (std::size_t j = 0; j < n; ++j)
    forward_index[kept[j]] = static_cast<std::int64_t>(j);
  const std::int64_t apex = static_cast<std::int64_t>(n);
  for (std::size_t j = 0; j < n; ++j)
    cone_index[by_death[j]] = static_cast<std::int64_t>(n + 1 + j);

  Coned out;
  Filtration& f = out.filtration;
  check_filtration_size(2 * n + 1, cells.size());
  f.cells.resize(2 * n + 1);
  f.dims.resize(2 * n + 1);
  std::vector<std::int64_t> col;
  out.births.resize(n);
  out.deaths.resize(n);
  out.cone_of.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    const Cell& c = cells[kept[j]];
    f.cells[j] = static_cast<FiltrationIndex>(kept[j]);
    f.dims[j] = static_cast<std::int8_t>(c.dim());
    out.births[j] = c.birth.batch;
    out.cone_of[j] = static_cast<std::size_t>(cone_index[kept[j]]);
    col.clear();
    for (CellId facet : c.facets) {
      const std::int64_t row = facet < cells.size() ? forward_index[facet] : absent;
      if (row == absent || row >= static_cast<std::int64_t>(j))
        throw InternalError("slice signatures: facet " + std::to_string(facet) + " of cell " +
                            std::to_string(c.id) + " does not precede it");
      col.push_back(row);
    }
    std::sort(col.begin(), col.end());
    f.columns.push_back(col);
    if (j % poll_every == 0)
      call(poll);
  }
  f.cells[n] = static_cast<FiltrationIndex>(cells.size()); // the apex is no cell of the medusa
  f.dims[n] = 0;
  f.columns.push_back({});
  for (std::size_t j = 0; j < n; ++j) {
    const Cell& c = cells[by_death[j]];
    const std::size_t at = n + 1 + j;
    f.cells[at] = static_cast<FiltrationIndex>(by_death[j]);
    f.dims[at] = static_cast<std::int8_t>(c.dim() + 1);
    out.deaths[j] = c.death.batch;
    col.clear();
    col.push_back(forward_index[by_death[j]]);
    if (c.facets.empty())
      col.push_back(apex);
    for (CellId facet : c.facets) {
      const std::int64_t row = cone_index[facet];
      if (row == absent || row >= static_cast<std::int64_t>(at))
        throw InternalError("slice signatures: the cone of facet " + std::to_string(facet) + " of cell " +
                            std::to_string(c.id) + " does not precede it");
      col.push_back(row);
    }
    std::sort(col.begin(), col.end());
    f.columns.push_back(col);
    if (j % poll_every == 0)
      call(poll);
  }
  return out;
}

// Adds 1 to count[s] for s in [lo, hi).
void add_range(std::vector<long long>& diff, std::size_t lo, std::size_t hi) {
  if (lo < hi) {
    ++diff[lo];
    --diff[hi];
  }
}

} // namespace

std::vector<Signature> slice_signatures(const std::vector<Cell>& cells, const std::vector<char>& member,
                                        const std::vector<SliceBounds>& slices,
                                        const std::function<void()>& poll) {
  if (!member.empty() && member.size() != cells.size())
    throw InternalError("slice signatures: membership of " + std::to_string(member.size()) + " cells for " +
                        std::to_string(cells.size()));
  for (std::size_t s = 0; s < slices.size(); ++s) {
    if (slices[s].born_before < slices[s].dies_from ||
        (s > 0 && (slices[s].born_before < slices[s - 1].born_before ||
                   slices[s].dies_from < slices[s - 1].dies_from)))
      throw InternalError("slice signatures: slice " + std::to_string(s) + " is out of time order");
  }
  const std::size_t S = slices.size();
  std::vector<Signature> out(S);
  const Coned coned = coned_filtration(cells, union_cells(cells, member), poll);
  const std::size_t n = coned.births.size();
  call(poll);

  // Prefix lengths of the slices: B = the first u forward cells, K^ u w*D = the first v indices.
  std::vector<std::size_t> u(S), v(S);
  for (std::size_t s = 0; s < S; ++s) {
    u[s] = static_cast<std::size_t>(
        std::lower_bound(coned.births.begin(), coned.births.end(), slices[s].born_before) -
        coned.births.begin());
    const std::size_t alive = static_cast<std::size_t>(
        std::partition_point(coned.deaths.begin(), coned.deaths.end(),
                             [&](std::uint64_t d) { return d >= slices[s].dies_from; }) -
        coned.deaths.begin());
    v[s] = n + 1 + alive;
  }
  // Slices s with u[s] > x: [first_u_above(x), S); with v[s] > x: [0, last_v_above(x)).
  auto first_u_above = [&](std::size_t x) {
    return static_cast<std::size_t>(std::upper_bound(u.begin(), u.end(), x) - u.begin());
  };
  auto end_v_above = [&](std::size_t x) {
    return static_cast<std::size_t>(
        std::partition_point(v.begin(), v.end(), [&](std::size_t y) { return y > x; }) - v.begin());
  };

  // Simplex counts: a kept cell (forward index j, cone index c) lies in slice s iff u[s] > j and
  // v[s] > c.
  std::array<std::vector<long long>, 4> f_diff;
  for (auto& d : f_diff)
    d.assign(S + 1, 0);
  for (std::size_t j = 0; j < n; ++j) {
    const int dim = coned.filtration.dims[j];
    if (dim > 3)
      throw InternalError("slice signatures: cell " + std::to_string(coned.filtration.cells[j]) +
                          " of dimension " + std::to_string(dim) + " lies in a time slice");
    add_range(f_diff[static_cast<std::size_t>(dim)], first_u_above(j), end_v_above(coned.cone_of[j]));
  }
  call(poll);

  const std::vector<IndexPair> pairs = reduce(coned.filtration, poll);
  call(poll);
  if (coned.filtration.size() != 2 * pairs.size() + 1)
    throw InternalError("slice signatures: the cone has " +
                        std::to_string(coned.filtration.size() - 2 * pairs.size()) +
                        " essential classes instead of one");

  // docs/MATH.md §6.8: the reduced Betti number of slice s in degree k counts the pairs of degree k
  // with b < u <= d < v and the pairs of degree k+1 with u <= b < v <= d.
  std::array<std::vector<long long>, 5> b_diff;
  for (auto& d : b_diff)
    d.assign(S + 1, 0);
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const std::size_t b = static_cast<std::size_t>(pairs[i].first);
    const std::size_t d = static_cast<std::size_t>(pairs[i].second);
    const int k = coned.filtration.dims[b];
    if (k <= 4)
      add_range(b_diff[static_cast<std::size_t>(k)], first_u_above(b),
                std::min(first_u_above(d), end_v_above(d)));
    if (k >= 1 && k <= 5)
      add_range(b_diff[static_cast<std::size_t>(k - 1)], end_v_above(d),
                std::min(first_u_above(b), end_v_above(b)));
    if (i % poll_every == 0)
      call(poll);
  }

  std::array<long long, 4> f{};
  std::array<long long, 5> reduced{};
  for (std::size_t s = 0; s < S; ++s) {
    Signature& g = out[s];
    for (std::size_t k = 0; k < 4; ++k) {
      f[k] += f_diff[k][s];
      g.f[k] = static_cast<std::size_t>(f[k]);
    }
    for (std::size_t k = 0; k < 5; ++k)
      reduced[k] += b_diff[k][s];
    g.euler = f[0] - f[1] + f[2] - f[3];
    if (f[0] == 0) {
      if (f[1] + f[2] + f[3] != 0 || reduced != std::array<long long, 5>{})
        throw InternalError("slice signatures: slice " + std::to_string(s) + " has no vertex but homology");
      continue;
    }
    if (reduced[4] != 0)
      throw InternalError("slice signatures: slice " + std::to_string(s) + " has homology in degree 4");
    for (std::size_t k = 0; k < 4; ++k)
      g.betti[k] = static_cast<std::size_t>(reduced[k] + (k == 0 ? 1 : 0));
    const long long chi = static_cast<long long>(g.betti[0]) - static_cast<long long>(g.betti[1]) +
                          static_cast<long long>(g.betti[2]) - static_cast<long long>(g.betti[3]);
    if (chi != g.euler)
      throw InternalError("slice signatures: slice " + std::to_string(s) + " has Euler characteristic " +
                          std::to_string(g.euler) + " but alternating Betti sum " + std::to_string(chi));
  }
  return out;
}

std::vector<SignatureSample> signatures_by_reduction(const Medusa& medusa, std::optional<int> type,
                                                     const std::function<void()>& poll) {
  std::vector<char> member;
  if (type) {
    member.resize(medusa.cells.size());
    for (std::size_t i = 0; i < medusa.cells.size(); ++i)
      member[i] = medusa.has_type(medusa.cells[i], *type) ? 1 : 0;
  }
  std::vector<SliceBounds> slices;
  std::vector<SignatureSample> samples;
  slices.reserve(medusa.batches.size() + 1);
  samples.reserve(medusa.batches.size() + 1);
  for (const BatchRecord& b : medusa.batches) {
    slices.push_back({b.batch + 1, b.batch + 1}); // K(b+)
    SignatureSample s;
    s.batch = b.batch;
    s.time = b.time;
    samples.push_back(std::move(s));
  }
  slices.push_back({medusa.end.batch, medusa.end.batch}); // K(t_end-)
  SignatureSample end;
  end.batch = medusa.end.batch;
  end.before = true;
  end.time = medusa.end.time;
  samples.push_back(std::move(end));
  const std::vector<Signature> signatures = slice_signatures(medusa.cells, member, slices, poll);
  for (std::size_t s = 0; s < samples.size(); ++s)
    samples[s].signature = signatures[s];
  assign_frames(medusa, samples);
  return samples;
}

} // namespace medusa::persistence
