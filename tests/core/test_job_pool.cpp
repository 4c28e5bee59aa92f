// The worker pool of a run's reductions (medusa/core/job_pool.h): every job once, never two heavy jobs
// at once, light jobs beside a heavy one, and the lowest-numbered error.
#include "medusa/core/job_pool.h"

#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

using medusa::run_jobs;

TEST_CASE("Every job runs exactly once on any number of threads", "[core][jobs]") {
  for (unsigned threads : {1U, 2U, 3U, 8U}) {
    std::vector<std::atomic<int>> runs(13);
    run_jobs(
        runs.size(), threads, [](std::size_t i) { return i % 3 == 0; }, [&](std::size_t i) { ++runs[i]; });
    for (std::size_t i = 0; i < runs.size(); ++i)
      CHECK(runs[i] == 1);
  }
}

TEST_CASE("One thread runs the jobs in index order", "[core][jobs]") {
  std::vector<std::size_t> order;
  run_jobs(
      6, 1, [](std::size_t i) { return i < 2; }, [&](std::size_t i) { order.push_back(i); });
  CHECK(order == std::vector<std::size_t>{0, 1, 2, 3, 4, 5});
}

TEST_CASE("Two heavy jobs never run at once, whatever the threads", "[core][jobs]") {
  for (unsigned threads : {2U, 4U, 8U}) {
    std::atomic<int> heavy_now{0}, most{0}, light_done{0};
    const auto heavy = [](std::size_t i) { return i < 4; };
    run_jobs(12, threads, heavy, [&](std::size_t i) {
      if (!heavy(i)) {
        ++light_done;
        return;
      }
      const int now = ++heavy_now;
      most = std::max(most.load(), now);
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      --heavy_now;
    });
    INFO("threads " << threads);
    CHECK(most == 1);
    CHECK(light_done == 8);
  }
}

TEST_CASE("Light jobs run beside a heavy one", "[core][jobs]") {
  // Job 0 (heavy) waits until job 2 (light) has run; job 1 (heavy) must wait for job 0. Two threads
  // finish only if the free thread skips job 1 and takes job 2 while job 0 runs.
  std::mutex mutex;
  std::condition_variable ran;
  bool light_ran = false, waited_in_vain = false;
  run_jobs(
      3, 2, [](std::size_t i) { return i < 2; },
      [&](std::size_t i) {
        std::unique_lock<std::mutex> lock(mutex);
        if (i == 0)
          waited_in_vain = !ran.wait_for(lock, std::chrono::seconds(60), [&] { return light_ran; });
        if (i == 2) {
          light_ran = true;
          ran.notify_all();
        }
      });
  CHECK_FALSE(waited_in_vain);
}

TEST_CASE("The error of the lowest-numbered failing job is the one thrown", "[core][jobs]") {
  for (unsigned threads : {1U, 2U, 8U}) {
    std::atomic<int> runs{0};
    try {
      run_jobs(
          10, threads, [](std::size_t i) { return i == 0 || i == 7; },
          [&](std::size_t i) {
            ++runs;
            if (i == 3 || i == 7 || i == 9)
              throw std::runtime_error("job " + std::to_string(i));
          });
      FAIL("no error thrown");
    } catch (const std::runtime_error& e) {
      CHECK(std::string(e.what()) == "job 3");
    }
    CHECK(runs == 10);
  }
}
