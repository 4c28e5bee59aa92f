// The asynchronous observer (medusa/medusa/async_observer.h): the inner observer sees the engine's
// calls unchanged and in order, from copies; a failure of the inner observer reaches the caller.
// Oracle: the same random streams (random_stream.h) played directly into the same observer.
#include "medusa/medusa/async_observer.h"
#include "medusa/medusa/medusa.h"
#include "medusa/medusa/medusa_builder.h"
#include "random_stream.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using medusa::AsyncObserver;
using medusa::test::EventTime;
using medusa::test::Simplex;
using medusa::test::Step;

namespace {

std::string text(const Simplex& s) {
  std::string out = "[";
  for (auto v : s)
    out += std::to_string(v) + " ";
  return out + "]";
}

// Every call as one line of text, with everything the observer receives.
class Recorder : public medusa::kinetic::Observer {
public:
  std::vector<std::string> calls;
  // Throws from the call with this index (counted from 0), if any.
  std::size_t fail_at = static_cast<std::size_t>(-1);

  void initial(const EventTime& t0, const std::vector<Simplex>& complex) override {
    std::ostringstream out;
    out << "initial " << t0.batch << " " << t0.time << ":";
    for (const Simplex& s : complex)
      out << text(s);
    record(out.str());
  }
  void batch(const EventTime& time, const std::vector<Step>& steps) override {
    std::ostringstream out;
    out << "batch " << time.batch << " " << time.slab << " " << time.u << " " << time.time << " "
        << time.at_frame;
    for (const Step& s : steps) {
      out << " | " << s.rank << " " << medusa::kinetic::to_string(s.kind) << " v" << s.vertex << " +";
      for (const Simplex& x : s.entered)
        out << text(x);
      out << " -";
      for (const Simplex& x : s.left)
        out << text(x);
      if (s.flip)
        out << " flip " << s.flip->vertices.size() << " " << s.flip->in_alpha;
      out << " groups " << s.groups.size() << " del " << s.delaunay_removed.size() << "/"
          << s.delaunay_created.size();
    }
    record(out.str());
  }
  void frame(std::size_t k, const EventTime& time) override {
    record("frame " + std::to_string(k) + " " + std::to_string(time.batch));
  }
  void finish(const EventTime& t_end) override { record("finish " + std::to_string(t_end.batch)); }

private:
  void record(std::string line) {
    if (calls.size() == fail_at) {
      calls.push_back("failed: " + line);
      throw std::runtime_error("store: disk full at call " + std::to_string(fail_at));
    }
    calls.push_back(std::move(line));
  }
};

} // namespace

TEST_CASE("an asynchronous observer passes on every call of the stream unchanged and in order") {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    INFO("random stream seed " << seed);
    medusa::test::RandomStreamOptions options;
    options.batches_per_slab = 6;
    const medusa::test::Stream stream = medusa::test::random_stream(seed, options);
    Recorder direct, delayed;
    stream.play(direct);
    {
      // Blocks of 1-4 calls and queues of 1-3 blocks: the caller often waits for the worker.
      AsyncObserver async(delayed, seed % 4 + 1, seed % 3 + 1);
      stream.play(async);
    }
    REQUIRE(direct.calls.size() > 10);
    CHECK(delayed.calls == direct.calls);
  }
}

TEST_CASE("an asynchronous observer copies each call, so the caller may reuse its vectors at once") {
  Recorder direct, delayed;
  const medusa::test::Stream stream = medusa::test::random_stream(7);
  stream.play(direct);
  {
    AsyncObserver async(delayed, 1, 1024); // each call handed over at once, and the caller runs ahead
    async.initial(stream.t0, stream.initial);
    for (std::size_t k : stream.frames_after_initial)
      async.frame(k, stream.t0);
    std::vector<Step> reused;
    for (const auto& b : stream.batches) {
      reused = b.steps;
      async.batch(b.time, reused);
      for (std::size_t k : b.frames_after)
        async.frame(k, b.time);
      reused.assign(3, Step{}); // the engine's scratch, overwritten right after the call
    }
    async.finish(stream.t_end);
  }
  CHECK(delayed.calls == direct.calls);
}

