// A static centred interval tree for stabbing queries (docs/MATH.md §6.6): O(n) space, O(n log n) build,
// O(log n + k) query.
#pragma once

#include <cstdint>
#include <vector>

namespace medusa {

class IntervalTree {
public:
  // The half-open interval [lo, hi) carrying `value`. Empty intervals (lo >= hi) are never stabbed.
  struct Interval {
    std::uint64_t lo = 0;
    std::uint64_t hi = 0;
    std::uint64_t value = 0;
  };

  IntervalTree() = default;
  explicit IntervalTree(std::vector<Interval> intervals);

  // Appends the values of every interval with lo <= x < hi (in no particular order).
  void stab(std::uint64_t x, std::vector<std::uint64_t>& out) const;
  std::size_t size() const { return size_; }

private:
  struct Node {
    std::uint64_t center = 0;
    std::int64_t left = -1;
    std::int64_t right = -1;
    std::vector<Interval> by_lo; // increasing lo
    std::vector<Interval> by_hi; // decreasing hi
  };
  std::int64_t build(std::vector<Interval> items);

  std::vector<Node> nodes_;
  std::int64_t root_ = -1;
  std::size_t size_ = 0;
};

} // namespace medusa
