#pragma once
// The bytes of one stored oracle result (runner/oracle_store/oracle_store.h):
// a header that names the key and the digest of the payload, then every
// field of every OracleVarying, so that a result read back is bit for bit
// the one that was computed. A file that was cut short, damaged, written
// by another format version or under another key reads as nothing.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/content_hash.h"
#include "core/expected_values.h"

namespace snell {

inline constexpr std::uint32_t kStoredResultFormat = 1;

std::string encodeStoredResult(const Digest& key, const std::vector<OracleVarying>& result);
std::optional<std::vector<OracleVarying>> decodeStoredResult(const Digest& key,
                                                             std::string_view bytes);

}  // namespace snell
