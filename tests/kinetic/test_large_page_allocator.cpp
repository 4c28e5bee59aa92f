// The allocator of the engine's large tables (libkinetic/include/medusa/kinetic/large_page_allocator.h):
// blocks of 2 MiB and more start on a huge-page boundary, smaller ones come from std::allocator, and a vector
// grown across the threshold keeps its contents.
#include "medusa/kinetic/large_page_allocator.h"

#include <catch2/catch.hpp>

#include <cstdint>
#include <numeric>

using medusa::kinetic::LargePageAllocator;
using medusa::kinetic::LargeVector;

TEST_CASE("A block of at least 2 MiB starts on a huge-page boundary", "[kinetic][allocator]") {
  LargePageAllocator<std::uint64_t> a;
  constexpr std::size_t huge = std::size_t{2} << 20;
  for (std::size_t bytes : {huge, huge + 8, 3 * huge + 4096, 64 * huge}) {
    const std::size_t n = bytes / sizeof(std::uint64_t);
    std::uint64_t* p = a.allocate(n);
    CHECK(reinterpret_cast<std::uintptr_t>(p) % huge == 0);
    p[0] = 1;
    p[n - 1] = 2; // the whole block is writable
    CHECK(p[0] + p[n - 1] == 3);
    a.deallocate(p, n);
  }
}

TEST_CASE("A vector grown across the huge-page threshold keeps its contents", "[kinetic][allocator]") {
  LargeVector<std::uint32_t> v;
  for (std::uint32_t i = 0; i < 3'000'000; ++i) // 12 MB: small blocks first, then large ones
    v.push_back(i);
  std::uint64_t sum = std::accumulate(v.begin(), v.end(), std::uint64_t{0});
  CHECK(sum == std::uint64_t{2'999'999} * 3'000'000 / 2);
  v.resize(10);
  v.shrink_to_fit(); // back to a small block, freed through the other path
  CHECK(v.size() == 10);
  CHECK(v.back() == 9);
}

TEST_CASE("An allocation too large to count is refused", "[kinetic][allocator]") {
  LargePageAllocator<std::uint64_t> a;
  CHECK_THROWS_AS(a.allocate(static_cast<std::size_t>(-1) / 4), std::bad_array_new_length);
}
