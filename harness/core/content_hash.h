#pragma once
// A 128-bit digest of a byte stream (XXH3-128), for content-addressed
// files: two streams with the same digest are taken to be the same stream.
// Fields are added with their lengths, so ("ab", "c") and ("a", "bc")
// differ.
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>

namespace snell {

struct Digest {
  std::array<std::uint8_t, 16> bytes{};
  std::string hex() const;  // 32 lowercase hex digits
  bool operator==(const Digest&) const = default;
};

class ContentHash {
 public:
  ContentHash();
  ~ContentHash();
  ContentHash(const ContentHash&) = delete;
  ContentHash& operator=(const ContentHash&) = delete;

  void addBytes(const void* data, std::size_t size);
  void add(std::string_view text);  // length first, then the bytes
  template <typename T>
  requires std::is_arithmetic_v<T> || std::is_enum_v<T>
  void add(T value) { addBytes(&value, sizeof value); }
  Digest finish() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

Digest digestOf(std::string_view bytes);

}  // namespace snell
