#include "touched_faces.h"

#include "cell_triangulation.h"
#include "face.h"

#include <algorithm>
#include <array>
#include <cstdint>

namespace medusa::kinetic::detail {

namespace {

constexpr std::size_t max_local = TouchedFaces::max_local;

int bits(unsigned m) { return __builtin_popcount(m); }

// The non-empty subsets of {0..n-1} as bit masks, ordered by size and then lexicographically by
// their sorted indices: over a sorted vertex set this is the canonical order of simplices.
const std::vector<unsigned>& canonical_masks(std::size_t n) {
  static const std::array<std::vector<unsigned>, max_local + 1> tables = [] {
    std::array<std::vector<unsigned>, max_local + 1> t;
    for (std::size_t k = 1; k <= max_local; ++k) {
      for (unsigned m = 1; m < (1u << k); ++m)
        t[k].push_back(m);
      std::sort(t[k].begin(), t[k].end(), [](unsigned a, unsigned b) {
        if (bits(a) != bits(b))
          return bits(a) < bits(b);
        // Lexicographic on the sorted indices: the lowest differing index decides, and the mask
        // holding it comes first.
        const unsigned low = (a ^ b) & -(a ^ b);
        return (a & low) != 0;
      });
    }
    return t;
  }();
  return tables[n];
}

Simplex from_mask(const std::array<VertexId, max_local>& vertices, unsigned mask) {
  // The set bits lowest first, so the vertices ascend; four fixed steps keep them in registers.
  const std::size_t n = static_cast<std::size_t>(bits(mask));
  std::array<VertexId, 4> v;
  for (VertexId& x : v) {
    x = mask != 0 ? vertices[static_cast<std::size_t>(__builtin_ctz(mask))] : -1;
    mask &= mask - 1;
  }
  return Simplex::from_sorted(v, n);
}

// The subset enumeration; false when the top simplices span more than max_local vertices.
bool collect_local(const std::vector<Simplex>& removed, const std::vector<Simplex>& added,
                   TouchedFaces& out) {
  std::array<VertexId, max_local> vertices{};
  std::size_t n = 0;
  for (const auto* list : {&removed, &added})
    for (const Simplex& t : *list)
      for (VertexId v : t)
        if (std::find(vertices.begin(), vertices.begin() + static_cast<std::ptrdiff_t>(n), v) ==
            vertices.begin() + static_cast<std::ptrdiff_t>(n)) {
          if (n == max_local)
            return false;
          vertices[n++] = v;
        }
  // Insertion sort: at most six entries (std::sort trips GCC 12's -Warray-bounds here).
  for (std::size_t i = 1; i < n; ++i)
    for (std::size_t j = i; j > 0 && vertices[j - 1] > vertices[j]; --j)
      std::swap(vertices[j - 1], vertices[j]);
  std::array<int, 1u << max_local> delta{};
  std::uint64_t present = 0;
  for (const auto* list : {&removed, &added}) {
    const int sign = list == &removed ? -1 : 1;
    for (const Simplex& t : *list) {
      unsigned m = 0;
      for (VertexId v : t)
        m |= 1u << static_cast<unsigned>(
                 std::find(vertices.begin(), vertices.begin() + static_cast<std::ptrdiff_t>(n), v) -
                 vertices.begin());
      for (unsigned s = m; s != 0; s = (s - 1) & m) {
        present |= std::uint64_t{1} << s;
        delta[s] += sign;
      }
    }
  }
  // The infinite vertex (-1) sorts first: faces through it are not finite simplices of Del.
  const unsigned infinite = n > 0 && vertices[0] == infinite_vertex ? 1u : 0u;
  out.local = vertices;
  out.local_count = n;
  out.index_of_mask.fill(-1);
  for (unsigned m : canonical_masks(n)) {
    if (!(present >> m & 1u))
      continue;
    if ((m & infinite) == 0) {
      out.index_of_mask[m] = static_cast<std::int8_t>(out.faces.size());
      out.faces.emplace_back(from_mask(vertices, m), delta[m]);
    }
  }
  return true;
}

// The finite faces of t with k vertices: C(m, k), m its finite vertices.
std::size_t finite_faces_of_size(const Simplex& t, std::size_t k) {
  const std::size_t m = t.size() - (t[0] == infinite_vertex ? 1 : 0);
  if (k > m)
    return 0;
  std::size_t c = 1;
  for (std::size_t i = 0; i < k; ++i)
    c = c * (m - i) / (i + 1);
  return c;
}

void collect_sorted(const std::vector<Simplex>& removed, const std::vector<Simplex>& added,
                    TouchedFaces& out) {
  // Every occurrence of a face, before merging. A static rebuild of the whole triangulation lists
  // about fifteen per top simplex (10^8 for a million cells), so they are listed one size at a
  // time, each list reserved exactly: the canonical order is by size first, and the largest list
  // (the edges) is then 6/15 of all, with no vector doubling on the way.
  struct Occurrence {
    Simplex face;
    int delta;
  };
  std::size_t top_size = 0;
  for (const auto* list : {&removed, &added})
    for (const Simplex& t : *list)
      top_size = std::max(top_size, t.size());
  std::vector<Occurrence> all;
  for (std::size_t k = 1; k <= top_size; ++k) {
    std::size_t count = 0;
    for (const auto* list : {&removed, &added})
      for (const Simplex& t : *list)
        count += finite_faces_of_size(t, k);
    std::vector<Occurrence>().swap(all);
    all.reserve(count);
    for (const auto* list : {&removed, &added}) {
      const int sign = list == &removed ? -1 : 1;
      for (const Simplex& t : *list)
        for_each_face(
            t,
            [&](const Simplex& f) {
              all.push_back({f, sign});
            },
            k);
    }
    std::sort(all.begin(), all.end(),
              [](const Occurrence& a, const Occurrence& b) { return a.face < b.face; });
    std::size_t distinct = 0;
    for (std::size_t i = 0; i < all.size(); ++i)
      distinct += i == 0 || !(all[i].face == all[i - 1].face);
    out.faces.reserve(out.faces.size() + distinct);
    const std::size_t first = out.faces.size();
    for (const Occurrence& f : all)
      if (out.faces.size() > first && out.faces.back().face == f.face)
        out.faces.back().delta += f.delta;
      else
        out.faces.emplace_back(f.face, f.delta);
  }
}

} // namespace

unsigned TouchedFaces::local_mask(const Simplex& s) const {
  // Both vertex lists are sorted: one merge pass.
  unsigned mask = 0;
  std::size_t j = 0;
  for (VertexId v : s) {
    while (j < local_count && local[j] < v)
      ++j;
    if (j == local_count || local[j] != v)
      return 0;
    mask |= 1u << j++;
  }
  return mask;
}

TouchedFace* TouchedFaces::find(const Simplex& s) {
  if (local_count != 0) {
    const int index = index_of_mask[local_mask(s)]; // index_of_mask[0] is -1: no face is empty
    return index < 0 ? nullptr : &faces[static_cast<std::size_t>(index)];
  }
  auto it = std::lower_bound(faces.begin(), faces.end(), s,
                             [](const TouchedFace& f, const Simplex& key) { return f.face < key; });
  return it != faces.end() && it->face == s ? &*it : nullptr;
}

void collect_touched_faces(const std::vector<Simplex>& removed, const std::vector<Simplex>& added,
                           TouchedFaces& out) {
  out.faces.clear();
  out.local_count = 0;
  if (!collect_local(removed, added, out)) { // it gives up before setting local_count
    out.faces.clear();
    collect_sorted(removed, added, out);
  }
}

} // namespace medusa::kinetic::detail
