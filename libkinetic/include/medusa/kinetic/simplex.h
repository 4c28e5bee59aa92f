// A simplex of the Delaunay triangulation / alpha complex: up to four sorted vertex ids.
#pragma once

#include <algorithm>
#include <array>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <initializer_list>
#include <ostream>
#include <utility>

namespace medusa::kinetic {

// Index of a trajectory (a medusa vertex). A CompuCell3D cell id maps to one trajectory, or to
// several when the cell is missing from intermediate frames (docs/MATH.md §2.1).
using VertexId = std::int32_t;

// A finite simplex of dimension 0..3, vertices sorted ascending.
class Simplex {
public:
  Simplex() = default;
  Simplex(std::initializer_list<VertexId> vertices) {
    for (VertexId v : vertices)
      v_[size_++] = v;
    sort();
  }
  template <class It> static Simplex from_range(It first, It last) {
    Simplex s;
    for (; first != last; ++first)
      s.v_[s.size_++] = *first;
    s.sort();
    return s;
  }
  // n vertices already in increasing order, v[0..n), and -1 in v's other entries. Sorting reads back,
  // as wider words, entries just written one by one, which stalls each load on the stores: a flip's
  // touched faces, subsets of a sorted vertex set taken in registers, skip that.
  static Simplex from_sorted(const std::array<VertexId, 4>& v, std::size_t n) {
    Simplex s;
    s.v_ = v;
    s.size_ = static_cast<std::uint8_t>(n);
    assert(
        n <= 4 && std::is_sorted(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(n)) &&
        std::all_of(v.begin() + static_cast<std::ptrdiff_t>(n), v.end(), [](VertexId x) { return x == -1; }));
    return s;
  }

  // The four entries, -1 past the last vertex (the key FlatSimplexMap's FiniteKeys stores).
  const std::array<VertexId, 4>& padded() const { return v_; }

  int dim() const { return static_cast<int>(size_) - 1; }
  std::size_t size() const { return size_; }
  VertexId operator[](std::size_t i) const { return v_[i]; }
  const VertexId* begin() const { return v_.data(); }
  const VertexId* end() const { return v_.data() + size_; }
  // A plain loop: std::find is not inlined here, and this runs for every incident top simplex of
  // every face the frontier and membership rules look at (docs/MATH.md §4.4, §4.5).
  bool contains(VertexId x) const {
    for (std::size_t i = 0; i < size_; ++i)
      if (v_[i] == x)
        return true;
    return false;
  }

  // The facet without the i-th vertex.
  Simplex facet(std::size_t i) const {
    Simplex s;
    for (std::size_t j = 0; j < size_; ++j)
      if (j != i)
        s.v_[s.size_++] = v_[j];
    return s;
  }

  // The simplex with one more vertex x, not among its vertices (a coface: {inf} + e, or s + x).
  Simplex with(VertexId x) const {
    Simplex s;
    std::size_t i = 0;
    for (; i < size_ && v_[i] < x; ++i)
      s.v_[s.size_++] = v_[i];
    s.v_[s.size_++] = x;
    for (; i < size_; ++i)
      s.v_[s.size_++] = v_[i];
    return s;
  }

  // Unused slots hold -1, so the four entries decide. Compared as two 64-bit words without a branch
  // between them: hash tables compare keys often, and entries that differ in a late vertex made the
  // chain of four tests mispredict.
  friend bool operator==(const Simplex& a, const Simplex& b) {
    return same_entries(a.v_, b.v_) & (a.size_ == b.size_);
  }
  static bool same_entries(const std::array<VertexId, 4>& a, const std::array<VertexId, 4>& b) {
    std::uint64_t x[2], y[2];
    std::memcpy(x, a.data(), sizeof x);
    std::memcpy(y, b.data(), sizeof y);
    return ((x[0] ^ y[0]) | (x[1] ^ y[1])) == 0;
  }
  friend bool operator!=(const Simplex& a, const Simplex& b) { return !(a == b); }
  // Order by dimension, then lexicographically: the canonical order of docs/MATH.md §5.2 and §7.2.
  // Unused slots hold -1 and sizes are equal past the first test, so the four entries decide
  // (spelled out: std::array's operator< is a library loop, and the engine sorts simplices often).
  friend bool operator<(const Simplex& a, const Simplex& b) {
    if (a.size_ != b.size_)
      return a.size_ < b.size_;
    if (a.v_[0] != b.v_[0])
      return a.v_[0] < b.v_[0];
    if (a.v_[1] != b.v_[1])
      return a.v_[1] < b.v_[1];
    if (a.v_[2] != b.v_[2])
      return a.v_[2] < b.v_[2];
    return a.v_[3] < b.v_[3];
  }
  friend std::ostream& operator<<(std::ostream& os, const Simplex& s) {
    os << '[';
    for (std::size_t i = 0; i < s.size_; ++i)
      os << (i ? " " : "") << s.v_[i];
    return os << ']';
  }

private:
  // Insertion sort: at most four elements (std::sort trips GCC 12's -Warray-bounds here).
  void sort() {
    for (std::size_t i = 1; i < size_; ++i)
      for (std::size_t j = i; j > 0 && v_[j - 1] > v_[j]; --j)
        std::swap(v_[j - 1], v_[j]);
  }

  std::array<VertexId, 4> v_{{-1, -1, -1, -1}};
  std::uint8_t size_ = 0;
  static_assert(sizeof(std::array<VertexId, 4>) == 2 * sizeof(std::uint64_t),
                "operator== reads v_ as two words");
};

struct SimplexHash {
  std::size_t operator()(const Simplex& s) const {
    std::size_t h = s.size();
    for (VertexId v : s)
      h = h * 0x9E3779B97F4A7C15ULL + static_cast<std::size_t>(v) + (h >> 29);
    // Final avalanche (MurmurHash3's fmix64): the tables take the hash modulo a prime, and sets of
    // simplices sharing vertices would otherwise crowd few buckets.
    h ^= h >> 33;
    h *= 0xFF51AFD7ED558CCDULL;
    h ^= h >> 33;
    h *= 0xC4CEB9FE1A85EC53ULL;
    h ^= h >> 33;
    return h;
  }
};

} // namespace medusa::kinetic
