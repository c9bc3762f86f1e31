#include "report/phase_summary.h"

#include <gtest/gtest.h>

#include <sstream>

namespace snell {
namespace {

CaseResult timed(const std::string& backend, std::size_t vertices, double draw, double oracle,
                 double start) {
  CaseResult r;
  r.backend = backend;
  r.vertices = vertices;
  r.varyings.resize(2);  // two vectors per vertex
  r.phases[Phase::Draw] = draw;
  r.phases[Phase::Oracle] = oracle;
  r.phases[Phase::Start] = start;
  r.seconds = draw + oracle;  // start comes on top of the case's own time
  return r;
}

TEST(PhaseSummary, SumsEachBackendAndCountsTheOracleInVectorsPerSecond) {
  const std::vector<CaseResult> results{timed("gl", 100, 0.5, 1.5, 0.25),
                                        timed("gl", 300, 0.5, 1.5, 0), timed("vk", 10, 1, 0, 0.5)};
  const RunTiming t = summarizeTiming(results, 3.5, 2, 0.125);
  ASSERT_EQ(t.backends.size(), 2u);
  const BackendTiming& gl = t.backends.at("gl");
  EXPECT_EQ(gl.cases, 2u);
  EXPECT_EQ(gl.vectors, 800u);
  EXPECT_DOUBLE_EQ(gl.phases[Phase::Oracle], 3);
  EXPECT_DOUBLE_EQ(gl.phases[Phase::Start], 0.25);
  EXPECT_DOUBLE_EQ(gl.caseSeconds, 4);
  EXPECT_DOUBLE_EQ(gl.vectorsPerSecond(), 200);  // 800 over 4 s, the oracle's 3 s included
  EXPECT_DOUBLE_EQ(t.backends.at("vk").vectorsPerSecond(), 20);

  const nlohmann::json j = runTimingJson(t);
  EXPECT_DOUBLE_EQ(j.at("wall_seconds").get<double>(), 3.5);
  EXPECT_EQ(j.at("workers").get<int>(), 2);
  EXPECT_DOUBLE_EQ(j.at("backends").at("gl").at("phases").at("oracle").get<double>(), 3);
  EXPECT_DOUBLE_EQ(j.at("backends").at("gl").at("vectors_per_second").get<double>(), 200);
}

TEST(PhaseSummary, PrintsEveryPhaseAndTheWallTime) {
  std::ostringstream out;
  printRunTiming(out, summarizeTiming({timed("gl", 100, 0.5, 1.5, 0.25)}, 3.5, 1, 0));
  const std::string text = out.str();
  for (Phase p : kAllPhases)
    EXPECT_NE(text.find(std::string(phaseName(p))), std::string::npos) << phaseName(p);
  EXPECT_NE(text.find("oracle          1.500"), std::string::npos) << text;
  EXPECT_NE(text.find("gl: 200 vectors checked, 100 per second"), std::string::npos) << text;
  EXPECT_NE(text.find("wall 3.50 s with 1 worker "), std::string::npos) << text;
}

TEST(PhaseSummary, NothingCheckedIsZeroPerSecondNotADivisionByZero) {
  const RunTiming t = summarizeTiming({CaseResult{}}, 0.1, 1, 0);
  EXPECT_DOUBLE_EQ(t.backends.begin()->second.vectorsPerSecond(), 0);
}

}  // namespace
}  // namespace snell
