#pragma once
// `--shard I/N`, as Mesa's CI splits a run over parallel jobs: shard I
// (1-based, as GitLab's CI_NODE_INDEX) runs cases I, I+N, I+2N, ... of the
// catalog, interleaved so that every shard gets a share of each listing.
// Both backends of a case land in the same shard.
#include <cstddef>
#include <string>

namespace snell {

struct Shard {
  std::size_t index = 1, count = 1;
  bool contains(std::size_t caseIndex) const { return caseIndex % count == index - 1; }
};

// Throws UsageError for anything but I/N with 1 <= I <= N.
Shard parseShard(const std::string& text);

}  // namespace snell
