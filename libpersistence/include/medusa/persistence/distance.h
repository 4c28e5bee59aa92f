// The result of a distance between two diagrams of one degree (docs/MATH.md §7.7): the finite part and the
// essential part reported separately, with the essential counts.
#pragma once

#include <cstddef>

namespace medusa::persistence {

struct DistanceResult {
  double finite = 0;    // distance between the finite parts (partial matchings, diagonal allowed)
  double essential = 0; // distance between the essential parts; +inf when the counts differ
  std::size_t essential_count_a = 0;
  std::size_t essential_count_b = 0;
  double total = 0;          // finite and essential combined; the finite part alone if ignore_essential
  bool exact = true;         // false when `finite` comes from the certified approximation
  double relative_error = 0; // certified bound: finite <= (1 + relative_error) * exact finite distance
};

} // namespace medusa::persistence