TEST_CASE(
    "a failure of the inner observer is thrown to the caller at a later call and again by finish, and stops "
    "the calls after it") {
  const medusa::test::Stream stream = medusa::test::random_stream(3);
  Recorder inner;
  inner.fail_at = 4;
  std::vector<std::string> caught;
  bool finish_threw = false;
  {
    AsyncObserver async(inner, 1, 2);
    auto call = [&](auto&& f) {
      try {
        f();
      } catch (const std::runtime_error& e) {
        caught.push_back(e.what());
      }
    };
    call([&] { async.initial(stream.t0, stream.initial); });
    for (const auto& b : stream.batches)
      call([&] { async.batch(b.time, b.steps); });
    try {
      async.finish(stream.t_end);
    } catch (const std::runtime_error& e) {
      finish_threw = std::string(e.what()) == "store: disk full at call 4";
    }
  }
  REQUIRE(stream.batches.size() > 6);
  // Once among the calls after the failure (the worker may still be busy with the next ones), then
  // finish() again: a finish() that returns means every call went through.
  REQUIRE(caught.size() == 1);
  CHECK(caught.front() == "store: disk full at call 4");
  CHECK(finish_threw);
  // Calls 0-3 went through, call 4 failed, and none after it reached the inner observer.
  REQUIRE(inner.calls.size() == 5);
  CHECK(inner.calls.back().rfind("failed: batch", 0) == 0);
}

TEST_CASE("a failure of the inner observer's own finish is thrown by finish") {
  const medusa::test::Stream stream = medusa::test::random_stream(5);
  Recorder direct;
  stream.play(direct);
  Recorder inner;
  inner.fail_at = direct.calls.size() - 1; // the last call: finish
  {
    AsyncObserver async(inner); // the defaults: the whole stream fits in one block
    stream.play_events(async);
    CHECK_THROWS_WITH(async.finish(stream.t_end),
                      "store: disk full at call " + std::to_string(inner.fail_at));
  }
  CHECK(inner.calls.size() == direct.calls.size());
  CHECK(inner.calls.back().rfind("failed: finish", 0) == 0);
}

TEST_CASE(
    "an asynchronous observer destroyed without finish drops the calls still queued and never finishes") {
  // The engine failed or was interrupted: the observer is destroyed mid-stream.
  const medusa::test::Stream stream = medusa::test::random_stream(9);
  Recorder direct, inner;
  stream.play(direct);
  {
    AsyncObserver async(inner, 1, 1000);
    stream.play_events(async);
  }
  // How far the worker got is up to the scheduler; what it passed on is a prefix of the stream.
  REQUIRE(inner.calls.size() < direct.calls.size());
  CHECK(std::equal(inner.calls.begin(), inner.calls.end(), direct.calls.begin()));
  for (const std::string& c : inner.calls)
    CHECK(c.rfind("finish", 0) != 0);
}

TEST_CASE("the medusa built through an asynchronous observer equals the one built directly") {
  for (std::uint64_t seed = 100; seed < 110; ++seed) {
    INFO("random stream seed " << seed);
    const medusa::test::Stream stream = medusa::test::random_stream(seed);
    medusa::MedusaCollector direct_sink, async_sink;
    {
      medusa::MedusaBuilder builder(direct_sink);
      stream.play(builder);
    }
    {
      medusa::MedusaBuilder builder(async_sink);
      // Small blocks, and the defaults `medusa run` uses.
      auto async = seed % 2 == 0 ? std::make_unique<AsyncObserver>(builder, 3, 2)
                                 : std::make_unique<AsyncObserver>(builder);
      stream.play(*async);
    }
    const auto& a = direct_sink.medusa().cells;
    const auto& b = async_sink.medusa().cells;
    REQUIRE(a.size() > 0);
    REQUIRE(a.size() == b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      CHECK(a[i].id == b[i].id);
      CHECK(a[i].vertices == b[i].vertices);
      CHECK(a[i].birth == b[i].birth);
      CHECK(a[i].death == b[i].death);
      CHECK(a[i].kind == b[i].kind);
      CHECK(a[i].facets == b[i].facets);
    }
  }
}
