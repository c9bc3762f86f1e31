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

// A shard of another run (another --filter or --backend) does not stand in
// for the missing shard of this one: its cases are not the ones missing.
// Each backend sharded apart, as a run of its own, merges whole.
TEST(MergeResults, AShardOfAnotherRunDoesNotStandForAMissingOne) {
  const std::vector<Case> catalog = {imageCase("a", false), imageCase("b", false),
                                     imageCase("c", false)};
  const auto of = [](CaseResult r, const char* shard, const char* run) {
    r.shard = shard;
    r.shardOf = run;
    return r;
  };
  const char* both = "--filter '*' --backend gl,vk";
  const char* glOnly = "--filter '*' --backend gl";
  const char* vkOnly = "--filter '*' --backend vk";
  try {
    mergeResults(
        {{"1.jsonl", {of(result("a", "gl"), "1/3", both), of(result("a", "vk"), "1/3", both)}},
         {"2.jsonl", {of(result("b", "gl"), "2/3", glOnly)}},
         {"3.jsonl", {of(result("c", "gl"), "3/3", both), of(result("c", "vk"), "3/3", both)}}},
        catalog);
    ADD_FAILURE() << "merged shards of two runs";
  } catch (const UsageError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("no results of shard 1/3, 3/3 of the run of --filter '*' --backend gl; "
                           "nor of shard 2/3 of the run of --filter '*' --backend gl,vk"),
              std::string::npos)
        << message;
  }
  const std::vector<CaseResult> merged = mergeResults(
      {{"gl1.jsonl", {of(result("a", "gl"), "1/2", glOnly), of(result("c", "gl"), "1/2", glOnly)}},
       {"gl2.jsonl", {of(result("b", "gl"), "2/2", glOnly)}},
       {"vk1.jsonl", {of(result("a", "vk"), "1/2", vkOnly), of(result("c", "vk"), "1/2", vkOnly)}},
       {"vk2.jsonl", {of(result("b", "vk"), "2/2", vkOnly)}}},
      catalog);
  EXPECT_EQ(merged.size(), 6u);
  for (const CaseResult& r : merged) EXPECT_TRUE(r.shard.empty() && r.shardOf.empty());
  // One empty file is one shard: it does not stand for a missing shard of
  // each of two runs.
  EXPECT_THROW(mergeResults({{"gl1.jsonl", {of(result("a", "gl"), "1/2", glOnly)}},
                             {"vk1.jsonl", {of(result("a", "vk"), "1/2", vkOnly)}},
                             {"empty.jsonl", {}}},
                            catalog),
               UsageError);
  // Records from before shard_of (a resumed old .partial) count for the
  // runs of their shard count.
  const std::vector<CaseResult> mixed = mergeResults(
      {{"1.jsonl", {of(result("a", "gl"), "1/2", ""), of(result("c", "gl"), "1/2", glOnly)}},
       {"2.jsonl", {of(result("b", "gl"), "2/2", glOnly)}}},
      catalog);
  EXPECT_EQ(mixed.size(), 3u);
}

// A shard of a run with another --filter that holds a case this run's
// shards hold too is named as a shard of another run, not as an overlap
// (which reads as one shard given twice).
TEST(MergeResults, AShardOfAnotherRunThatOverlapsIsNamedAsSuch) {
  const std::vector<Case> catalog = {imageCase("a", false), imageCase("b", false)};
  const auto of = [](CaseResult r, const char* shard, const char* run) {
    r.shard = shard;
    r.shardOf = run;
    return r;
  };
  try {
    mergeResults({{"s1.jsonl", {of(result("a", "gl"), "1/2", "--filter '*' --backend gl")}},
                  {"s2.jsonl", {of(result("b", "gl"), "2/2", "--filter '*' --backend gl")}},
                  {"f.jsonl", {of(result("b", "gl"), "2/2", "--filter 'b' --backend gl")}}},
                 catalog);
    ADD_FAILURE() << "merged shards of two runs";
  } catch (const UsageError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("s2.jsonl holds shard 2/2 of the run of --filter '*' --backend gl, "
                           "and f.jsonl shard 2/2 of the run of --filter 'b' --backend gl"),
              std::string::npos)
        << message;
  }
}

// Shards of two driver builds under one backend would be credited to one
// of them: refused, naming both files and both builds. A record that names
// no driver (a worker that died first) joins any; other backends may differ.
TEST(MergeResults, TwoDriverBuildsUnderOneBackendAreRefused) {
  const std::vector<Case> catalog = {imageCase("a", false), imageCase("b", false),
                                     imageCase("c", false)};
  const auto on = [](CaseResult r, const char* version) {
    r.driver.renderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
    r.driver.apiVersion = "4.5 (Core Profile) Mesa 22.3.6";
    r.driver.driverVersion = version;
    return r;
  };
  try {
    mergeResults({{"1.jsonl", {on(result("a", "gl"), "Mesa 22.3.6")}},
                  {"2.jsonl", {on(result("b", "gl"), "Mesa 24.0.0")}}},
                 catalog);
    ADD_FAILURE() << "merged two driver builds";
  } catch (const UsageError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("1.jsonl ran gl on Mesa 22.3.6"), std::string::npos) << message;
    EXPECT_NE(message.find("2.jsonl on Mesa 24.0.0"), std::string::npos) << message;
  }
  EXPECT_NO_THROW(mergeResults({{"1.jsonl", {result("a", "gl")}},
                                {"2.jsonl", {on(result("b", "gl"), "Mesa 22.3.6")}},
                                {"3.jsonl", {on(result("c", "gl"), "Mesa 22.3.6")}}},
                               catalog));
  EXPECT_NO_THROW(mergeResults({{"1.jsonl", {on(result("a", "gl"), "Mesa 22.3.6")}},
                                {"2.jsonl", {on(result("a", "vk"), "Mesa 24.0.0")}}},
                               catalog));
  EXPECT_THROW(mergeResults({{"1.jsonl", {result("a", "gl")}},
                             {"2.jsonl", {on(result("b", "gl"), "Mesa 22.3.6")}},
                             {"3.jsonl", {on(result("c", "gl"), "Mesa 24.0.0")}}},
                            catalog),
               UsageError);
}

