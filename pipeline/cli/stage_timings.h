// Wall and CPU seconds per stage of `medusa run` and the process's peak memory, for
// `--timings FILE.json` (read by bench/e2e_bench.py). CPU seconds matter on a shared machine, where
// wall time also measures the other processes.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

namespace medusa::cli {

// The stages in the order they run; the JSON keys of --timings.
const std::vector<std::string>& stage_names();

// CPU seconds of the whole process (all threads) so far.
double process_cpu_seconds();

// A wall clock and the process CPU clock started together.
struct StageClock {
  std::chrono::steady_clock::time_point wall = std::chrono::steady_clock::now();
  double cpu = process_cpu_seconds();

  double wall_seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count();
  }
  double cpu_seconds() const { return process_cpu_seconds() - cpu; }
};

class StageTimings {
public:
  // Adds seconds to a stage of stage_names() (several parts may add to one stage); throws
  // InternalError for another name.
  void add(const std::string& stage, double wall_seconds, double cpu_seconds);
  void add(const std::string& stage, const StageClock& clock) {
    add(stage, clock.wall_seconds(), clock.cpu_seconds());
  }
  double wall(const std::string& stage) const;
  double cpu(const std::string& stage) const;
  // The process's peak RSS when the stage last ended (so the stage that raised the peak shows).
  std::int64_t peak_rss_after(const std::string& stage) const;
  double total_wall() const;
  double total_cpu() const;

private:
  struct Entry {
    std::string stage;
    double wall = 0.0, cpu = 0.0;
    std::int64_t peak_rss = 0;
  };
  Entry& entry(const std::string& stage);
  const Entry* find(const std::string& stage) const;
  std::vector<Entry> entries_;
};

// The peak resident set size of this process so far in bytes (VmHWM of /proc/self/status).
std::int64_t peak_rss_bytes();

} // namespace medusa::cli
