#pragma once
// Oracle results kept on disk between runs. An oracle's answer depends only
// on its code, the listing it follows and its input, and computing it is
// most of a run's time (the intervals), while a driver developer runs the
// same snell build on the same cases again and again. So each result is
// stored under a digest of all of those (oracle_store_key.h) and read back
// when the same oracle meets the same input again: a hit gives the very
// bytes the oracle computed, and any change to the build, the listing or
// an input is another key.
//
// One file per result in a KeyedFileStore (core/keyed_file_store.h); a
// damaged file reads as a miss. The folder is trimmed to a size after each
// run, the least recently used results first.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "core/content_hash.h"
#include "core/expected_values.h"
#include "core/keyed_file_store.h"
#include "oracle/reference/reference_image.h"

namespace snell {

// What a run may keep, at most (Mesa's shader cache keeps 1 GiB too).
inline constexpr std::uintmax_t kOracleStoreMaxBytes = std::uintmax_t{1} << 30;

class OracleStore : public KeyedFileStore {
 public:
  using KeyedFileStore::KeyedFileStore;

  // The result stored under `key`, or nothing (absent, unreadable,
  // damaged). A hit marks the file as used now, for the trim. Other kinds
  // of result are read and written as bytes of stored_result_format.h
  // through read(), markUsed() and write().
  std::optional<std::vector<OracleVarying>> load(const Digest& key) const;
  std::optional<ReferenceImage> loadReference(const Digest& key) const;
  // False when it could not be written: see KeyedFileStore::write.
  bool save(const Digest& key, const std::vector<OracleVarying>& result) const;
  bool saveReference(const Digest& key, const ReferenceImage& reference) const;
};

// Where results are kept unless the user says otherwise: $SNELL_ORACLE_CACHE,
// else $XDG_CACHE_HOME/snell/oracle, else $HOME/.cache/snell/oracle; empty
// when none of those is set, or when SNELL_ORACLE_CACHE is off
// (isOracleStoreOff).
std::filesystem::path defaultOracleStoreDir();

// "off" in any case: keep nothing (a folder called OFF would be a surprise).
bool isOracleStoreOff(const std::string& value);

// `dir` made where it is missing, as an absolute path, or empty with a
// note for the user when it cannot be: a store that cannot be kept costs
// speed, not results, so the caller says so and goes on without one.
struct OracleStoreFolder {
  std::filesystem::path dir;
  std::string note;
};
OracleStoreFolder prepareOracleStoreDir(const std::filesystem::path& dir,
                                        const std::string& howToChoose);

}  // namespace snell