// Records name their shard: a merge that lacks one is refused, naming it;
// an empty file (a shard with no cases) stands for one shard; results of a
// whole run name none and are not counted; and the merged records are the
// whole run's.
TEST(MergeResults, AMissingShardIsRefusedAndAnEmptyFileStandsForOne) {
  const std::vector<Case> catalog = {imageCase("a", false), imageCase("b", false),
                                     imageCase("c", false)};
  const auto of = [](CaseResult r, const char* shard) {
    r.shard = shard;
    return r;
  };
  const ResultsFile one{"1.jsonl", {of(result("a", "gl"), "1/3"), of(result("a", "vk"), "1/3")}};
  const ResultsFile two{"2.jsonl", {of(result("b", "gl"), "2/3"), of(result("b", "vk"), "2/3")}};
  const ResultsFile three{"3.jsonl", {of(result("c", "gl"), "3/3"), of(result("c", "vk"), "3/3")}};
  const ResultsFile empty{"e.jsonl", {}};
  try {
    mergeResults({one, three}, catalog);
    ADD_FAILURE() << "merged without shard 2";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("no results of shard 2/3"), std::string::npos) << e.what();
  }
  EXPECT_EQ(mergeResults({one, two, three}, catalog).size(), 6u);
  EXPECT_EQ(mergeResults({one, three, empty}, catalog).size(), 4u);
  EXPECT_THROW(mergeResults({one, empty}, catalog), UsageError);  // two missing, one empty
  for (const CaseResult& r : mergeResults({one, two, three}, catalog)) EXPECT_EQ(r.shard, "");
  // A shard with no record of one backend (its cases skipped there, or the
  // backend not up on that runner) is still that shard.
  const ResultsFile twoGlOnly{"2gl.jsonl", {of(result("b", "gl"), "2/3")}};
  EXPECT_EQ(mergeResults({one, twoGlOnly, three}, catalog).size(), 5u);
  // A whole run's records say nothing of shards: gl run whole, vk in shards.
  const ResultsFile wholeGl{"gl.jsonl", {result("a", "gl"), result("b", "gl"), result("c", "gl")}};
  const ResultsFile vk1{"vk1.jsonl", {of(result("a", "vk"), "1/2"), of(result("c", "vk"), "1/2")}};
  const ResultsFile vk2{"vk2.jsonl", {of(result("b", "vk"), "2/2")}};
  EXPECT_EQ(mergeResults({wholeGl, vk1, vk2}, catalog).size(), 6u);
  EXPECT_THROW(mergeResults({wholeGl, vk1}, catalog), UsageError);
}

// Records count the cases of every shard of their run: a missing shard
// that had cases is refused whatever empty files are given, one that had
// none needs no file (its cases all skipped, or more shards than cases).
TEST(MergeResults, RecordsSayWhichShardsHadCases) {
  const std::vector<Case> catalog = {imageCase("a", false), imageCase("b", false),
                                     imageCase("c", false), imageCase("d", false)};
  const auto of = [](CaseResult r, const char* shard, std::vector<std::size_t> cases) {
    r.shard = shard;
    r.shardOf = "--filter '*' --backend gl,vk";
    r.shardCases = std::move(cases);
    return r;
  };
  const ResultsFile empty{"e.jsonl", {}};
  // Three cases in four shards, the third skipped: shards 3 and 4 had none.
  const std::vector<std::size_t> plan{1, 1, 0, 0};
  const ResultsFile one{"1.jsonl",
                        {of(result("a", "gl"), "1/4", plan), of(result("a", "vk"), "1/4", plan)}};
  const ResultsFile two{"2.jsonl", {of(result("b", "gl"), "2/4", plan)}};
  EXPECT_EQ(mergeResults({one, two}, catalog).size(), 3u);
  EXPECT_EQ(mergeResults({one, two, empty, empty}, catalog).size(), 3u);
  for (const CaseResult& r : mergeResults({one, two}, catalog)) EXPECT_TRUE(r.shardCases.empty());
  // Shard 2 had a case: an empty file does not stand for it.
  for (const std::vector<ResultsFile>& files :
       {std::vector<ResultsFile>{one, empty}, std::vector<ResultsFile>{one}}) {
    try {
      mergeResults(files, catalog);
      ADD_FAILURE() << "merged without shard 2";
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("no results of shard 2/4 (1 case) of the run of "
                                           "--filter '*' --backend gl,vk"),
                std::string::npos)
          << e.what();
    }
  }
  // The last shard with a case, missing, is found as any other.
  const std::vector<std::size_t> full{1, 1, 1, 1};
  const ResultsFile a{"1.jsonl", {of(result("a", "gl"), "1/4", full)}};
  const ResultsFile b{"2.jsonl", {of(result("b", "gl"), "2/4", full)}};
  const ResultsFile c{"3.jsonl", {of(result("c", "gl"), "3/4", full)}};
  EXPECT_THROW(mergeResults({a, b, c, empty}, catalog), UsageError);
}

}  // namespace
}  // namespace snell
