// Check kinds (runner/checks/): the results file, the summary table, the
// JUnit file and validation go through the registry, and each kind says
// what it found in its own words.
#include <gtest/gtest.h>

#include <sstream>

#include "core/errors.h"
#include "core/manifest.h"
#include "report/junit.h"
#include "report/summary_table.h"
#include "runner/case_result_json.h"
#include "runner/checks/check_kind.h"

namespace snell {
namespace {

CaseResult failingResult() {
  CaseResult r;
  r.caseId = "a/sphere";
  r.backend = "gl:llvmpipe-128";
  r.status = Status::Fail;
  r.vertices = 33;
  VaryingCheck refracted;
  refracted.name = "Refract";
  refracted.checked = 99;
  refracted.failed = 3;
  refracted.worstSlack = 4.5;
  r.varyings.push_back(refracted);
  ImageComparison golden;
  golden.against = "golden";
  golden.verdict = ImageVerdict::Fail;
  golden.maxError = 0.25;
  golden.compared = 1000;
  golden.failed = 7;
  r.images.push_back(golden);
  return r;
}

TEST(CheckKinds, VectorsAndImageAreRegisteredByName) {
  ASSERT_NE(findCheckKind("vectors"), nullptr);
  ASSERT_NE(findCheckKind("image"), nullptr);
  EXPECT_EQ(findCheckKind("pixels"), nullptr);
}

TEST(CheckKinds, JUnitFailureMessageSaysWhatEachKindFound) {
  const std::string xml = toJUnitXml({failingResult()});
  EXPECT_NE(xml.find("message=\"Fail: 3 of 99 components outside the spec interval, worst slack "
                     "4.500 in `Refract`: image vs golden: fail, max error 0.25, 7 of 1000 pixels "
                     "over the limit\""),
            std::string::npos)
      << xml;
}

TEST(CheckKinds, NothingWrongAddsNothingToTheMessage) {
  CaseResult r = failingResult();
  r.varyings[0].failed = 0;
  r.images[0].verdict = ImageVerdict::Pass;
  for (const auto& kind : checkKinds()) EXPECT_EQ(kind->junitMessage(r), "") << kind->name();
}

TEST(CheckKinds, EachKindRoundTripsItsFieldsThroughTheResultsFile) {
  const CaseResult before = failingResult();
  const nlohmann::json record = toJson(before);
  EXPECT_EQ(record.at("components_failed"), 3);
  EXPECT_EQ(record.at("images").size(), 1u);
  const CaseResult after = caseResultFromJson(record);
  ASSERT_EQ(after.varyings.size(), 1u);
  EXPECT_EQ(after.varyings[0].name, "Refract");
  EXPECT_EQ(after.varyings[0].failed, 3u);
  EXPECT_EQ(after.varyings[0].worstSlack, 4.5);
  ASSERT_EQ(after.images.size(), 1u);
  EXPECT_EQ(after.images[0].against, "golden");
  EXPECT_EQ(after.images[0].verdict, ImageVerdict::Fail);
  EXPECT_EQ(after.images[0].failed, 7u);
  // A record without a kind's fields is refused, not read as zeros.
  nlohmann::json broken = record;
  broken.erase("varyings");
  EXPECT_THROW(caseResultFromJson(broken), nlohmann::json::exception);
}

TEST(CheckKinds, SummaryTableHasEveryKindsColumnsAndFitsLongBackendNames) {
  std::ostringstream out;
  printSummaryTable(out, {failingResult()});
  const std::string table = out.str();
  std::istringstream lines(table);
  std::string header, row;
  std::getline(lines, header);
  std::getline(lines, row);
  for (const auto& kind : checkKinds())
    for (const SummaryColumn& column : kind->summaryColumns())
      EXPECT_NE(header.find(column.header), std::string::npos) << column.header << "\n" << table;
  // Columns line up: the status starts where its header does.
  EXPECT_EQ(header.find("status"), row.find("Fail")) << table;
  EXPECT_NE(row.find("4.500"), std::string::npos) << table;
  EXPECT_NE(row.find("gl:llvmpipe-128  Fail"), std::string::npos) << table;
}

// Nothing held against an interval reads "-", never 0.000; a value on the
// edge of its interval (slack exactly 1) is explained once, under the table.
TEST(CheckKinds, SlackReadsDashWhenNothingWasCheckedAndOneIsExplainedOnce) {
  CaseResult nothing = failingResult();
  nothing.varyings.clear();
  nothing.images.clear();
  nothing.status = Status::Fail;
  CaseResult edge = failingResult();
  edge.caseId = "b/sphere";
  edge.varyings[0].failed = 0;
  edge.varyings[0].worstSlack = 1.0;
  std::ostringstream out;
  printSummaryTable(out, {nothing, edge, edge});
  const std::string table = out.str();
  std::istringstream lines(table);
  std::string header, nothingRow;
  std::getline(lines, header);
  std::getline(lines, nothingRow);
  const std::size_t slackColumn =
      header.find("worst slack") + std::string("worst slack").size() - 1;
  ASSERT_LT(slackColumn, nothingRow.size()) << table;
  EXPECT_EQ(nothingRow[slackColumn], '-') << table;
  EXPECT_EQ(nothingRow.find(" 0.000 "), std::string::npos) << table;  // the time reads 0.000s
  const std::string note = "worst slack 1.000: a value on the edge of its interval";
  ASSERT_NE(table.find(note), std::string::npos) << table;
  EXPECT_EQ(table.find(note), table.rfind(note)) << table;
  std::ostringstream without;
  printSummaryTable(without, {failingResult()});
  EXPECT_EQ(without.str().find(note), std::string::npos) << without.str();
}

TEST(CheckKinds, AMisspeltCheckIsRefusedWithTheNearestKnownOne) {
  Manifest m;
  m.path = "shaders/x/manifest.toml";
  Case c;
  c.id = "x/sphere";
  c.manifest = &m;
  c.spec.checks = {"vectors", "imgae"};
  c.spec.line = 12;
  try {
    requireKnownChecks(c);
    FAIL() << "accepted";
  } catch (const UsageError& error) {
    EXPECT_STREQ(error.what(),
                 "shaders/x/manifest.toml:12: check `imgae` is not known; did you mean "
                 "\"image\"? known checks: \"vectors\", \"image\"");
  }
  c.spec.checks = {"vectors", "image"};
  EXPECT_NO_THROW(requireKnownChecks(c));
}

}  // namespace
}  // namespace snell
