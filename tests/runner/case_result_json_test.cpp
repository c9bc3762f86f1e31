#include "runner/case_result_json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace snell {
namespace {

TEST(CaseResultJson, RoundTripsEveryField) {
  CaseResult r;
  r.caseId = "a/b/sphere";
  r.backend = "vk";
  r.status = Status::Fail;
  r.message = "R: 1 of 3";
  r.title = "t";
  r.sourceFile = "f.txt";
  r.sourceWhere = "Listing 1";
  r.driver = {"Vulkan", "1.3", "llvmpipe", "Mesa 22.3.6", "cpu"};
  r.vertices = 7;
  VaryingCheck v;
  v.name = "R";
  v.checked = 3;
  v.undefined = 1;
  v.failed = 1;
  v.worstSlack = std::numeric_limits<double>::infinity();
  v.worstVertex = 2;
  v.worstFailures.push_back({2, 1, 0.5f, 0.25, 0.2, 0.3, std::numeric_limits<double>::infinity()});
  r.varyings.push_back(v);
  r.compileLog = "log";
  r.seconds = 1.5;
  r.backendSeconds = 1.0;
  r.oracleSeconds = 0.25;
  r.phases[Phase::Start] = 0.125;
  r.phases[Phase::Oracle] = 0.25;
  r.phases[Phase::Draw] = 0.5;
  r.shard = "2/3";
  r.shardOf = "--filter '*' --backend vk";
  r.shardCases = {2, 1, 0};
  const CaseResult back = caseResultFromJson(nlohmann::json::parse(toJson(r).dump()));
  EXPECT_EQ(toJson(back), toJson(r));
  EXPECT_EQ(back.shardCases, (std::vector<std::size_t>{2, 1, 0}));
  EXPECT_TRUE(std::isinf(back.varyings[0].worstSlack));
  EXPECT_EQ(back.status, Status::Fail);
  EXPECT_DOUBLE_EQ(back.phases[Phase::Start], 0.125);
  EXPECT_DOUBLE_EQ(back.phases[Phase::Draw], 0.5);
}

TEST(CaseResultJson, PhasesAreOptionalButMustBeAnObject) {
  nlohmann::json older = toJson(CaseResult{});
  older.erase("phases");
  EXPECT_DOUBLE_EQ(caseResultFromJson(older).phases.total(), 0);
  nlohmann::json bad = toJson(CaseResult{});
  bad["phases"] = 3;
  EXPECT_THROW(caseResultFromJson(bad), nlohmann::json::exception);
  bad["phases"] = {{"draw", "slow"}};
  EXPECT_THROW(caseResultFromJson(bad), nlohmann::json::exception);
}

TEST(CaseResultJson, ShardCasesAreOptionalButMustBeCounts) {
  nlohmann::json record = toJson(CaseResult{});
  EXPECT_TRUE(caseResultFromJson(record).shardCases.empty());
  for (const nlohmann::json& bad :
       {nlohmann::json(3), nlohmann::json::parse("[1, -1]"), nlohmann::json::parse(R"(["a"])")}) {
    record["shard_cases"] = bad;
    EXPECT_THROW(caseResultFromJson(record), nlohmann::json::exception) << bad.dump();
  }
}

TEST(CaseResultJson, MalformedRecordThrows) {
  EXPECT_THROW(caseResultFromJson(nlohmann::json::parse(R"({"case": "x"})")),
               nlohmann::json::exception);
  nlohmann::json j = toJson(CaseResult{});
  j["status"] = "Sideways";
  EXPECT_THROW(caseResultFromJson(j), nlohmann::json::exception);
}

TEST(CaseResultJson, CountsOutOfRangeOrFractionalThrowInsteadOfCasting) {
  for (const char* bad : {"1e20", "-2.5", "18446744073709551616", "-1", "\"7\""}) {
    nlohmann::json j = toJson(CaseResult{});
    j["vertices"] = nlohmann::json::parse(bad);
    EXPECT_THROW(caseResultFromJson(j), nlohmann::json::exception) << bad;
  }
  nlohmann::json ok = toJson(CaseResult{});
  ok["vertices"] = 4753;
  EXPECT_EQ(caseResultFromJson(ok).vertices, 4753u);
}

}  // namespace
}  // namespace snell
