#include "baseline/shard.h"

#include <fmt/format.h>

#include <charconv>

#include "core/errors.h"

namespace snell {

Shard parseShard(const std::string& text) {
  const auto slash = text.find('/');
  Shard shard;
  const auto number = [&](std::size_t from, std::size_t to, std::size_t& out) {
    const char* end = text.data() + to;
    const auto [ptr, ec] = std::from_chars(text.data() + from, end, out);
    return ec == std::errc() && ptr == end && to > from;
  };
  if (slash == std::string::npos || !number(0, slash, shard.index) ||
      !number(slash + 1, text.size(), shard.count) || shard.count == 0 || shard.index == 0 ||
      shard.index > shard.count)
    throw UsageError(
        fmt::format("--shard {}: expected I/N with 1 <= I <= N, e.g. --shard 2/4 "
                    "(GitLab: --shard $CI_NODE_INDEX/$CI_NODE_TOTAL)",
                    text));
  return shard;
}

}  // namespace snell
