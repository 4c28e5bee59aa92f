// A list of plain values held in place up to N of them, on the heap beyond: a medusa cell's vertices
// and facets. A medusa holds millions of cells with at most four vertices each, and two heap vectors
// per cell cost more than the values they hold (a 3D run's instant cells can have five, and the cells
// of a static repair any number, docs/MATH.md §6.3, so a fixed array is not enough).
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <iterator>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace medusa {

template <class T, std::uint32_t N> class SmallList {
  static_assert(std::is_trivially_copyable_v<T>, "SmallList copies its values as bytes");
  static_assert(N >= 1);

public:
  using value_type = T;
  using size_type = std::size_t;
  using iterator = T*;
  using const_iterator = const T*;
  using reference = T&;
  using const_reference = const T&;

  SmallList() = default;
  SmallList(std::initializer_list<T> values) { assign(values.begin(), values.end()); }
  template <class It, class = typename std::iterator_traits<It>::iterator_category>
  SmallList(It first, It last) {
    assign(first, last);
  }
  explicit SmallList(const std::vector<T>& values) { assign(values.begin(), values.end()); }
  SmallList(const SmallList& other) { assign(other.begin(), other.end()); }
  SmallList(SmallList&& other) noexcept { take(other); }
  SmallList& operator=(const SmallList& other) {
    if (this != &other)
      assign(other.begin(), other.end());
    return *this;
  }
  SmallList& operator=(SmallList&& other) noexcept {
    if (this != &other) {
      release();
      take(other);
    }
    return *this;
  }
  SmallList& operator=(std::initializer_list<T> values) {
    assign(values.begin(), values.end());
    return *this;
  }
  SmallList& operator=(const std::vector<T>& values) {
    assign(values.begin(), values.end());
    return *this;
  }
  ~SmallList() { release(); }

  template <class It> void assign(It first, It last) {
    const auto n = static_cast<std::size_t>(std::distance(first, last));
    size_ = 0;
    reserve(n);
    std::copy(first, last, data());
    size_ = static_cast<std::uint32_t>(n);
  }

  std::vector<T> to_vector() const { return {begin(), end()}; }

  size_type size() const { return size_; }
  bool empty() const { return size_ == 0; }
  size_type capacity() const { return capacity_; }
  // True while the values are held in place (no heap block).
  bool is_inline() const { return capacity_ == N; }

  T* data() { return is_inline() ? local_ : heap_; }
  const T* data() const { return is_inline() ? local_ : heap_; }
  iterator begin() { return data(); }
  iterator end() { return data() + size_; }
  const_iterator begin() const { return data(); }
  const_iterator end() const { return data() + size_; }
  T& operator[](size_type i) { return data()[i]; }
  const T& operator[](size_type i) const { return data()[i]; }
  T& front() { return data()[0]; }
  const T& front() const { return data()[0]; }
  T& back() { return data()[size_ - 1]; }
  const T& back() const { return data()[size_ - 1]; }

  void reserve(size_type n) {
    if (n <= capacity_)
      return;
    if (n > UINT32_MAX)
      throw std::bad_alloc();
    const auto grown = std::max<size_type>(n, 2 * static_cast<size_type>(capacity_));
    const auto capacity = static_cast<std::uint32_t>(std::min<size_type>(grown, UINT32_MAX));
    T* block = static_cast<T*>(::operator new(sizeof(T) * capacity));
    std::memcpy(static_cast<void*>(block), static_cast<const void*>(data()), sizeof(T) * size_);
    release();
    heap_ = block;
    capacity_ = capacity;
  }
  void push_back(const T& value) {
    if (size_ == capacity_) {
      const T copy = value; // value may live in this list
      reserve(size_ + 1);
      data()[size_++] = copy;
      return;
    }
    data()[size_++] = value;
  }
  template <class... Args> T& emplace_back(Args&&... args) {
    push_back(T(std::forward<Args>(args)...));
    return back();
  }
  void pop_back() { --size_; }
  void resize(size_type n) {
    reserve(n);
    std::fill(data() + size_, data() + std::max<size_type>(n, size_), T());
    size_ = static_cast<std::uint32_t>(n);
  }
  void clear() { size_ = 0; }

  friend bool operator==(const SmallList& a, const SmallList& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end());
  }
  friend bool operator!=(const SmallList& a, const SmallList& b) { return !(a == b); }
  friend bool operator<(const SmallList& a, const SmallList& b) {
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end());
  }
  friend bool operator==(const SmallList& a, const std::vector<T>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end());
  }
  friend bool operator==(const std::vector<T>& a, const SmallList& b) { return b == a; }
  friend bool operator!=(const SmallList& a, const std::vector<T>& b) { return !(a == b); }
  friend bool operator!=(const std::vector<T>& a, const SmallList& b) { return !(b == a); }

private:
  void release() {
    if (!is_inline())
      ::operator delete(heap_);
    capacity_ = N;
  }
  // Takes other's values; leaves other empty and inline.
  void take(SmallList& other) {
    size_ = other.size_;
    capacity_ = other.capacity_;
    if (other.is_inline())
      std::memcpy(static_cast<void*>(local_), static_cast<const void*>(other.local_), sizeof(T) * size_);
    else
      heap_ = other.heap_;
    other.size_ = 0;
    other.capacity_ = N;
  }

  std::uint32_t size_ = 0;
  std::uint32_t capacity_ = N; // N: the values are in local_; above N: in heap_
  // heap_ starts null, so that no path reads an indeterminate pointer (GCC cannot tell that
  // capacity_ == N means local_ holds the values).
  union {
    T* heap_ = nullptr;
    T local_[N];
  };
};

} // namespace medusa
