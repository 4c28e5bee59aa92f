#include "medusa/persistence/medusa_diagrams.h"

#include "medusa/persistence/degree_check.h"
#include "medusa/persistence/euler.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <thread>

namespace medusa::persistence {
namespace {

// Runs task(i) for i in [0, count) on `threads` threads, each taking the next index; the tasks write
// only to their own slots. Every exception is kept by index and the lowest one rethrown, so the
// error does not depend on the scheduling.
template <class Task> void for_each_index(std::size_t count, unsigned threads, const Task& task) {
  std::vector<std::exception_ptr> errors(count);
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t i = next++; i < count; i = next++) {
      try {
        task(i);
      } catch (...) {
        errors[i] = std::current_exception();
      }
    }
  };
  const auto workers = static_cast<unsigned>(std::max<std::size_t>(1, std::min<std::size_t>(threads, count)));
  std::vector<std::thread> pool;
  for (unsigned w = 1; w < workers; ++w)
    pool.emplace_back(work);
  work();
  for (std::thread& t : pool)
    t.join();
  for (const std::exception_ptr& e : errors)
    if (e)
      std::rethrow_exception(e);
}

std::vector<std::pair<int, Direction>> medusa_jobs(const std::vector<int>& types) {
  std::vector<std::pair<int, Direction>> jobs;
  for (Direction direction : {Direction::forward, Direction::reverse})
    jobs.emplace_back(all_types, direction);
  for (int type : types)
    for (Direction direction : {Direction::forward, Direction::reverse})
      jobs.emplace_back(type, direction);
  return jobs;
}

Filtration make_job_filtration(const std::vector<medusa::Cell>& cells, const std::vector<int>& vertex_type,
                               const std::pair<int, Direction>& job) {
  return job.first == all_types ? make_filtration(cells, job.second)
                                : make_type_filtration(cells, vertex_type, job.first, job.second);
}

Diagram audited_diagram(const std::vector<medusa::Cell>& cells, const Filtration& f,
                        ClassRepresentatives* classes, const RepresentativeOptions& options) {
  Diagram d;
  if (classes != nullptr) {
    DiagramWithClasses both = compute_diagram_with_classes(cells, f, options);
    d = std::move(both.diagram);
    *classes = std::move(both.classes);
  } else {
    d = compute_diagram(cells, f);
  }
  check_euler(d, f);
  check_homology_degrees(d);
  return d;
}

} // namespace

std::vector<Diagram> compute_medusa_diagrams(const std::vector<medusa::Cell>& cells,
                                             const std::vector<int>& vertex_type,
                                             const std::vector<int>& types, unsigned threads,
                                             DiagramPhaseSeconds* phases,
                                             std::vector<ClassRepresentatives>* forward_classes,
                                             const RepresentativeOptions& options) {
  const auto jobs = medusa_jobs(types);
  std::vector<Diagram> diagrams(jobs.size());
  if (forward_classes != nullptr)
    forward_classes->assign(jobs.size(), ClassRepresentatives{});
  std::vector<DiagramPhaseSeconds> seconds(jobs.size());
  using Clock = std::chrono::steady_clock;
  auto since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  for_each_index(jobs.size(), threads, [&](std::size_t i) {
    auto start = Clock::now();
    const Filtration filtration = make_job_filtration(cells, vertex_type, jobs[i]);
    seconds[i].filtrations = since(start);
    start = Clock::now();
    ClassRepresentatives* classes =
        forward_classes != nullptr && jobs[i].second == Direction::forward ? &(*forward_classes)[i] : nullptr;
    diagrams[i] = audited_diagram(cells, filtration, classes, options);
    seconds[i].reduction = since(start);
  });
  if (phases != nullptr)
    for (const DiagramPhaseSeconds& s : seconds) {
      phases->filtrations += s.filtrations;
      phases->reduction += s.reduction;
    }
  return diagrams;
}

} // namespace medusa::persistence
