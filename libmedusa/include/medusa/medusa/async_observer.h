// Runs an observer of the kinetic event stream on a thread of its own, beside the engine.
//
// `medusa run` feeds the stream to the medusa builder, whose cells go to the HDF5 store (writes and
// deflate). Called from the engine's thread, that work sits between the engine's events; here it
// runs on a second core while the engine goes on. The stream is copied and handed over in blocks of
// `block` calls (one hand-over per call would cost a wake-up of the worker per event); the engine
// waits when the worker is `capacity` blocks behind, so memory stays bounded.
//
// The inner observer receives exactly the calls the engine made, in the same order, all from the
// worker thread (which runs with every signal blocked); nothing else may touch it (nor, for the store
// writer, the HDF5 library) until finish() has returned. An exception thrown by the inner observer
// stops the worker and drops the calls after it; it is thrown to the engine at its next call (the
// inner observer may be up to a block behind), and again by finish(), so the run stops with the
// store's own error message and a finish() that returns means every call went through. If the
// engine fails first, its own exception unwinds past the observer and a later failure of the inner
// observer is not reported.
#pragma once

#include "medusa/kinetic/observer.h"

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace medusa {

class AsyncObserver : public kinetic::Observer {
public:
  explicit AsyncObserver(kinetic::Observer& next, std::size_t block = 256, std::size_t capacity = 8);
  // Stops the worker and drops the calls still queued (the engine failed or was interrupted).
  ~AsyncObserver() override;
  AsyncObserver(const AsyncObserver&) = delete;
  AsyncObserver& operator=(const AsyncObserver&) = delete;

  void initial(const kinetic::EventTime& t0, const std::vector<kinetic::Simplex>& complex) override;
  void batch(const kinetic::EventTime& time, const std::vector<kinetic::Step>& steps) override;
  void frame(std::size_t k, const kinetic::EventTime& time) override;
  // Queues the inner finish() and waits until the worker has made every call.
  void finish(const kinetic::EventTime& t_end) override;

private:
  enum class Kind { initial, batch, frame, finish };
  struct Call {
    Kind kind = Kind::batch;
    kinetic::EventTime time;
    std::size_t frame = 0;
    std::vector<kinetic::Simplex> complex;
    std::vector<kinetic::Step> steps;
  };

  void push(Call call);
  void hand_over(); // queues the pending block
  void work();

  kinetic::Observer& next_;
  const std::size_t block_, capacity_;
  std::vector<Call> pending_; // the caller's block in the making
  std::mutex mutex_;
  std::condition_variable not_empty_, not_full_, drained_;
  std::deque<std::vector<Call>> queue_;
  bool busy_ = false;     // the worker is inside a call of the inner observer
  bool stopping_ = false; // the destructor asks the worker to leave
  std::exception_ptr failure_;
  std::atomic<bool> failed_{false}; // failure_ is set: read by the caller without the lock
  bool failure_reported_ = false;
  std::thread worker_;
};

} // namespace medusa
