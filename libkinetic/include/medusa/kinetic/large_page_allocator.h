// An allocator that asks for transparent huge pages (2 MiB) for blocks of 2 MiB and more. The
// engine's hash tables are hundreds of megabytes at 100,000 cells and gigabytes at a million, and
// every look-up lands at random in them: with 4 KiB pages nearly each also misses the TLB, whose
// reach is a few megabytes. Debian's default transparent-huge-page mode is "madvise", which gives
// huge pages only to memory that asks for them (bench/README.md, "Huge pages").
#pragma once

#include <cstddef>
#include <cstdlib>
#include <limits>
#include <memory>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace medusa::kinetic {

template <class T> struct LargePageAllocator {
  using value_type = T;
  static constexpr std::size_t huge_page = std::size_t{2} << 20;

  LargePageAllocator() = default;
  template <class U> LargePageAllocator(const LargePageAllocator<U>&) noexcept {} // NOLINT: rebinding

  T* allocate(std::size_t n) {
    if (n > std::numeric_limits<std::size_t>::max() / sizeof(T))
      throw std::bad_array_new_length();
    if (n * sizeof(T) < huge_page)
      return std::allocator<T>().allocate(n);
    const std::size_t bytes = rounded(n);
    void* p = std::aligned_alloc(huge_page, bytes);
    if (p == nullptr)
      throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    // Advice only: where huge pages are off or short, the block keeps small pages.
    madvise(p, bytes, MADV_HUGEPAGE);
#endif
    return static_cast<T*>(p);
  }

  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) < huge_page)
      std::allocator<T>().deallocate(p, n);
    else
      std::free(p);
  }

  friend bool operator==(const LargePageAllocator&, const LargePageAllocator&) { return true; }
  friend bool operator!=(const LargePageAllocator&, const LargePageAllocator&) { return false; }

private:
  static std::size_t rounded(std::size_t n) {
    return (n * sizeof(T) + huge_page - 1) / huge_page * huge_page;
  }
};

// A vector whose large blocks ask for huge pages.
template <class T> using LargeVector = std::vector<T, LargePageAllocator<T>>;

} // namespace medusa::kinetic
