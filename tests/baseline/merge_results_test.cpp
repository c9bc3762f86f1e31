// Shards: interleaved, every case in exactly one; merged back in the order
// of an unsharded run; overlaps and unknown cases refused.
#include "baseline/merge_results.h"

#include <gtest/gtest.h>

#include "baseline/shard.h"
#include "core/errors.h"

namespace snell {
namespace {

Case imageCase(const std::string& id, bool image) {
  Case c;
  c.id = id;
  c.spec.checks =
      image ? std::vector<std::string>{"vectors", "image"} : std::vector<std::string>{"vectors"};
  return c;
}

CaseResult result(const std::string& id, const std::string& backend) {
  CaseResult r;
  r.caseId = id;
  r.backend = backend;
  return r;
}

TEST(Shard, ParsesAndRefuses) {
  const Shard s = parseShard("2/3");
  EXPECT_EQ(s.index, 2u);
  EXPECT_EQ(s.count, 3u);
  for (const char* bad : {"", "3", "0/3", "4/3", "1/0", "a/b", "1/3x", "-1/3", "1//3"})
    EXPECT_THROW(parseShard(bad), UsageError) << bad;
}

TEST(Shard, InterleavedAndEveryCaseInExactlyOne) {
  const std::size_t cases = 11, shards = 4;
  for (std::size_t k = 0; k < cases; ++k) {
    int owners = 0;
    for (std::size_t i = 1; i <= shards; ++i) owners += Shard{i, shards}.contains(k) ? 1 : 0;
    EXPECT_EQ(owners, 1) << k;
  }
  // Shard 2 of 4 runs the 2nd, 6th and 10th case.
  std::vector<std::size_t> mine;
  for (std::size_t k = 0; k < cases; ++k)
    if (Shard{2, 4}.contains(k)) mine.push_back(k);
  EXPECT_EQ(mine, (std::vector<std::size_t>{1, 5, 9}));
}

TEST(MergeResults, ShardsMergeInUnshardedOrder) {
  const std::vector<Case> catalog = {imageCase("a", true), imageCase("b", false),
                                     imageCase("c", true)};
  const std::vector<ResultsFile> files = {
      {"shard2.jsonl", {result("b", "gl"), result("b", "vk")}},
      {"shard1.jsonl",
       {result("a", "vk"), result("c", "vk"), result("a", "gl"), result("c", "gl")}}};
  const std::vector<CaseResult> merged = mergeResults(files, catalog);
  std::vector<std::string> order;
  for (const CaseResult& r : merged) order.push_back(r.backend + " " + r.caseId);
  EXPECT_EQ(order, (std::vector<std::string>{"gl a", "gl b", "gl c", "vk a", "vk b", "vk c"}));
}

TEST(MergeResults, OverlapAndUnknownCaseAreUsageErrors) {
  const std::vector<Case> catalog = {imageCase("a", true)};
  EXPECT_THROW(
      mergeResults({{"1.jsonl", {result("a", "gl")}}, {"2.jsonl", {result("a", "gl")}}}, catalog),
      UsageError);
  EXPECT_THROW(mergeResults({{"1.jsonl", {result("zz", "gl")}}}, catalog), UsageError);
}

}  // namespace
}  // namespace snell
