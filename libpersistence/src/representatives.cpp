#include "medusa/persistence/representatives.h"

#include "medusa/core/error.h"
#include "medusa/persistence/boundary_matrix.h"

#include "cycle_shortening.h"

#include <phat/algorithms/twist_reduction.h>
#include <phat/representations/bit_tree_pivot_column.h>

#include <algorithm>
#include <iterator>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>

namespace medusa::persistence {
namespace {

using Index = std::int64_t;
using Chain = std::vector<Index>; // filtration indices, ascending
using Matrix = phat::boundary_matrix<compact_pivot_column>;

Chain sum(const Chain& a, const Chain& b) {
  Chain out;
  out.reserve(a.size() + b.size());
  std::set_symmetric_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

// The reduced matrix R, compacted into one array once the reduction is done: from then on its columns
// are only read (a death's cycle, the expressions of essential cycles), and PHAT's vector per column
// costs a heap block and the capacity its additions left besides the entries. Built before the diagram, so
// that the matrix and the diagram, the two largest structures of a filtration, are never held together.
class ReducedColumns {
public:
  explicit ReducedColumns(const Matrix& matrix) {
    offsets_.reserve(static_cast<std::size_t>(matrix.get_num_cols()) + 1);
    offsets_.push_back(0);
    entries_.reserve(static_cast<std::size_t>(matrix.get_num_entries()));
    std::vector<phat::index> column;
    for (Index j = 0; j < matrix.get_num_cols(); ++j) {
      column.clear(); // PHAT's pivot column appends to it
      matrix.get_col(j, column);
      std::sort(column.begin(), column.end());
      entries_.insert(entries_.end(), column.begin(), column.end()); // indices of f: 32 bits (filtration.h)
      offsets_.push_back(entries_.size());
    }
  }

  Chain column(Index j) const { return Chain(begin(j), end(j)); }
  const FiltrationIndex* begin(Index j) const {
    return entries_.data() + offsets_[static_cast<std::size_t>(j)];
  }
  const FiltrationIndex* end(Index j) const {
    return entries_.data() + offsets_[static_cast<std::size_t>(j) + 1];
  }

private:
  std::vector<std::size_t> offsets_;     // column j is entries_[offsets_[j], offsets_[j + 1])
  std::vector<FiltrationIndex> entries_; // ascending within a column
};

Chain boundary_of(const Filtration& f, Index j) { return f.columns[static_cast<std::size_t>(j)].to_vector(); }

// The reduced boundary matrix of `f`, compacted, and its finite pairs in `pairs`; PHAT's matrix is
// gone when this returns.
ReducedColumns reduce_compacted(const Filtration& f, const std::function<void()>& poll,
                                std::vector<IndexPair>& pairs) {
  Matrix matrix = make_boundary_matrix(f);
  PolledTwistReduction{poll}(matrix);
  pairs = reduced_pairs(matrix);
  return ReducedColumns(matrix);
}

// Cycles of essential classes (docs/MATH.md §7.11). The twist reduction keeps R but not V (R = D V):
// V is rebuilt only where an essential class needs it. A reduced column R[i] is the boundary of i
// plus reduced columns R[j], j < i, of the same degree; those j are recovered by eliminating the
// lowest entry of R[i] + ∂i against the column holding that entry as its pivot (pivots are unique, so
// the expression is). Then W(i) = i + sum of W(j) has boundary R[i], and for an essential cell b,
// ∂b = sum of R[j] over the j found the same way, so b + sum of W(j) is a cycle whose last cell is b.
class EssentialCycles {
public:
  EssentialCycles(const ReducedColumns& reduced, const Filtration& f, const std::vector<IndexPair>& pairs)
      : reduced_(reduced), filtration_(f), pivot_column_(f.size(), -1) {
    column_.init(static_cast<phat::index>(f.size()));
    for (const auto& [b, d] : pairs)
      pivot_column_[static_cast<std::size_t>(b)] = d;
  }

  Chain cycle_of(Index b) {
    const std::vector<Index> used = express(boundary_of(filtration_, b), {}, b);
    // b plus the W(j), summed at once in the pivot column (pairwise sums of long cycles would cost
    // their length once per term). The W(j) are all found first: finding one uses the column too.
    std::vector<const Chain*> terms;
    terms.reserve(used.size());
    for (Index j : used)
      terms.push_back(&preimage(j)); // memo_'s nodes stay where they are
    column_.add_index(static_cast<std::size_t>(b));
    for (const Chain* w : terms)
      column_.add_col(w->begin(), w->end());
    Chain z;
    column_.get_col_and_clear(z);
    return z;
  }

private:
  // The columns whose reduced forms sum to a + b, each before `before`. The sum is held in PHAT's
  // bit-tree pivot column (docs/MATH.md §7.11), where adding an entry toggles it and the largest is
  // at hand: each step adds the reduced column whose pivot is that entry, at the cost of the column's
  // length, not the sum's as a merge of sorted chains would. The column is left empty.
  std::vector<Index> express(const Chain& a, const Chain& b, Index before) const {
    column_.add_col(a.begin(), a.end());
    column_.add_col(b.begin(), b.end());
    std::vector<Index> used;
    while (!column_.is_empty()) {
      const Index low = column_.get_max_index();
      const Index j = pivot_column_[static_cast<std::size_t>(low)];
      if (j < 0 || j >= before) {
        column_.clear();
        throw InternalError("representatives: filtration index " + std::to_string(low) +
                            " is no pivot of an earlier reduced column");
      }
      column_.add_col(reduced_.begin(j), reduced_.end(j)); // its largest entry, low, cancels
      used.push_back(j);
    }
    return used;
  }

  // W(i) with boundary R[i], memoised; built bottom-up with an explicit stack (chains of
  // dependencies can be long).
  const Chain& preimage(Index root) {
    if (const auto it = memo_.find(root); it != memo_.end())
      return it->second;
    std::unordered_map<Index, std::vector<Index>> pending;
    std::vector<Index> stack{root};
    while (!stack.empty()) {
      const Index i = stack.back();
      if (memo_.count(i) != 0) {
        stack.pop_back();
        continue;
      }
      auto at = pending.find(i);
      if (at == pending.end()) {
        at = pending.emplace(i, express(reduced_.column(i), boundary_of(filtration_, i), i)).first;
        bool ready = true;
        for (Index j : at->second)
          if (memo_.count(j) == 0) {
            stack.push_back(j);
            ready = false;
          }
        if (!ready)
          continue;
      }
      Chain w{i};
      for (Index j : at->second)
        w = sum(w, memo_.at(j));
      memo_.emplace(i, std::move(w));
      pending.erase(at);
      stack.pop_back();
    }
    return memo_.at(root);
  }

  const ReducedColumns& reduced_;
  const Filtration& filtration_;
  std::vector<Index> pivot_column_; // by birth index: the column that kills it, -1 if none
  std::unordered_map<Index, Chain> memo_;
  mutable phat::bit_tree_column column_; // the working sum of express() and cycle_of(), empty between calls
};

// Union-find over the vertices in filtration order (docs/MATH.md §7.11): the components with their
// members (linked lists, concatenated in O(1)) and their oldest vertex.
class Components {
public:
  explicit Components(std::size_t n) : parent_(n), oldest_(n), next_(n, -1), tail_(n) {}

  void add_vertex(Index v) {
    parent_[static_cast<std::size_t>(v)] = v;
    oldest_[static_cast<std::size_t>(v)] = v;
    tail_[static_cast<std::size_t>(v)] = v;
  }
  Index find(Index v) {
    while (parent_[static_cast<std::size_t>(v)] != v) {
      auto& p = parent_[static_cast<std::size_t>(v)];
      p = parent_[static_cast<std::size_t>(p)];
      v = p;
    }
    return v;
  }
  Index oldest(Index root) const { return oldest_[static_cast<std::size_t>(root)]; }
  Chain members(Index root) const {
    Chain out;
    for (Index v = root; v >= 0; v = next_[static_cast<std::size_t>(v)])
      out.push_back(v);
    std::sort(out.begin(), out.end());
    return out;
  }
  // Merges the component of root `b` into that of root `a` (a keeps its oldest vertex).
  void merge_into(Index a, Index b) {
    parent_[static_cast<std::size_t>(b)] = a;
    next_[static_cast<std::size_t>(tail_[static_cast<std::size_t>(a)])] = b;
    tail_[static_cast<std::size_t>(a)] = tail_[static_cast<std::size_t>(b)];
  }

private:
  std::vector<Index> parent_, oldest_, next_, tail_;
};

// The degree-0 representatives, cycle and cluster, of the degree-0 points among `rows`, in row order
// (entry i belongs to the i-th such row).
void degree_zero(const Filtration& f, const Diagram& diagram, const std::vector<std::size_t>& rows,
                 std::vector<Chain>& cycles, std::vector<Chain>& clusters) {
  // Rows wanted, by the death column (finite) or the birth vertex (essential).
  std::unordered_map<Index, std::size_t> by_death, by_birth;
  std::vector<std::size_t> zero; // the degree-0 rows
  for (std::size_t row : rows) {
    const PersistencePair& p = diagram.pairs[row];
    if (p.dim != 0)
      continue;
    (p.essential ? by_birth[p.birth_index] : by_death[p.death_index]) = zero.size();
    zero.push_back(row);
  }
  cycles.assign(zero.size(), Chain());
  clusters.assign(zero.size(), Chain());
  if (by_death.empty() && by_birth.empty())
    return;
  Components components(f.size());
  for (std::size_t j = 0; j < f.size(); ++j) {
    const auto index = static_cast<Index>(j);
    if (f.dims[j] == 0) {
      components.add_vertex(index);
      continue;
    }
    if (f.dims[j] != 1)
      continue;
    const Index u = components.find(f.columns[j][0]), v = components.find(f.columns[j][1]);
    if (u == v)
      continue;
    // Elder rule: the component with the younger oldest vertex dies (docs/MATH.md §7.5).
    const bool u_older = components.oldest(u) < components.oldest(v);
    const Index older = u_older ? u : v, younger = u_older ? v : u;
    if (const auto it = by_death.find(index); it != by_death.end()) {
      const PersistencePair& p = diagram.pairs[zero[it->second]];
      if (p.birth_index != components.oldest(younger))
        throw InternalError("representatives: H0 pair (" + std::to_string(p.birth_index) + ", " +
                            std::to_string(p.death_index) + ") does not follow the elder rule");
      cycles[it->second] = {components.oldest(older), components.oldest(younger)};
      clusters[it->second] = components.members(younger);
    }
    components.merge_into(older, younger);
  }
  for (const auto& [birth, i] : by_birth) {
    const Index root = components.find(birth);
    if (components.oldest(root) != birth)
      throw InternalError("representatives: essential H0 class born at " + std::to_string(birth) +
                          " is not the oldest vertex of its component");
    cycles[i] = {birth};
    clusters[i] = components.members(root);
  }
}

// The boundary of a chain over Z/2 is zero.
bool is_cycle(const Filtration& f, const Chain& z) {
  std::vector<Index> faces;
  for (Index j : z)
    faces.insert(faces.end(), f.columns[static_cast<std::size_t>(j)].begin(),
                 f.columns[static_cast<std::size_t>(j)].end());
  std::sort(faces.begin(), faces.end());
  for (std::size_t k = 0; k < faces.size(); k += 2)
    if (k + 1 >= faces.size() || faces[k] != faces[k + 1])
      return false;
  return true;
}

// The defining properties that are cheap to check (docs/MATH.md §7.11): a cycle whose last cell is the
// birth cell. Not being a boundary before the death follows from the pivots, and is kept by shortening.
void check_cycle(const Filtration& f, Index birth, const Chain& z) {
  if (z.empty() || z.back() != birth || !is_cycle(f, z))
    throw InternalError("representatives: the cycle of the class born at filtration index " +
                        std::to_string(birth) + " is not a cycle ending at its birth cell");
}

// Appends the cell ids of chain z to `lists`.
void push_cell_ids(CellLists& lists, const std::vector<medusa::Cell>& cells, const Filtration& f,
                   const Chain& z) {
  lists.push_back(z, [&](Index j) { return cells[f.cells[static_cast<std::size_t>(j)]].id; });
}

} // namespace

DiagramWithClasses compute_diagram_with_classes(const std::vector<medusa::Cell>& cells,
                                                const Filtration& filtration,
                                                const RepresentativeOptions& options,
                                                const std::function<void()>& poll) {
  std::vector<IndexPair> pairs;
  const ReducedColumns reduced = reduce_compacted(filtration, poll, pairs);

  DiagramWithClasses out;
  out.diagram = make_diagram(cells, filtration, pairs);
  const Diagram& diagram = out.diagram;
  ClassRepresentatives& classes = out.classes;
  classes.options = options;
  for (std::size_t r = 0; r < diagram.pairs.size(); ++r) {
    const PersistencePair& p = diagram.pairs[r];
    if (p.dim <= options.max_dim && (options.zero_length || !p.zero_length))
      classes.rows.push_back(r);
  }
  // Degree 0 comes from one pass over the whole filtration, its chains held for its rows only. Every
  // other cycle is turned into cell ids as soon as it is found: held for the whole diagram, the
  // chains would sit beside their cell ids, with the slack their sums reserved (the essential
  // cycles are long, and among the largest structures of a diagram).
  std::vector<Chain> zero_cycles, zero_clusters;
  degree_zero(filtration, diagram, classes.rows, zero_cycles, zero_clusters);
  EssentialCycles essential(reduced, filtration, pairs);
  std::optional<detail::Cofaces> cofaces;
  if (options.shorten && options.max_dim >= 1)
    cofaces.emplace(filtration, options.max_dim);
  classes.cycles.reserve(classes.rows.size());
  classes.clusters.reserve(classes.rows.size());
  std::size_t next_zero = 0;
  for (std::size_t i = 0; i < classes.rows.size(); ++i) {
    const PersistencePair& p = diagram.pairs[classes.rows[i]];
    if (p.dim == 0) {
      push_cell_ids(classes.cycles, cells, filtration, zero_cycles[next_zero]);
      push_cell_ids(classes.clusters, cells, filtration, zero_clusters[next_zero]);
      Chain().swap(zero_cycles[next_zero]);
      Chain().swap(zero_clusters[next_zero++]);
      continue;
    }
    Chain z = p.essential ? essential.cycle_of(p.birth_index) : reduced.column(p.death_index);
    // Cells added by shortening enter before the death, or anywhere for an essential class (§7.13).
    if (cofaces)
      detail::shorten_cycle(filtration, *cofaces,
                            p.essential ? static_cast<Index>(filtration.size()) : p.death_index, z);
    check_cycle(filtration, p.birth_index, z);
    push_cell_ids(classes.cycles, cells, filtration, z);
    classes.clusters.push_back({});
  }
  return out;
}

void shorten_representatives(const std::vector<medusa::Cell>& cells, const Filtration& filtration,
                             const Diagram& diagram, ClassRepresentatives& classes) {
  if (!classes.options.shorten && classes.options.max_dim >= 1) {
    std::unordered_map<medusa::CellId, Index> index_of;
    index_of.reserve(filtration.size());
    for (std::size_t j = 0; j < filtration.size(); ++j)
      index_of.emplace(cells[filtration.cells[j]].id, static_cast<Index>(j));
    const detail::Cofaces cofaces(filtration, classes.options.max_dim);
    classes.cycles.rebuild([&](std::size_t i, CellLists::List cycle, CellLists& shortened) {
      const PersistencePair& p = diagram.pairs.at(classes.rows[i]);
      if (p.dim == 0) {
        shortened.push_back(cycle);
        return;
      }
      // Stored diagrams keep cell ids, not filtration indices: both are looked up.
      const auto index = [&](medusa::CellId id) {
        const auto it = index_of.find(id);
        if (it == index_of.end())
          throw InputError("representatives: cell " + std::to_string(id) + " of the class born at cell " +
                           std::to_string(p.birth_cell) + " is not in its diagram's filtration");
        return it->second;
      };
      Chain z;
      z.reserve(cycle.size());
      for (medusa::CellId id : cycle)
        z.push_back(index(id));
      std::sort(z.begin(), z.end());
      const Index birth = index(p.birth_cell);
      detail::shorten_cycle(filtration, cofaces,
                            p.essential ? static_cast<Index>(filtration.size()) : index(p.death_cell), z);
      check_cycle(filtration, birth, z);
      push_cell_ids(shortened, cells, filtration, z);
    });
  }
  classes.options.shorten = true;
}

} // namespace medusa::persistence
