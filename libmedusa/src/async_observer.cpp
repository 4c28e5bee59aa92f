// The worker thread and its bounded queue (async_observer.h).
#include "medusa/medusa/async_observer.h"

#include <csignal>
#include <pthread.h>
#include <utility>

namespace medusa {

AsyncObserver::AsyncObserver(kinetic::Observer& next, std::size_t block, std::size_t capacity)
    : next_(next), block_(block == 0 ? 1 : block), capacity_(capacity == 0 ? 1 : capacity) {
  // Signals (SIGINT, SIGTERM: the CLI's interrupt handlers) go to the engine's thread, which checks
  // for them: the worker starts with every signal blocked.
  sigset_t all, previous;
  sigfillset(&all);
  pthread_sigmask(SIG_BLOCK, &all, &previous);
  worker_ = std::thread([this] { work(); });
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
}

AsyncObserver::~AsyncObserver() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
    queue_.clear();
  }
  not_empty_.notify_all();
  worker_.join();
}

void AsyncObserver::push(Call call) {
  pending_.push_back(std::move(call));
  // After a failure, at once: hand_over throws it (once) and drops the calls.
  if (pending_.size() >= block_ || failed_.load(std::memory_order_acquire))
    hand_over();
}

void AsyncObserver::hand_over() {
  std::unique_lock<std::mutex> lock(mutex_);
  not_full_.wait(lock, [&] { return queue_.size() < capacity_ || failure_; });
  if (failure_) {
    pending_.clear();
    // Thrown once, to the engine's call that meets it; the calls after it (the engine unwinding) are
    // ignored.
    if (failure_reported_)
      return;
    failure_reported_ = true;
    std::rethrow_exception(failure_);
  }
  queue_.push_back(std::move(pending_));
  pending_.clear();
  pending_.reserve(block_);
  lock.unlock();
  not_empty_.notify_one();
}

void AsyncObserver::work() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    not_empty_.wait(lock, [&] { return !queue_.empty() || stopping_; });
    if (stopping_)
      return;
    std::vector<Call> calls = std::move(queue_.front());
    queue_.pop_front();
    busy_ = true;
    lock.unlock();
    not_full_.notify_one();
    std::exception_ptr failure;
    try {
      for (const Call& call : calls) {
        switch (call.kind) {
        case Kind::initial: next_.initial(call.time, call.complex); break;
        case Kind::batch: next_.batch(call.time, call.steps); break;
        case Kind::frame: next_.frame(call.frame, call.time); break;
        case Kind::finish: next_.finish(call.time); break;
        }
      }
    } catch (...) {
      failure = std::current_exception();
    }
    calls.clear(); // freed here, on the worker: the engine's thread does not pay for it
    lock.lock();
    busy_ = false;
    if (failure) {
      failure_ = failure;
      failed_.store(true, std::memory_order_release);
      queue_.clear(); // nothing after a failed call reaches the inner observer
    }
    if (failure || queue_.empty())
      drained_.notify_all();
    if (failure)
      not_full_.notify_all();
  }
}

void AsyncObserver::initial(const kinetic::EventTime& t0, const std::vector<kinetic::Simplex>& complex) {
  push({Kind::initial, t0, 0, complex, {}});
}

void AsyncObserver::batch(const kinetic::EventTime& time, const std::vector<kinetic::Step>& steps) {
  push({Kind::batch, time, 0, {}, steps});
}

void AsyncObserver::frame(std::size_t k, const kinetic::EventTime& time) {
  push({Kind::frame, time, k, {}, {}});
}

void AsyncObserver::finish(const kinetic::EventTime& t_end) {
  pending_.push_back({Kind::finish, t_end, 0, {}, {}});
  hand_over(); // throws a failure not thrown yet
  std::unique_lock<std::mutex> lock(mutex_);
  drained_.wait(lock, [&] { return (queue_.empty() && !busy_) || failure_; });
  // Thrown again if an earlier call threw it already: a finish() that returns means a complete run.
  if (failure_) {
    failure_reported_ = true;
    std::rethrow_exception(failure_);
  }
}

} // namespace medusa
