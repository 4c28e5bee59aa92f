// A fingerprint of the kinetic engine's whole event stream (observer.h): a 64-bit FNV-1a hash over a
// canonical serialisation of every callback, and counts of what the stream holds. Two engines with
// equal fingerprints on a run emit the same batches at the same double times with the same steps,
// ranks, simplices, flip groups, degenerate groups and vertices.
//
// Sequences keep the order the engine reports them in (batches, steps of a batch, entered and left,
// which observer.h defines as sorted); lists that the stream defines as sets (the Delaunay simplices
// a step removed or created, the degenerate groups of a repair) are hashed sorted, so that only the
// information in the stream counts, not the order a triangulation happens to visit its cells in.
#pragma once

#include "medusa/kinetic/observer.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace medusa::kinetic::testing {

class StreamDigest : public Observer {
public:
  static constexpr std::size_t step_kinds = 9; // StepKind::radius .. StepKind::flip22

  std::uint64_t hash = 0xcbf29ce484222325ull;
  std::size_t batches = 0, frame_batches = 0, frames = 0, steps = 0, entered = 0, left = 0;
  std::size_t flips_in_alpha = 0, degenerate_groups = 0;
  std::array<std::size_t, step_kinds> by_kind{};

  void initial(const EventTime& t0, const std::vector<Simplex>& complex) override {
    tag('I');
    time(t0);
    simplices(complex);
  }
  void batch(const EventTime& t, const std::vector<Step>& batch_steps) override {
    ++batches;
    frame_batches += t.at_frame ? 1 : 0;
    tag('B');
    time(t);
    word(batch_steps.size());
    for (const Step& s : batch_steps)
      step(s);
  }
  void frame(std::size_t k, const EventTime& t) override {
    ++frames;
    tag('F');
    word(k);
    time(t);
  }
  void finish(const EventTime& t) override {
    tag('E');
    time(t);
  }

  // "batches=... steps=... step_<kind>=... entered=... left=..." then the digest as 16 hex digits.
  std::string counts() const {
    std::string out = "batches=" + std::to_string(batches) +
                      " frame_batches=" + std::to_string(frame_batches) +
                      " frames=" + std::to_string(frames) + " steps=" + std::to_string(steps);
    for (std::size_t k = 0; k < step_kinds; ++k)
      out += std::string(" step_") + to_string(static_cast<StepKind>(k)) + "=" + std::to_string(by_kind[k]);
    out += " flips_in_alpha=" + std::to_string(flips_in_alpha) +
           " degenerate_groups=" + std::to_string(degenerate_groups) + " entered=" + std::to_string(entered) +
           " left=" + std::to_string(left);
    return out;
  }
  std::string digest() const {
    char buffer[17];
    std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(hash));
    return buffer;
  }

private:
  void bytes(const void* p, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) {
      hash ^= b[i];
      hash *= 0x100000001b3ull;
    }
  }
  void tag(char c) { bytes(&c, 1); }
  void word(std::uint64_t x) { bytes(&x, sizeof x); }
  void real(double x) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &x, sizeof bits);
    word(bits);
  }
  void time(const EventTime& t) {
    word(t.batch);
    word(t.slab);
    real(t.u);
    real(t.time);
    word(t.at_frame ? 1 : 0);
  }
  void vertices(const VertexId* first, const VertexId* last) {
    word(static_cast<std::uint64_t>(last - first));
    for (; first != last; ++first)
      word(static_cast<std::uint64_t>(static_cast<std::int64_t>(*first)));
  }
  void simplices(const std::vector<Simplex>& list) {
    word(list.size());
    for (const Simplex& s : list)
      vertices(s.begin(), s.end());
  }
  void simplex_set(std::vector<Simplex> list) {
    std::sort(list.begin(), list.end());
    simplices(list);
  }
  void step(const Step& s) {
    ++steps;
    ++by_kind[static_cast<std::size_t>(s.kind)];
    entered += s.entered.size();
    left += s.left.size();
    tag('S');
    word(s.rank);
    word(static_cast<std::uint64_t>(s.kind));
    simplices(s.entered);
    simplices(s.left);
    word(s.flip ? 1 : 0);
    if (s.flip) {
      flips_in_alpha += s.flip->in_alpha ? 1 : 0;
      vertices(s.flip->vertices.data(), s.flip->vertices.data() + s.flip->vertices.size());
      word(s.flip->in_alpha ? 1 : 0);
    }
    std::vector<std::vector<VertexId>> groups;
    for (const DegenerateGroup& g : s.groups)
      groups.push_back(g.vertices);
    std::sort(groups.begin(), groups.end());
    degenerate_groups += groups.size();
    word(groups.size());
    for (const auto& g : groups)
      vertices(g.data(), g.data() + g.size());
    word(static_cast<std::uint64_t>(static_cast<std::int64_t>(s.vertex)));
    simplex_set(s.delaunay_removed);
    simplex_set(s.delaunay_created);
  }
};

} // namespace medusa::kinetic::testing
