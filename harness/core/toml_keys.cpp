#include "core/toml_keys.h"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "core/errors.h"

namespace snell {
namespace {

std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string nearestKey(std::string_view key, std::initializer_list<std::string_view> known) {
  return nearestKey(key, std::vector<std::string>(known.begin(), known.end()));
}

std::string nearestKey(std::string_view key, const std::vector<std::string>& known) {
  std::string best;
  std::size_t bestDistance = 0;
  for (const std::string& candidate : known) {
    const std::size_t d = editDistance(key, candidate);
    if (best.empty() || d < bestDistance) {
      best = candidate;
      bestDistance = d;
    }
  }
  // A suggestion only when it is plausibly the same word.
  const std::size_t close = std::max<std::size_t>(2, key.size() / 3);
  return bestDistance <= close ? best : std::string();
}

void rejectUnknownKeys(const toml::table& table, std::initializer_list<std::string_view> known,
                       const std::filesystem::path& file, std::string_view where) {
  for (const auto& [key, value] : table) {
    const std::string_view name = key.str();
    if (std::find(known.begin(), known.end(), name) != known.end()) continue;
    const std::string nearest = nearestKey(name, known);
    std::string list;
    for (std::string_view k : known) list += (list.empty() ? "" : ", ") + std::string(k);
    throw UsageError(fmt::format(
        "{}:{}: unknown key `{}` in {}; {}known keys: {}", file.string(),
        key.source().begin.line ? key.source().begin.line : value.source().begin.line, name, where,
        nearest.empty() ? "" : fmt::format("did you mean `{}`? ", nearest), list));
  }
}

}  // namespace snell
