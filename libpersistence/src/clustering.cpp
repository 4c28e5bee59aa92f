#include "medusa/persistence/clustering.h"

#include "medusa/core/error.h"

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/kruskal_min_spanning_tree.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <tuple>

namespace medusa::persistence {
namespace {

void check_matrix(const DistanceMatrix& d) {
  if (d.values.size() != d.size * d.size)
    throw InputError("clustering: distance matrix of size " + std::to_string(d.size) + " holds " +
                     std::to_string(d.values.size()) + " values");
  for (std::size_t i = 0; i < d.size; ++i)
    for (std::size_t j = 0; j < d.size; ++j)
      if (std::isnan(d.at(i, j)) || d.at(i, j) < 0 || d.at(i, j) != d.at(j, i))
        throw InputError("clustering: distance matrix entry (" + std::to_string(i) + ", " +
                         std::to_string(j) + ") is negative, NaN or not symmetric");
}

} // namespace

Dendrogram single_linkage(const DistanceMatrix& distances) {
  check_matrix(distances);
  const std::size_t n = distances.size;
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                                      boost::property<boost::edge_weight_t, double>>;
  using Edge = boost::graph_traits<Graph>::edge_descriptor;
  Graph graph(n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      boost::add_edge(i, j, distances.at(i, j), graph);
  std::vector<Edge> tree;
  boost::kruskal_minimum_spanning_tree(graph, std::back_inserter(tree));
  // The single-linkage dendrogram is the MST's edges in increasing weight, merged in that order.
  std::vector<std::tuple<double, std::size_t, std::size_t>> edges;
  for (const Edge& e : tree) {
    const std::size_t u = boost::source(e, graph), v = boost::target(e, graph);
    edges.emplace_back(boost::get(boost::edge_weight, graph, e), std::min(u, v), std::max(u, v));
  }
  std::sort(edges.begin(), edges.end());
  std::vector<std::size_t> parent(n), cluster(n), size(n, 1);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  std::iota(cluster.begin(), cluster.end(), std::size_t{0});
  auto find = [&](std::size_t x) {
    while (parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  };
  Dendrogram dendrogram{n, {}};
  for (const auto& [w, u, v] : edges) {
    const std::size_t ru = find(u), rv = find(v);
    const std::size_t cu = cluster[ru], cv = cluster[rv];
    parent[rv] = ru;
    size[ru] += size[rv];
    cluster[ru] = n + dendrogram.merges.size();
    dendrogram.merges.push_back({std::min(cu, cv), std::max(cu, cv), w, size[ru]});
  }
  return dendrogram;
}

Dendrogram average_linkage(const DistanceMatrix& distances) {
  check_matrix(distances);
  const std::size_t n = distances.size;
  std::vector<double> d = distances.values;
  std::vector<std::size_t> cluster(n), size(n, 1);
  std::iota(cluster.begin(), cluster.end(), std::size_t{0});
  std::vector<char> alive(n, 1);
  Dendrogram dendrogram{n, {}};
  for (std::size_t step = 0; step + 1 < n; ++step) {
    double best = std::numeric_limits<double>::infinity();
    std::size_t bi = n, bj = n;
    for (std::size_t i = 0; i < n; ++i) {
      if (!alive[i])
        continue;
      for (std::size_t j = i + 1; j < n; ++j) {
        if (!alive[j])
          continue;
        const double v = d[i * n + j];
        const auto key = std::make_pair(std::min(cluster[i], cluster[j]), std::max(cluster[i], cluster[j]));
        if (bi == n || v < best ||
            (v == best &&
             key < std::make_pair(std::min(cluster[bi], cluster[bj]), std::max(cluster[bi], cluster[bj])))) {
          best = v;
          bi = i;
          bj = j;
        }
      }
    }
    // Lance-Williams for UPGMA: d(k, i+j) = (|i| d(k,i) + |j| d(k,j)) / (|i| + |j|); slot bi holds the union.
    for (std::size_t k = 0; k < n; ++k) {
      if (!alive[k] || k == bi || k == bj)
        continue;
      const double v =
          (static_cast<double>(size[bi]) * d[k * n + bi] + static_cast<double>(size[bj]) * d[k * n + bj]) /
          static_cast<double>(size[bi] + size[bj]);
      d[k * n + bi] = d[bi * n + k] = v;
    }
    dendrogram.merges.push_back(
        {std::min(cluster[bi], cluster[bj]), std::max(cluster[bi], cluster[bj]), best, size[bi] + size[bj]});
    size[bi] += size[bj];
    cluster[bi] = n + step;
    alive[bj] = 0;
  }
  return dendrogram;
}

} // namespace medusa::persistence
