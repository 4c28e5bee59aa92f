#include "medusa/persistence/distance_matrix.h"

#include <algorithm>
#include <exception>
#include <thread>
#include <utility>

namespace medusa::persistence {

DistanceMatrix distance_matrix(const std::vector<PointDiagram>& diagrams, const DiagramMetric& metric,
                               unsigned workers) {
  const std::size_t n = diagrams.size();
  DistanceMatrix matrix{n, std::vector<double>(n * n, 0.0)};
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      pairs.emplace_back(i, j);
  workers = std::max(
      1u, std::min<unsigned>(workers, static_cast<unsigned>(std::max<std::size_t>(pairs.size(), 1))));
  // Each pair is independent and written to its own two cells, so the workers share no state.
  std::vector<std::exception_ptr> errors(workers);
  auto work = [&](unsigned w) {
    try {
      for (std::size_t k = w; k < pairs.size(); k += workers) {
        const auto [i, j] = pairs[k];
        const double d = metric(diagrams[i], diagrams[j]);
        matrix.values[i * n + j] = d;
        matrix.values[j * n + i] = d;
      }
    } catch (...) {
      errors[w] = std::current_exception();
    }
  };
  std::vector<std::thread> threads;
  for (unsigned w = 1; w < workers; ++w)
    threads.emplace_back(work, w);
  work(0);
  for (auto& t : threads)
    t.join();
  for (const auto& e : errors)
    if (e)
      std::rethrow_exception(e);
  return matrix;
}

} // namespace medusa::persistence
