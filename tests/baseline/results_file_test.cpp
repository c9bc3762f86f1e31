// Results files read back: records round-trip, a torn last line (a run
// killed mid-write) is dropped, anything else malformed is FILE:LINE.
#include "baseline/results_file.h"

#include <gtest/gtest.h>

#include "core/errors.h"
#include "test_files.h"

namespace snell {
namespace {

CaseResult result(const std::string& id, Status status) {
  CaseResult r;
  r.caseId = id;
  r.backend = "vk";
  r.status = status;
  r.reruns = {Status::Fail, Status::Pass};
  return r;
}

TEST(ResultsFile, RoundTripsWithRerunsAndIncompleteMark) {
  testing::TempDir dir;
  const std::string text =
      toResultsJsonLines({result("a/b/c", Status::Fail), result("d/e/f", Status::Pass)}, true);
  EXPECT_NE(text.find("\"incomplete\":true"), std::string::npos);
  const auto read = readResultsFile(dir.write("r.jsonl", text));
  ASSERT_EQ(read.size(), 2u);
  EXPECT_EQ(read[0].caseId, "a/b/c");
  EXPECT_EQ(read[0].status, Status::Fail);
  EXPECT_EQ(read[0].reruns, (std::vector<Status>{Status::Fail, Status::Pass}));
  EXPECT_EQ(resultKey(read[1]), "vk d/e/f");
}

TEST(ResultsFile, TornLastLineIsDropped) {
  testing::TempDir dir;
  std::string text = toResultsJsonLines({result("a/b/c", Status::Pass)});
  text += text.substr(0, 40);  // no newline: the write was cut off
  EXPECT_EQ(readResultsFile(dir.write("r.jsonl.partial", text)).size(), 1u);
}

TEST(ResultsFile, MalformedRecordIsUsageErrorAtItsLine) {
  testing::TempDir dir;
  const std::string good = toResultsJsonLines({result("a/b/c", Status::Pass)});
  try {
    readResultsFile(dir.write("r.jsonl", good + "{\"case\": 1}\n" + good));
    FAIL() << "accepted a malformed record";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("r.jsonl:2:"), std::string::npos) << e.what();
    // The field is named, not only the JSON library's complaint about it.
    EXPECT_NE(std::string(e.what()).find("\"case\": type must be string"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(readResultsFile(dir.path() / "missing.jsonl"), UsageError);
  std::string noRenderer = good;
  noRenderer.replace(noRenderer.find("\"renderer\""), 10, "\"rendered\"");
  try {
    readResultsFile(dir.write("n.jsonl", noRenderer));
    FAIL() << "accepted a record with no renderer";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("\"renderer\": key 'renderer' not found"),
              std::string::npos)
        << e.what();
  }
  try {
    readResultsFile(dir.write("a.jsonl", "[1, 2]\n"));
    FAIL() << "accepted an array";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("a record is an object, not array"), std::string::npos)
        << e.what();
  }
}

// Two records of one case on one backend (two files concatenated, a record
// pasted twice): compare kept one without a word and report counted both.
TEST(ResultsFile, ASecondRecordOfOneCaseIsUsageErrorNamingBothLines) {
  testing::TempDir dir;
  const std::string one = toResultsJsonLines({result("a/b/c", Status::Pass)});
  const std::string other = toResultsJsonLines({result("d/e/f", Status::Pass)});
  try {
    readResultsFile(dir.write("r.jsonl", one + other + one));
    ADD_FAILURE() << "read two records of one case";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "r.jsonl:3: a second result of a/b/c on vk (the first is line 1)"),
              std::string::npos)
        << e.what();
  }
  CaseResult gl = result("a/b/c", Status::Pass);
  gl.backend = "gl";
  EXPECT_EQ(readResultsFile(dir.write("two.jsonl", one + toResultsJsonLines({gl}))).size(), 2u);
}

// A run's FILE.partial that is still there is a run that was killed: read
// as incomplete, as an interrupted run's file is, not as a finished run.
TEST(ResultsFile, AKilledRunsPartialFileIsReadAsIncomplete) {
  testing::TempDir dir;
  const std::string text = toResultsJsonLines({result("a/b/c", Status::Pass)});
  bool incomplete = false;
  EXPECT_EQ(readFinishedResultsFile(dir.write("r.jsonl.partial", text), &incomplete).size(), 1u);
  EXPECT_TRUE(incomplete);
  EXPECT_EQ(readFinishedResultsFile(dir.write("r.jsonl", text), &incomplete).size(), 1u);
  EXPECT_FALSE(incomplete);
  // An empty file is no run, except where a shard with no cases is allowed.
  const auto empty = dir.write("e.jsonl", "");
  EXPECT_THROW(readFinishedResultsFile(empty), UsageError);
  EXPECT_TRUE(readFinishedResultsFile(empty, nullptr, EmptyResults::Allowed).empty());
}

}  // namespace
}  // namespace snell
