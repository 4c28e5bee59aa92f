#include "medusa/persistence/diagram.h"

#include "medusa/core/error.h"

#include <algorithm>
#include <limits>
#include <string>

namespace medusa::persistence {

Diagram make_diagram(const std::vector<medusa::Cell>& cells, const Filtration& filtration,
                     const std::vector<IndexPair>& pairs) {
  if (cells.size() > medusa::max_cell_count)
    throw InternalError("diagram: " + std::to_string(cells.size()) + " cells, more than a medusa holds (" +
                        std::to_string(medusa::max_cell_count) + ")");
  const auto position = [&](std::int64_t j) {
    return static_cast<std::uint32_t>(filtration.cells[static_cast<std::size_t>(j)]);
  };
  const bool forward = filtration.direction == Direction::forward;
  // The filtration value of a cell: its birth forward, its death in reverse (docs/MATH.md §7.2, §7.3).
  auto value_time = [&](std::int64_t j) -> const medusa::VirtualTime& {
    const medusa::Cell& c = cells.at(filtration.cells.at(static_cast<std::size_t>(j)));
    return forward ? c.birth : c.death;
  };
  auto cell_at = [&](std::int64_t j) -> const medusa::Cell& {
    return cells.at(filtration.cells.at(static_cast<std::size_t>(j)));
  };

  const auto n = static_cast<std::int64_t>(filtration.size());
  std::vector<char> in_pair(filtration.size(), 0);
  Diagram diagram;
  diagram.direction = filtration.direction;
  diagram.cell_type = filtration.cell_type;
  // Every column is in one pair or essential: reserve exactly (the diagrams are the largest
  // structure after the medusa itself).
  diagram.pairs.reserve(pairs.size() <= filtration.size() / 2 ? filtration.size() - pairs.size() : 0);
  for (const auto& [b, d] : pairs) {
    if (b < 0 || d <= b || d >= n || in_pair[static_cast<std::size_t>(b)] ||
        in_pair[static_cast<std::size_t>(d)])
      throw InternalError("diagram: invalid reduction pair (" + std::to_string(b) + ", " + std::to_string(d) +
                          ") for a filtration of " + std::to_string(n) + " cells");
    in_pair[static_cast<std::size_t>(b)] = in_pair[static_cast<std::size_t>(d)] = 1;
    const medusa::Cell& birth_cell = cell_at(b);
    const medusa::Cell& death_cell = cell_at(d);
    PersistencePair p;
    p.dim = birth_cell.dim();
    p.birth_time = value_time(b);
    p.death_time = value_time(d);
    p.birth = p.birth_time.time;
    p.death = p.death_time.time;
    p.birth_index = b;
    p.death_index = d;
    p.birth_cell = birth_cell.id;
    p.death_cell = death_cell.id;
    p.birth_position = position(b);
    p.death_position = position(d);
    p.zero_length = p.birth_time.batch == p.death_time.batch;
    diagram.pairs.push_back(std::move(p));
  }
  // Unpaired columns are positive (a negative column is always a death): essential classes
  // (docs/MATH.md §7.5).
  const double infinity = std::numeric_limits<double>::infinity();
  for (std::int64_t j = 0; j < n; ++j) {
    if (in_pair[static_cast<std::size_t>(j)])
      continue;
    const medusa::Cell& c = cell_at(j);
    PersistencePair p;
    p.dim = c.dim();
    p.birth_time = value_time(j);
    p.birth = p.birth_time.time;
    p.death = forward ? infinity : -infinity;
    p.birth_index = j;
    p.birth_cell = c.id;
    p.birth_position = position(j);
    p.essential = true;
    diagram.pairs.push_back(std::move(p));
  }
  std::sort(diagram.pairs.begin(), diagram.pairs.end(),
            [](const PersistencePair& a, const PersistencePair& b) {
              return a.dim != b.dim ? a.dim < b.dim : a.birth_index < b.birth_index;
            });
  return diagram;
}

namespace {

const medusa::Cell& cell_at_position(const std::vector<medusa::Cell>& cells, std::size_t position) {
  if (position >= cells.size())
    throw InternalError("diagram: cell position " + std::to_string(position) + " outside a vector of " +
                        std::to_string(cells.size()) + " cells");
  return cells[position];
}

} // namespace

const medusa::CellVertices& birth_vertices(const PersistencePair& p, const std::vector<medusa::Cell>& cells) {
  return cell_at_position(cells, p.birth_position).vertices;
}

const medusa::CellVertices& death_vertices(const PersistencePair& p, const std::vector<medusa::Cell>& cells) {
  static const medusa::CellVertices none{};
  return p.essential ? none : cell_at_position(cells, p.death_position).vertices;
}

std::vector<PersistencePair> pairs_in_dimension(const Diagram& diagram, int k, bool keep_zero_length) {
  std::vector<PersistencePair> result;
  for (const auto& p : diagram.pairs)
    if (p.dim == k && (keep_zero_length || !p.zero_length))
      result.push_back(p);
  return result;
}

void drop_zero_length(Diagram& diagram) {
  auto& pairs = diagram.pairs;
  pairs.erase(
      std::remove_if(pairs.begin(), pairs.end(), [](const PersistencePair& p) { return p.zero_length; }),
      pairs.end());
  pairs.shrink_to_fit();
}

Diagram without_zero_length(const Diagram& diagram) {
  Diagram result{diagram.direction, diagram.cell_type, {}};
  for (const auto& p : diagram.pairs)
    if (!p.zero_length)
      result.pairs.push_back(p);
  return result;
}

} // namespace medusa::persistence
