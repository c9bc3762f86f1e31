#pragma once
// The bytes of one stored result (core/keyed_file_store.h): a header that
// names the format, the kind of result, the key it was stored under and the
// digest of the payload, then the payload. A file that was cut short,
// damaged, written by another format or kind, or under another key opens
// as nothing, so a reader never takes a wrong or partial result for a
// right one.
//
// ByteWriter and ByteReader write and read the payload's fields; every
// read is checked against the end, so damaged bytes give ok() == false,
// never an out-of-bounds read or a huge allocation.
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/content_hash.h"

namespace snell {

// Who wrote a record and what it holds: `magic` names the store (8
// characters), `format` its layout version, `kind` the result type.
struct RecordTag {
  char magic[8];
  std::uint32_t format;
  std::uint32_t kind;
};
// `magic` is exactly 8 characters (a literal's terminating NUL is left out).
inline RecordTag recordTag(const char (&magic)[9], std::uint32_t format, std::uint32_t kind) {
  RecordTag tag{};
  std::memcpy(tag.magic, magic, sizeof tag.magic);
  tag.format = format;
  tag.kind = kind;
  return tag;
}

std::string sealRecord(const RecordTag& tag, const Digest& key, std::string_view payload);
// The payload, when the header matches `tag` and `key` and the payload is
// whole; a view into `bytes`.
std::optional<std::string_view> openRecord(const RecordTag& tag, const Digest& key,
                                           std::string_view bytes);

class ByteWriter {
 public:
  template <typename T>
  requires std::is_trivially_copyable_v<T>
  void put(const T& value) { out_.append(reinterpret_cast<const char*>(&value), sizeof value); }
  void put(const std::string& text) {
    put(static_cast<std::uint64_t>(text.size()));
    out_ += text;
  }
  template <typename T>
  void putArray(const std::vector<T>& values) {
    put(static_cast<std::uint64_t>(values.size()));
    out_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
  }
  std::string take() { return std::move(out_); }

 private:
  std::string out_;
};

class ByteReader {
 public:
  explicit ByteReader(std::string_view bytes)
      : at_(bytes.data()), end_(bytes.data() + bytes.size()) {}
  bool ok() const { return ok_; }
  bool atEnd() const { return at_ == end_; }
  // Marks the bytes as not holding together (a value out of its range).
  void fail() { ok_ = false; }

  template <typename T>
  requires std::is_trivially_copyable_v<T> T get() {
    T value{};
    if (!take(&value, sizeof value)) return T{};
    return value;
  }
  std::string getString() {
    const auto size = get<std::uint64_t>();
    if (!fits(size, 1)) return {};
    std::string text(at_, size);
    at_ += size;
    return text;
  }
  template <typename T>
  std::vector<T> getArray() {
    const auto count = get<std::uint64_t>();
    if (!fits(count, sizeof(T))) return {};
    std::vector<T> values(count);
    take(values.data(), count * sizeof(T));
    return values;
  }
  // An array written as Stored, read as Out (floats widened to doubles),
  // without a Stored copy in between.
  template <typename Stored, typename Out>
  requires std::is_trivially_copyable_v<Stored> std::vector<Out> getArrayAs() {
    const auto count = get<std::uint64_t>();
    if (!fits(count, sizeof(Stored))) return {};
    std::vector<Out> values(count);
    for (Out& value : values) {
      Stored stored;
      std::memcpy(&stored, at_, sizeof stored);
      at_ += sizeof stored;
      value = static_cast<Out>(stored);
    }
    return values;
  }

 private:
  bool fits(std::uint64_t count, std::size_t size) {
    if (ok_ && count <= static_cast<std::uint64_t>(end_ - at_) / size) return true;
    ok_ = false;
    return false;
  }
  bool take(void* out, std::size_t size) {
    if (!fits(size, 1)) return false;
    std::memcpy(out, at_, size);
    at_ += size;
    return true;
  }
  const char* at_;
  const char* end_;
  bool ok_ = true;
};

}  // namespace snell
