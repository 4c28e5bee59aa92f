#include "clusters_apart.h"

#include "medusa/core/error.h"
#include "medusa/medusa/complex_index.h"

#include <algorithm>
#include <numeric>
#include <unordered_map>

namespace medusa::cli {

ClustersApart clusters_apart(const medusa::Medusa& medusa, std::size_t k, int type) {
  if (medusa.input.cells.empty())
    throw InternalError("clusters_apart: the store's input is not loaded");
  std::unordered_map<VertexId, std::size_t> index;
  std::vector<VertexId> vertices;
  std::vector<std::pair<VertexId, VertexId>> edges;
  for (const CellId id : medusa::cells_at_frame(medusa, k, type)) {
    const medusa::Cell& c = medusa.cell(id);
    if (c.vertices.size() == 1) {
      index.emplace(c.vertices[0], vertices.size());
      vertices.push_back(c.vertices[0]);
    } else if (c.vertices.size() == 2) {
      edges.emplace_back(c.vertices[0], c.vertices[1]);
    }
  }
  // Union-find over the type's cells; an edge of K_t^X has both ends among them (a complex).
  std::vector<std::size_t> parent(vertices.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  const auto find = [&](std::size_t x) {
    while (parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& [a, b] : edges)
    parent[find(index.at(a))] = find(index.at(b));
  std::unordered_map<std::size_t, std::size_t> size;
  for (std::size_t i = 0; i < vertices.size(); ++i)
    ++size[find(i)];
  ClustersApart result;
  result.cells = vertices.size();
  for (const auto& entry : size)
    result.largest = std::max(result.largest, entry.second);
  const auto holds_largest = [&](const auto& entry) { return entry.second == result.largest; };
  result.tied = std::count_if(size.begin(), size.end(), holds_largest) > 1;
  if (result.tied)
    return result;
  result.others = size.size() - 1;
  const std::size_t root = std::find_if(size.begin(), size.end(), holds_largest)->first;
  for (std::size_t i = 0; i < vertices.size(); ++i)
    if (find(i) != root)
      result.apart.push_back(medusa.input.cells.at(static_cast<std::size_t>(vertices[i])).cell_id);
  std::sort(result.apart.begin(), result.apart.end());
  result.apart.erase(std::unique(result.apart.begin(), result.apart.end()), result.apart.end());
  return result;
}

} // namespace medusa::cli
