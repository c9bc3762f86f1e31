// A run judged against its expectations: each outcome, the gate, and the
// results.csv and JUnit that carry them.
#include "baseline/baseline_judgement.h"

#include <gtest/gtest.h>

#include <sstream>

#include "baseline/results_csv.h"
#include "report/junit.h"
#include "test_files.h"

namespace snell {
namespace {

CaseResult result(const std::string& id, Status status, std::vector<Status> reruns = {}) {
  CaseResult r;
  r.caseId = id;
  r.backend = "gl";
  r.status = status;
  r.reruns = std::move(reruns);
  r.seconds = 0.25;
  return r;
}

ExpectationSet expectations(const testing::TempDir& dir) {
  dir.write("gl-fails.txt",
            "# reason: rim pixels\nknown/fail/a,Fail\nknown/fail/b,Fail\nknown/now-passes/a,Fail\n"
            "not/in/run,Crash\n");
  dir.write("gl-flakes.txt", "^flaky/\n");
  return loadExpectations(dir.path(), {"gl"}, "2026-11-25");
}

TEST(BaselineJudgement, EveryOutcome) {
  testing::TempDir dir;
  const ExpectationSet set = expectations(dir);
  const std::vector<CaseResult> results = {
      result("plain/pass/a", Status::Pass),
      result("known/fail/a", Status::Fail),
      result("known/fail/b", Status::Crash),  // listed as Fail: a different failure
      result("known/now-passes/a", Status::Pass),
      result("flaky/case/a", Status::Timeout),
      result("new/fail/a", Status::Fail, {Status::Fail}),
      result("new/flake/a", Status::Fail, {Status::Pass}),
  };
  const BaselineReport report = judgeResults(set, results, {});
  ASSERT_EQ(report.cases.size(), results.size());
  EXPECT_EQ(report.cases[0].outcome, Outcome::Pass);
  EXPECT_EQ(report.cases[1].outcome, Outcome::ExpectedFail);
  EXPECT_EQ(report.cases[2].outcome, Outcome::UnexpectedFail);
  EXPECT_EQ(report.cases[3].outcome, Outcome::UnexpectedPass);
  EXPECT_EQ(report.cases[4].outcome, Outcome::KnownFlake);
  EXPECT_EQ(report.cases[5].outcome, Outcome::UnexpectedFail);
  EXPECT_EQ(report.cases[6].outcome, Outcome::Flake);
  ASSERT_EQ(report.absent.size(), 1u);
  EXPECT_EQ(report.absent[0].entry->caseId, "not/in/run");
  EXPECT_TRUE(report.failed());

  std::ostringstream out;
  printBaselineReport(out, set, report);
  const std::string text = out.str();
  EXPECT_NE(text.find("2 unexpected failures"), std::string::npos) << text;
  EXPECT_NE(text.find("1 flakes"), std::string::npos) << text;
  // The improvement names the line to delete.
  EXPECT_NE(text.find("improvement: gl known/now-passes/a is Pass; delete " +
                      (dir.path() / "gl-fails.txt").string() + ":4 `known/now-passes/a,Fail`"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("flake: gl new/flake/a was Fail, then on rerun Pass"), std::string::npos)
      << text;
  EXPECT_NE(text.find("absent: gl not/in/run"), std::string::npos) << text;
  EXPECT_NE(text.find("add `new/fail/a,Fail`"), std::string::npos) << text;
}

TEST(BaselineJudgement, ExpectedFailuresAndFlakesPassTheGate) {
  testing::TempDir dir;
  const ExpectationSet set = expectations(dir);
  const std::vector<CaseResult> results = {result("known/fail/a", Status::Fail),
                                           result("flaky/x/y", Status::Crash),
                                           result("new/flake/a", Status::Fail, {Status::Pass})};
  EXPECT_FALSE(judgeResults(set, results, {}).failed());
  // Without expectations, only the flake passes.
  EXPECT_TRUE(judgeResults({}, results, {}).failed());
  EXPECT_FALSE(isUnexpectedFailure(set, results[0]));
  EXPECT_TRUE(isUnexpectedFailure({}, results[0]));
  // The rerun candidate is judged on its first run.
  EXPECT_TRUE(isUnexpectedFailure(set, results[2]));
}

TEST(BaselineJudgement, ResultsCsvInDeqpRunnerFormat) {
  testing::TempDir dir;
  const ExpectationSet set = expectations(dir);
  const std::vector<CaseResult> results = {
      result("plain/pass/a", Status::Pass), result("known/fail/a", Status::Fail),
      result("new/flake/a", Status::Fail, {Status::Pass}), result("new/fail/a", Status::Crash)};
  EXPECT_EQ(toResultsCsv(judgeResults(set, results, {})),
            "gl/plain/pass/a,Pass,0.250\n"
            "gl/known/fail/a,ExpectedFail,0.250\n"
            "gl/new/flake/a,Flake,0.250\n"
            "gl/new/fail/a,Crash,0.250\n");
}

// deqp-runner refuses a status it does not know ("unknown runner status"):
// snell's own are named as the nearest of its statuses.
TEST(BaselineJudgement, ResultsCsvUsesOnlyDeqpRunnersStatuses) {
  testing::TempDir dir;
  const ExpectationSet set = expectations(dir);
  const std::vector<CaseResult> results = {
      result("a", Status::NotSupported),   result("b", Status::CompatibilityWarning),
      result("c", Status::QualityWarning), result("d", Status::ExpectedCompileError),
      result("e", Status::CompileError),   result("f", Status::Timeout),
      result("known/fail/a", Status::Pass)};
  EXPECT_EQ(toResultsCsv(judgeResults(set, results, {})),
            "gl/a,Skip,0.250\n"
            "gl/b,Warn,0.250\n"
            "gl/c,Warn,0.250\n"
            "gl/d,Pass,0.250\n"
            "gl/e,Fail,0.250\n"
            "gl/f,Timeout,0.250\n"
            "gl/known/fail/a,UnexpectedImprovement(Pass),0.250\n");
}

// One PREFIX-fails.txt covers every backend: a line whose case passes on
// one backend and still fails on another was to be deleted, which would
// make the other's failure unexpected.
TEST(BaselineJudgement, AnImprovementOnOneBackendOfASharedLineSaysToKeepIt) {
  testing::TempDir dir;
  const auto fails = dir.write("lo-fails.txt", "x/y/z,Fail\nboth/pass/a,Fail\n");
  const ExpectationSet set = loadExpectations(fails, {"gl", "vk"}, "2026-11-25");
  const auto on = [](const char* backend, const char* id, Status status) {
    CaseResult r = result(id, status);
    r.backend = backend;
    return r;
  };
  const std::vector<CaseResult> results = {
      on("gl", "x/y/z", Status::Fail), on("vk", "x/y/z", Status::Pass),
      on("gl", "both/pass/a", Status::Pass), on("vk", "both/pass/a", Status::Pass)};
  std::ostringstream out;
  printBaselineReport(out, set, judgeResults(set, results, {}));
  const std::string text = out.str();
  EXPECT_NE(text.find("improvement: vk x/y/z is Pass; " + fails.string() +
                      ":1 also covers gl, where it still fails: keep it"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("delete " + fails.string() + ":1"), std::string::npos) << text;
  EXPECT_NE(text.find("improvement: gl both/pass/a is Pass; delete " + fails.string() + ":2"),
            std::string::npos)
      << text;
}

TEST(BaselineJudgement, JUnitShowsExpectedFailuresAsSkippedAndFlakesAsFlaky) {
  testing::TempDir dir;
  const ExpectationSet set = expectations(dir);
  const std::vector<CaseResult> results = {result("known/fail/a", Status::Fail),
                                           result("new/flake/a", Status::Fail, {Status::Pass}),
                                           result("new/fail/a", Status::Fail)};
  JUnitNotes notes = junitNotesOf(judgeResults(set, results, {}));
  notes.incomplete = "interrupted by SIGINT after 3 of 9 results";
  const std::string xml = toJUnitXml(results, notes);
  EXPECT_NE(xml.find("failures=\"1\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("skipped=\"1\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("<flakyFailure"), std::string::npos) << xml;
  EXPECT_NE(xml.find("incomplete: interrupted by SIGINT"), std::string::npos) << xml;
  EXPECT_NE(xml.find("<property name=\"incomplete\""), std::string::npos) << xml;
}

}  // namespace
}  // namespace snell
