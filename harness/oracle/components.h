#pragma once
// The one to four components of a GLSL vector, held in place. `snell eval`
// answers a million calls a second or so, and a heap vector per field of
// each answer (value, strict, lo, hi, undefined, per way) made the
// allocator a fifth of its time.
#include <algorithm>
#include <array>
#include <cstddef>
#include <initializer_list>
#include <span>
#include <stdexcept>
#include <vector>

namespace snell {

template <class T>
class Components {
 public:
  static constexpr std::size_t kCapacity = 4;

  Components() = default;
  Components(std::initializer_list<T> values) { assign(values.begin(), values.end()); }
  explicit Components(std::span<const T> values) { assign(values.begin(), values.end()); }

  template <class It>
  void assign(It first, It last) {
    size_ = 0;
    for (; first != last; ++first) push_back(static_cast<T>(*first));
  }
  void push_back(const T& value) {
    if (size_ == kCapacity) throw std::length_error("a GLSL vector has at most 4 components");
    values_[size_++] = value;
  }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T& operator[](std::size_t k) { return values_[k]; }
  const T& operator[](std::size_t k) const { return values_[k]; }
  T* begin() { return values_.data(); }
  T* end() { return values_.data() + size_; }
  const T* begin() const { return values_.data(); }
  const T* end() const { return values_.data() + size_; }

  // For code that keeps components in its own vectors (records, sweeps).
  operator std::vector<T>() const {  // NOLINT(google-explicit-constructor)
    return std::vector<T>(begin(), end());
  }

  friend bool operator==(const Components& a, const Components& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end());
  }

 private:
  std::array<T, kCapacity> values_{};
  std::size_t size_ = 0;
};

}  // namespace snell
