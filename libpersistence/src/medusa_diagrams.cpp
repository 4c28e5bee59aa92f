#include "medusa/persistence/medusa_diagrams.h"

#include "medusa/core/error.h"
#include "medusa/core/free_memory.h"
#include "medusa/core/job_pool.h"
#include "medusa/persistence/degree_check.h"
#include "medusa/persistence/diagram_store.h"
#include "medusa/persistence/euler.h"

#include <chrono>
#include <mutex>

namespace medusa::persistence {
namespace {

std::vector<std::pair<int, Direction>> medusa_jobs(const std::vector<int>& types) {
  std::vector<std::pair<int, Direction>> jobs;
  for (int type : sub_medusa_types(types))
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
                        ClassRepresentatives* classes, const RepresentativeOptions& options,
                        const std::function<void()>& poll) {
  Diagram d;
  if (classes != nullptr) {
    DiagramWithClasses both = compute_diagram_with_classes(cells, f, options, poll);
    d = std::move(both.diagram);
    *classes = std::move(both.classes);
  } else {
    d = compute_diagram(cells, f, poll);
  }
  check_euler(d, f);
  check_homology_degrees(d);
  return d;
}

} // namespace

std::vector<int> sub_medusa_types(const std::vector<int>& types) {
  std::vector<int> sub_medusas = {all_types};
  sub_medusas.insert(sub_medusas.end(), types.begin(), types.end());
  return sub_medusas;
}

std::vector<std::string> medusa_diagram_names(const std::vector<int>& types) {
  std::vector<std::string> names;
  for (const auto& [type, direction] : medusa_jobs(types)) {
    Diagram d;
    d.cell_type = type;
    d.direction = direction;
    names.push_back(diagram_group_name(d));
  }
  return names;
}

std::vector<Diagram> compute_medusa_diagrams(const std::vector<medusa::Cell>& cells,
                                             const std::vector<int>& vertex_type,
                                             const std::vector<int>& types,
                                             const DiagramRunOptions& options) {
  std::vector<ClassRepresentatives>* forward_classes = options.forward_classes;
  if (forward_classes != nullptr && !options.zero_length && !options.on_diagram)
    throw InternalError("medusa diagrams: representatives need the zero-length pairs kept, or on_diagram");
  const auto jobs = medusa_jobs(types);
  std::vector<Diagram> diagrams(jobs.size());
  if (forward_classes != nullptr)
    forward_classes->assign(jobs.size(), ClassRepresentatives{});
  std::vector<DiagramPhaseSeconds> seconds(jobs.size());
  using Clock = std::chrono::steady_clock;
  auto since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  const auto whole = [&](std::size_t i) { return jobs[i].first == all_types; };
  std::mutex handing_over;
  const auto job = [&](std::size_t i) {
    auto start = Clock::now();
    const Filtration filtration = make_job_filtration(cells, vertex_type, jobs[i]);
    seconds[i].filtrations = since(start);
    start = Clock::now();
    ClassRepresentatives* classes =
        forward_classes != nullptr && jobs[i].second == Direction::forward ? &(*forward_classes)[i] : nullptr;
    diagrams[i] = audited_diagram(cells, filtration, classes, options.representatives, options.poll);
    seconds[i].reduction = since(start);
    start = Clock::now();
    if (options.on_diagram) {
      const std::lock_guard<std::mutex> one_at_a_time(handing_over);
      options.on_diagram(i, diagrams[i], classes);
    }
    if (!options.zero_length) {
      drop_zero_length(diagrams[i]);
      if (classes != nullptr)
        *classes = ClassRepresentatives{};
    }
    seconds[i].handed_over = since(start);
  };
  run_jobs(jobs.size(), options.threads, whole, [&](std::size_t i) {
    job(i);
    // The filtration, its matrix and the zero-length pairs are freed: their pages go back before the
    // next job, whose thread may allocate from another malloc arena that could not reuse them.
    release_free_memory();
  });
  if (options.phases != nullptr)
    for (const DiagramPhaseSeconds& s : seconds) {
      options.phases->filtrations += s.filtrations;
      options.phases->reduction += s.reduction;
      options.phases->handed_over += s.handed_over;
    }
  return diagrams;
}

} // namespace medusa::persistence
