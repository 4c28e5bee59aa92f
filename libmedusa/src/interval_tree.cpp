#include "medusa/medusa/interval_tree.h"

#include <algorithm>

namespace medusa {

IntervalTree::IntervalTree(std::vector<Interval> intervals) {
  intervals.erase(
      std::remove_if(intervals.begin(), intervals.end(), [](const Interval& i) { return i.lo >= i.hi; }),
      intervals.end());
  size_ = intervals.size();
  nodes_.reserve(intervals.size());
  root_ = build(std::move(intervals));
}

std::int64_t IntervalTree::build(std::vector<Interval> items) {
  if (items.empty())
    return -1;
  // The centre is the median left end: that interval contains it, so every node keeps at least one
  // interval and each side gets at most half of the left ends, hence depth O(log n).
  std::vector<std::uint64_t> los(items.size());
  std::transform(items.begin(), items.end(), los.begin(), [](const Interval& i) { return i.lo; });
  std::nth_element(los.begin(), los.begin() + static_cast<std::ptrdiff_t>(los.size() / 2), los.end());
  const std::uint64_t center = los[los.size() / 2];
  std::vector<Interval> left, right, here;
  for (const Interval& i : items) {
    if (i.hi <= center)
      left.push_back(i);
    else if (i.lo > center)
      right.push_back(i);
    else
      here.push_back(i);
  }
  items.clear();
  items.shrink_to_fit();
  const std::int64_t index = static_cast<std::int64_t>(nodes_.size());
  nodes_.emplace_back();
  nodes_[static_cast<std::size_t>(index)].center = center;
  std::vector<Interval> by_hi = here;
  std::sort(here.begin(), here.end(), [](const Interval& a, const Interval& b) { return a.lo < b.lo; });
  std::sort(by_hi.begin(), by_hi.end(), [](const Interval& a, const Interval& b) { return a.hi > b.hi; });
  nodes_[static_cast<std::size_t>(index)].by_lo = std::move(here);
  nodes_[static_cast<std::size_t>(index)].by_hi = std::move(by_hi);
  const std::int64_t l = build(std::move(left));
  const std::int64_t r = build(std::move(right));
  nodes_[static_cast<std::size_t>(index)].left = l;
  nodes_[static_cast<std::size_t>(index)].right = r;
  return index;
}

void IntervalTree::stab(std::uint64_t x, std::vector<std::uint64_t>& out) const {
  std::int64_t n = root_;
  while (n >= 0) {
    const Node& node = nodes_[static_cast<std::size_t>(n)];
    if (x < node.center) {
      // Every interval here ends after the centre, so it contains x iff it starts at or before x.
      for (const Interval& i : node.by_lo) {
        if (i.lo > x)
          break;
        out.push_back(i.value);
      }
      n = node.left;
    } else if (x > node.center) {
      for (const Interval& i : node.by_hi) {
        if (i.hi <= x)
          break;
        out.push_back(i.value);
      }
      n = node.right;
    } else {
      for (const Interval& i : node.by_lo)
        out.push_back(i.value);
      return;
    }
  }
}

} // namespace medusa
