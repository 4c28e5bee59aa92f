// The event stream of the covering space turned into the stream of the complex on the torus
// (docs/MATH.md §8.5): only canonical simplices pass, named by their originals' vertex ids, and the
// steps that are periodic copies of one event on the torus are merged into one step.
#pragma once

#include "medusa/kinetic/observer.h"
#include "medusa/periodic/periodic_cover.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace medusa::periodic {

// A covering simplex (or vertex set) is canonical when its vertex of smallest original id is an
// original; then its image on the torus is the sorted original ids. std::nullopt otherwise. Throws
// InternalError if two of its vertices are copies of one original (the quotient would not be
// simplicial; excluded by 4 rho < L, docs/MATH.md §8.3).
std::optional<std::vector<kinetic::VertexId>> canonical_image(const PeriodicCover& cover,
                                                              const std::vector<kinetic::VertexId>& vertices);

// Sits between the kinetic engine (run on cover.trajectories) and the medusa builder. Batches left
// without a canonical change are dropped and the others renumbered 1, 2, ... in order; frames report
// the last batch passed on; t_end follows it.
class CanonicalFilter : public kinetic::Observer {
public:
  CanonicalFilter(const PeriodicCover& cover, kinetic::Observer& next) : cover_(cover), next_(next) {}

  void initial(const kinetic::EventTime& t0, const std::vector<kinetic::Simplex>& complex) override;
  void batch(const kinetic::EventTime& time, const std::vector<kinetic::Step>& steps) override;
  void frame(std::size_t k, const kinetic::EventTime& time) override;
  void finish(const kinetic::EventTime& t_end) override;

  std::size_t batches_passed() const { return passed_; }
  std::size_t batches_dropped() const { return dropped_; }

private:
  std::optional<kinetic::Simplex> canonical(const kinetic::Simplex& s) const;

  const PeriodicCover& cover_;
  kinetic::Observer& next_;
  std::size_t batch_ = 0; // number of the last batch passed on
  std::size_t passed_ = 0, dropped_ = 0;
};

} // namespace medusa::periodic
