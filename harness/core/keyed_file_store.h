#pragma once
// A folder of files named by a digest of what they were computed from, as
// ccache and Mesa's shader cache keep theirs: a result is written once
// under its key and read back on every later run that asks with the same
// key. What the bytes mean is the caller's (sealed_record.h gives them a
// checked header).
//
// Each file is written beside its name and renamed into place, so
// concurrent processes never read half a file. The folder is trimmed to a
// size, least recently used first.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "core/content_hash.h"

namespace snell {

class KeyedFileStore {
 public:
  explicit KeyedFileStore(std::filesystem::path dir) : dir_(std::move(dir)) {}
  const std::filesystem::path& dir() const { return dir_; }

  // The file's bytes as they are, or nothing when it is absent or unreadable.
  std::optional<std::string> read(const Digest& key) const;
  // For a hit: the trim keeps what was used last.
  void markUsed(const Digest& key) const;
  // False when it could not be written (a full disk, a read-only folder):
  // the result is then computed again next time, nothing else changes.
  bool write(const Digest& key, const std::string& bytes) const;

  // The result kept under `key` as `decode(key, bytes)` reads it (nothing
  // for bytes that are not a whole result), marked as used; or nothing.
  template <class Decode>
  auto kept(const Digest& key, Decode decode) const {
    std::optional<std::string> bytes = read(key);
    decltype(decode(key, std::string_view())) result;
    if (bytes) result = decode(key, std::string_view(*bytes));
    if (result) markUsed(key);
    return result;
  }
  // The kept result, or `compute()`, then kept as `encode(key, result)`.
  template <class Decode, class Encode, class Compute>
  auto keptOrComputed(const Digest& key, Decode decode, Encode encode, Compute compute) const {
    if (auto result = kept(key, decode)) return std::move(*result);
    auto result = compute();
    write(key, encode(key, result));
    return result;
  }

 private:
  std::filesystem::path pathOf(const Digest& key) const;
  std::filesystem::path dir_;
};

struct StoreTrim {
  std::size_t removed = 0;  // files
  std::uintmax_t kept = 0;  // bytes left
};
// Removes the least recently used entries until at most `maxBytes` are
// left, and any temporary file an interrupted write left a day ago. Only the
// store's own files (HEX/HEX.result and their temporaries) are touched.
StoreTrim trimKeyedFileStore(const std::filesystem::path& dir, std::uintmax_t maxBytes);

}  // namespace snell
