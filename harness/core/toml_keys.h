#pragma once
// Every reader of snell's TOML files (manifests, scenes) rejects a key it
// does not know: a misspelt `timeot = 5` would otherwise be ignored and the
// default used in silence.
#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

namespace snell {

// Throws UsageError "FILE:LINE: unknown key `k` in `where`; did you mean
// `nearest`? (known: ...)" for the first key of `table` not in `known`.
void rejectUnknownKeys(const toml::table& table, std::initializer_list<std::string_view> known,
                       const std::filesystem::path& file, std::string_view where);

// The known key nearest to `key` by edit distance, or "" when none is close.
std::string nearestKey(std::string_view key, std::initializer_list<std::string_view> known);
std::string nearestKey(std::string_view key, const std::vector<std::string>& known);

}  // namespace snell
