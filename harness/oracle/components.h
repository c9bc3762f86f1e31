#pragma once
// Up to a fixed number of values held in place: the one to four components
// of a GLSL vector, and the one or two ways of a built-in call. `snell eval`
// answers a million calls a second or so, and a heap vector per field of
// each answer (value, strict, lo, hi, undefined, per way, and the list of
// ways) made the allocator a fifth of its time.
#include <algorithm>
#include <array>
#include <cstddef>
#include <initializer_list>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace snell {

template <class T, std::size_t Capacity>
class InlineVector {
 public:
  static constexpr std::size_t kCapacity = Capacity;

  InlineVector() = default;
  InlineVector(std::initializer_list<T> values) { assign(values.begin(), values.end()); }
  explicit InlineVector(std::span<const T> values) { assign(values.begin(), values.end()); }

  template <class It>
  void assign(It first, It last) {
    size_ = 0;
    for (; first != last; ++first) push_back(static_cast<T>(*first));
  }
  void push_back(T value) {
    if (size_ == kCapacity)
      throw std::length_error("holds at most " + std::to_string(kCapacity) + " values");
    values_[size_++] = std::move(value);
  }
  void clear() { size_ = 0; }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T& operator[](std::size_t k) { return values_[k]; }
  const T& operator[](std::size_t k) const { return values_[k]; }
  T& back() { return values_[size_ - 1]; }
  const T& back() const { return values_[size_ - 1]; }
  T* begin() { return values_.data(); }
  T* end() { return values_.data() + size_; }
  const T* begin() const { return values_.data(); }
  const T* end() const { return values_.data() + size_; }

  // For code that keeps values in its own vectors (records, sweeps).
  operator std::vector<T>() const {  // NOLINT(google-explicit-constructor)
    return std::vector<T>(begin(), end());
  }

  friend bool operator==(const InlineVector& a, const InlineVector& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end());
  }

 private:
  std::array<T, kCapacity> values_{};
  std::size_t size_ = 0;
};

// A GLSL vector's components.
template <class T>
using Components = InlineVector<T, 4>;

}  // namespace snell
