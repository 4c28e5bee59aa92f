// Jobs on worker threads with at most one heavy job in memory at a time: the reductions of a run
// (its diagrams, and the open classes of its first and last frames) are one job per sub-medusa, and
// the whole medusa's filtration, boundary matrix and reduction are the largest structures after the
// kinetic stage, so two at once would set the peak of `medusa run` (bench/README.md, "Memory at a
// million cells"). Light jobs (the sub-medusas of one cell type) fill the other threads meanwhile.
#pragma once

#include <algorithm>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace medusa {

// Runs task(i) once for every i in [0, count) on up to `threads` threads (1 = in the calling thread, in
// index order). A free thread takes the lowest-numbered job not yet started, skipping heavy ones
// (heavy(i) true) while a heavy job runs, and waits when only those are left. The tasks write only to
// their own slots, so results do not depend on the scheduling; every exception is kept by index and
// the lowest one rethrown, so neither does the error.
template <class Heavy, class Task>
void run_jobs(std::size_t count, unsigned threads, const Heavy& heavy, const Task& task) {
  std::vector<std::exception_ptr> errors(count);
  std::vector<bool> started(count, false);
  std::size_t left = count;
  bool heavy_running = false;
  std::mutex mutex;
  std::condition_variable heavy_done;
  auto work = [&] {
    std::unique_lock<std::mutex> lock(mutex);
    while (left > 0) {
      std::size_t i = 0;
      while (i < count && (started[i] || (heavy_running && heavy(i))))
        ++i;
      if (i == count) {
        heavy_done.wait(lock);
        continue;
      }
      started[i] = true;
      --left;
      const bool is_heavy = heavy(i);
      heavy_running = heavy_running || is_heavy;
      lock.unlock();
      try {
        task(i);
      } catch (...) {
        errors[i] = std::current_exception();
      }
      lock.lock();
      if (is_heavy) {
        heavy_running = false;
        heavy_done.notify_all();
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

} // namespace medusa
