#include "stage_timings.h"

#include "medusa/core/error.h"

#include <algorithm>
#include <ctime>
#include <fstream>
#include <sstream>
#include <sys/resource.h>
#ifdef __GLIBC__
#endif

namespace medusa::cli {
namespace {

double clock_seconds(clockid_t id) {
  timespec t{};
  if (clock_gettime(id, &t) != 0)
    return 0.0;
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

} // namespace

const std::vector<std::string>& stage_names() {
  static const std::vector<std::string> names = {"reading",     "kinetic",   "medusa_store",
                                                 "filtrations", "reduction", "exports"};
  return names;
}

double process_cpu_seconds() { return clock_seconds(CLOCK_PROCESS_CPUTIME_ID); }

StageTimings::Entry& StageTimings::entry(const std::string& stage) {
  const auto& names = stage_names();
  if (std::find(names.begin(), names.end(), stage) == names.end())
    throw InternalError("stage timings: unknown stage " + stage);
  for (Entry& e : entries_)
    if (e.stage == stage)
      return e;
  entries_.push_back({stage, 0.0, 0.0, 0});
  return entries_.back();
}

const StageTimings::Entry* StageTimings::find(const std::string& stage) const {
  for (const Entry& e : entries_)
    if (e.stage == stage)
      return &e;
  return nullptr;
}

void StageTimings::add(const std::string& stage, double wall_seconds, double cpu_seconds) {
  Entry& e = entry(stage);
  e.wall += wall_seconds;
  e.cpu += cpu_seconds;
  e.peak_rss = peak_rss_bytes();
}

std::int64_t StageTimings::peak_rss_after(const std::string& stage) const {
  const Entry* e = find(stage);
  return e != nullptr ? e->peak_rss : 0;
}

double StageTimings::wall(const std::string& stage) const {
  const Entry* e = find(stage);
  return e != nullptr ? e->wall : 0.0;
}

double StageTimings::cpu(const std::string& stage) const {
  const Entry* e = find(stage);
  return e != nullptr ? e->cpu : 0.0;
}

double StageTimings::total_wall() const {
  double sum = 0.0;
  for (const Entry& e : entries_)
    sum += e.wall;
  return sum;
}

double StageTimings::total_cpu() const {
  double sum = 0.0;
  for (const Entry& e : entries_)
    sum += e.cpu;
  return sum;
}

namespace {

std::int64_t read_peak_rss_bytes() {
  // VmHWM is the high-water mark of this process image. getrusage's ru_maxrss is the fallback only:
  // Linux carries it across execve, so a child of a large process (say a Python benchmark) would
  // report its parent's peak.
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) {
      std::istringstream fields(line.substr(6));
      std::int64_t kib = 0;
      std::string unit;
      if (fields >> kib >> unit && unit == "kB")
        return kib * 1024;
    }
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0)
    return -1;
  return static_cast<std::int64_t>(usage.ru_maxrss) * 1024;
}

} // namespace

std::int64_t peak_rss_bytes() {
  // Linux reports VmHWM as max(recorded high-water mark, current RSS) and records the mark only when
  // it unmaps pages: pages released by madvise (malloc_trim, release_free_memory) lower the current
  // RSS without recording it, so a later reading can be lower. The peak seen so far cannot be.
  static std::int64_t highest = -1;
  highest = std::max(highest, read_peak_rss_bytes());
  return highest;
}

} // namespace medusa::cli
