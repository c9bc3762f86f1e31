// Two hand-made runs that hold one case of each kind: every category is
// found, and nothing else is.
#include "baseline/compare_runs.h"

#include <gtest/gtest.h>

#include <sstream>

#include "core/errors.h"
#include "core/listing_digest.h"

namespace snell {
namespace {

CaseResult result(const std::string& id, const std::string& backend, Status status,
                  double slack = 0.1, double imageError = -1) {
  CaseResult r;
  r.caseId = id;
  r.backend = backend;
  r.status = status;
  VaryingCheck v;
  v.name = "Refract";
  v.checked = 10;
  v.worstSlack = slack;
  r.varyings.push_back(v);
  if (imageError >= 0) {
    ImageComparison c;
    c.against = "reference";
    c.maxError = imageError;
    r.images.push_back(c);
  }
  return r;
}

RunSide side(const std::string& label, std::vector<CaseResult> results, std::string backend = "") {
  return {label, std::move(backend), std::move(results)};
}

// Support that comes or goes is a change; a case not supported before that
// a new build claims and fails is a regression (it passed the gate).
TEST(CompareRuns, NewlySupportedAndFailingIsARegression) {
  const RunSide before = side(
      "a.jsonl",
      {result("breaks", "gl", Status::NotSupported), result("crashes", "gl", Status::NotSupported),
       result("works", "gl", Status::NotSupported), result("dropped", "gl", Status::Fail)});
  const RunSide after =
      side("b.jsonl",
           {result("breaks", "gl", Status::Fail), result("crashes", "gl", Status::Crash),
            result("works", "gl", Status::Pass), result("dropped", "gl", Status::NotSupported)});
  const RunComparison c = compareRuns(before, after, DriftRule{});
  ASSERT_EQ(c.regressions.size(), 2u);
  EXPECT_EQ(c.regressions[0].key, "gl breaks");
  EXPECT_EQ(c.regressions[1].key, "gl crashes");
  ASSERT_EQ(c.changes.size(), 2u);
  EXPECT_EQ(c.changes[0].key, "gl dropped");
  EXPECT_EQ(c.changes[1].key, "gl works");
}

// A failure that passed on a rerun passes the gate in `run` and `merge`:
// compared, it is a flake, not a regression; one that failed its reruns
// too is a regression.
TEST(CompareRuns, AFlakeIsNoRegression) {
  const RunSide before =
      side("a.jsonl", {result("flaky", "gl", Status::Pass), result("broken", "gl", Status::Pass),
                       result("settled", "gl", Status::Timeout)});
  CaseResult flaky = result("flaky", "gl", Status::Timeout);
  flaky.reruns = {Status::Pass};
  CaseResult broken = result("broken", "gl", Status::Timeout);
  broken.reruns = {Status::Timeout};
  CaseResult settled = result("settled", "gl", Status::Timeout);
  settled.reruns = {Status::Timeout, Status::Pass};
  const RunComparison c =
      compareRuns(before, side("b.jsonl", {flaky, broken, settled}), DriftRule{});
  ASSERT_EQ(c.regressions.size(), 1u);
  EXPECT_EQ(c.regressions[0].key, "gl broken");
  ASSERT_EQ(c.fixes.size(), 1u);  // a timeout before, a flake now: it passes the gate
  EXPECT_EQ(c.fixes[0].key, "gl settled");
  ASSERT_EQ(c.flakes.size(), 2u);
  EXPECT_EQ(c.flakes[0].key, "gl flaky");
  EXPECT_EQ(c.flakes[0].from, Status::Timeout);
  std::ostringstream text;
  printComparison(text, c, DriftRule{});
  EXPECT_NE(text.str().find("flake       gl flaky: Timeout, then Pass on a rerun"),
            std::string::npos)
      << text.str();
  EXPECT_EQ(comparisonToJson(c)["flakes"].size(), 2u);
  EXPECT_EQ(flaky.statusText(), "Timeout, then Pass on a rerun (Flake)");
  EXPECT_EQ(broken.statusText(), "Timeout (reruns: Timeout)");
}

// Cases an interrupted later run did not reach are not "removed": they are
// listed as not reached, in the text and in the JSON.
TEST(CompareRuns, CasesAnInterruptedRunDidNotReachAreNotRemoved) {
  const RunSide before =
      side("a.jsonl", {result("ran", "gl", Status::Pass), result("later", "gl", Status::Pass)});
  RunSide after = side("b.jsonl", {result("ran", "gl", Status::Pass)});
  after.incomplete = true;
  const RunComparison c = compareRuns(before, after, DriftRule{});
  EXPECT_TRUE(c.removed.empty());
  ASSERT_EQ(c.notReached.size(), 1u);
  EXPECT_EQ(c.notReached[0], "gl later");
  std::ostringstream text;
  printComparison(text, c, DriftRule{});
  EXPECT_NE(text.str().find("0 removed, 1 not reached (the later run was interrupted)"),
            std::string::npos)
      << text.str();
  EXPECT_NE(text.str().find("not reached  gl later"), std::string::npos) << text.str();
  EXPECT_EQ(comparisonToJson(c)["not_reached"], nlohmann::json::array({"gl later"}));
  after.incomplete = false;
  EXPECT_EQ(compareRuns(before, after, DriftRule{}).removed.size(), 1u);
}

TEST(CompareRuns, EveryCategory) {
  const RunSide before =
      side("a.jsonl", {result("same", "gl", Status::Pass), result("worse", "gl", Status::Pass),
                       result("crashes", "gl", Status::Fail), result("better", "gl", Status::Fail),
                       result("enabled", "gl", Status::NotSupported),
                       result("gone", "gl", Status::Pass), result("slack", "gl", Status::Pass, 0.1),
                       result("image", "gl", Status::Pass, 0.1, 1e-4),
                       result("noise", "gl", Status::Pass, 0.001, 1e-9)});
  const RunSide after =
      side("b.jsonl", {result("same", "gl", Status::Pass), result("worse", "gl", Status::Fail),
                       result("crashes", "gl", Status::Crash), result("better", "gl", Status::Pass),
                       result("enabled", "gl", Status::Pass), result("fresh", "gl", Status::Pass),
                       result("slack", "gl", Status::Pass, 0.25),
                       result("image", "gl", Status::Pass, 0.1, 3e-4),
                       result("noise", "gl", Status::Pass, 0.009, 5e-7)});
  const RunComparison c = compareRuns(before, after, DriftRule{});
  ASSERT_EQ(c.regressions.size(), 2u);
  EXPECT_EQ(c.regressions[0].key, "gl crashes");
  EXPECT_EQ(c.regressions[1].key, "gl worse");
  ASSERT_EQ(c.fixes.size(), 1u);
  EXPECT_EQ(c.fixes[0].key, "gl better");
  ASSERT_EQ(c.changes.size(), 1u);
  EXPECT_EQ(c.changes[0].key, "gl enabled");
  EXPECT_EQ(c.added, (std::vector<std::string>{"gl fresh"}));
  EXPECT_EQ(c.removed, (std::vector<std::string>{"gl gone"}));
  // 0.1 -> 0.25 and 1e-4 -> 3e-4 grew more than 2x; "noise" stays under the floors.
  ASSERT_EQ(c.drift.size(), 2u);
  EXPECT_EQ(c.drift[0].key, "gl image");
  EXPECT_EQ(c.drift[0].metric, "image error vs reference");
  EXPECT_EQ(c.drift[1].key, "gl slack");
  EXPECT_EQ(c.drift[1].metric, "worst slack");
  EXPECT_EQ(c.unchanged, 4u);  // same, slack, image, noise

  // A larger factor keeps the image drift only.
  DriftRule loose;
  loose.factor = 2.8;
  EXPECT_EQ(compareRuns(before, after, loose).drift.size(), 1u);

  std::ostringstream text;
  printComparison(text, c, DriftRule{});
  EXPECT_NE(
      text.str().find("2 regressions, 1 fixes, 1 changes, 0 flakes, 1 new, 1 removed, 2 drifted"),
      std::string::npos)
      << text.str();
  EXPECT_NE(text.str().find("regression  gl worse: Pass -> Fail"), std::string::npos) << text.str();
  const nlohmann::json json = comparisonToJson(c);
  EXPECT_EQ(json["regressions"].size(), 2u);
  EXPECT_EQ(json["new"][0], "gl fresh");
  EXPECT_EQ(json["drift"][1]["to"], 0.25);
}

// A growing distance from the golden (what was blessed, 0 before) or from
// the other API's image is drift too, each named by what it was against;
// a comparison the earlier run did not make is not.
TEST(CompareRuns, GoldenAndOtherBackendImageErrorsDrift) {
  const auto withImages = [](std::vector<std::pair<std::string, double>> images) {
    CaseResult r = result("image", "gl", Status::Pass);
    for (const auto& [against, error] : images) {
      ImageComparison c;
      c.against = against;
      c.maxError = error;
      r.images.push_back(c);
    }
    return r;
  };
  const RunSide before =
      side("a.jsonl",
           {withImages({{"reference", 1e-3}, {"golden", 0.0}, {"other-backend:gl/vk", 1e-5}})});
  const RunSide after = side("b.jsonl", {withImages({{"reference", 1e-3},
                                                     {"golden", 4e-3},
                                                     {"other-backend:gl/vk", 4e-3},
                                                     {"other-backend:gl/gl:softpipe", 1.0}})});
  const RunComparison c = compareRuns(before, after, DriftRule{});
  ASSERT_EQ(c.drift.size(), 2u);
  // A comparison the earlier run could not make (its max error 0, with a
  // problem) is no baseline for drift.
  CaseResult unmade = withImages({{"other-backend:gl/vk", 0.0}});
  unmade.images[0].problem = "the images differ in size";
  EXPECT_TRUE(compareRuns(side("a.jsonl", {unmade}), after, DriftRule{}).drift.empty());
  EXPECT_EQ(c.drift[0].metric, "image error vs golden");
  EXPECT_EQ(c.drift[0].to, 4e-3);
  EXPECT_EQ(c.drift[1].metric, "image error vs other-backend:gl/vk");
  EXPECT_EQ(c.drift[1].from, 1e-5);
}

// A gl pass whose record carries `digest` as its listing's.
CaseResult ran(const std::string& id, const std::string& digest) {
  CaseResult r = result(id, "gl", Status::Pass);
  r.listingDigest = digest;
  return r;
}

// A result whose listing's text changed between the runs is named, so
// that a change of status can be laid at the shader's edit, not the
// driver's; records from before the digest say nothing either way.
TEST(CompareRuns, AListingEditedBetweenRunsIsNamed) {
  const RunComparison c = compareRuns(
      side("a.jsonl", {ran("edited", "1"), ran("same", "2"), ran("old", "")}),
      side("b.jsonl", {ran("edited", "3"), ran("same", "2"), ran("old", "4")}), DriftRule{});
  EXPECT_EQ(c.listingEdited, (std::vector<std::string>{"gl edited"}));
  std::ostringstream text;
  printComparison(text, c, DriftRule{});
  EXPECT_NE(text.str().find("; 1 ran another text of their listing"), std::string::npos)
      << text.str();
  EXPECT_NE(text.str().find("edited      gl edited: its listing's manifest or shader files"),
            std::string::npos)
      << text.str();
  EXPECT_EQ(comparisonToJson(c)["listing_edited"], nlohmann::json::array({"gl edited"}));
}

// A case that ended while its listing was being edited ran an unknown
// text: named as edited even where both records say so.
TEST(CompareRuns, ARecordOfAnEditDuringTheRunIsNamedAsEdited) {
  const RunComparison c = compareRuns(
      side("a.jsonl", {ran("both", kListingEditedDuringRun), ran("now", "1"), ran("same", "2")}),
      side("b.jsonl", {ran("both", kListingEditedDuringRun), ran("now", kListingEditedDuringRun),
                       ran("same", "2")}),
      DriftRule{});
  EXPECT_EQ(c.listingEdited, (std::vector<std::string>{"gl both", "gl now"}));
}

TEST(CompareRuns, BackendHalvesCompareCaseByCase) {
  const RunSide run = side(
      "r.jsonl", {result("x", "gl", Status::Pass), result("x", "vk", Status::CompatibilityWarning),
                  result("y", "gl", Status::Pass)});
  RunSide gl = run, vk = run;
  gl.backend = "gl";
  vk.backend = "vk";
  const RunComparison c = compareRuns(gl, vk, DriftRule{});
  ASSERT_EQ(c.regressions.size(), 1u);
  EXPECT_EQ(c.regressions[0].key, "x");
  EXPECT_EQ(c.removed, (std::vector<std::string>{"y"}));
  EXPECT_THROW(compareRuns(gl, run, DriftRule{}), UsageError);
}

}  // namespace
}  // namespace snell
