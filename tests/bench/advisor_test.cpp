// The advisor's choice on a small hand-made results file.
#include "bench/advisor.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/errors.h"

namespace snell::bench {
namespace {

// Three methods on gl, two on vk; times and errors chosen so that the
// cheapest method is not the most accurate and the order differs per backend.
constexpr const char* kResults = R"({
  "scene": "sphere", "reference": "hand-made",
  "records": [
    {"method": "m/1-cheap", "backend": "gl", "timings": [{"width": 64, "height": 64, "median_ms": 1.0}],
     "error": {"rms": 0.10, "max": 0.5, "de_mean": 6.0, "de_p95": 12.0}},
    {"method": "m/2-middle", "backend": "gl", "timings": [{"width": 64, "height": 64, "median_ms": 2.0}],
     "error": {"rms": 0.03, "max": 0.2, "de_mean": 2.0, "de_p95": 4.0}},
    {"method": "m/3-exact", "backend": "gl", "timings": [{"width": 64, "height": 64, "median_ms": 3.0}],
     "error": {"rms": 0.01, "max": 0.1, "de_mean": 0.5, "de_p95": 1.0}},
    {"method": "m/2-middle", "backend": "vk", "timings": [{"width": 64, "height": 64, "median_ms": 5.0}],
     "error": {"rms": 0.03, "max": 0.2, "de_mean": 2.0, "de_p95": 4.0}},
    {"method": "m/3-exact", "backend": "vk", "timings": [{"width": 64, "height": 64, "median_ms": 4.0}],
     "error": {"rms": 0.01, "max": 0.1, "de_mean": 0.5, "de_p95": 1.0}}
  ]
})";

BenchResults handMade() {
  const auto path = std::filesystem::temp_directory_path() / "snell_advisor_test.json";
  std::ofstream(path) << kResults;
  BenchResults results = readBenchResults(path);
  std::filesystem::remove(path);
  return results;
}

TEST(Advisor, NamesTheCheapestWithinBudgetAndTheRunnerUp) {
  const std::vector<Advice> advice = advise(handMade(), "sphere", 2.5, "de_mean");
  ASSERT_EQ(advice.size(), 2u);
  EXPECT_EQ(advice[0].backend, "gl");
  ASSERT_TRUE(advice[0].choice && advice[0].runnerUp);
  EXPECT_EQ(advice[0].choice->method, "m/2-middle");
  EXPECT_EQ(advice[0].runnerUp->method, "m/3-exact");
  // On vk the exact method is the faster one: it wins, middle is runner-up.
  ASSERT_TRUE(advice[1].choice && advice[1].runnerUp);
  EXPECT_EQ(advice[1].choice->method, "m/3-exact");
  EXPECT_EQ(advice[1].runnerUp->method, "m/2-middle");
}

TEST(Advisor, TheMetricAndTheBudgetDecide) {
  // A budget the cheap method meets in RMS: it wins there.
  std::vector<Advice> advice = advise(handMade(), "sphere", 0.1, "rms", "gl");
  ASSERT_EQ(advice.size(), 1u);
  EXPECT_EQ(advice[0].choice->method, "m/1-cheap");
  // A budget only the exact method meets: no runner-up.
  advice = advise(handMade(), "sphere", 1.0, "de_p95", "gl");
  EXPECT_EQ(advice[0].choice->method, "m/3-exact");
  EXPECT_FALSE(advice[0].runnerUp);
  // Nothing within budget: no choice, the nearest miss is named.
  advice = advise(handMade(), "sphere", 0.1, "de_mean", "gl");
  EXPECT_FALSE(advice[0].choice);
  ASSERT_TRUE(advice[0].mostAccurate);
  EXPECT_EQ(advice[0].mostAccurate->method, "m/3-exact");
}

TEST(Advisor, RefusesWhatTheResultsCannotAnswer) {
  EXPECT_THROW(advise(handMade(), "torus", 1.0, "de_mean"), UsageError);
  EXPECT_THROW(advise(handMade(), "sphere", 1.0, "psnr"), UsageError);
  EXPECT_THROW(advise(handMade(), "sphere", -1.0, "de_mean"), UsageError);
  EXPECT_THROW(advise(handMade(), "sphere", 1.0, "de_mean", "gl:softpipe"), UsageError);
  EXPECT_THROW(readBenchResults("/nonexistent/bench.json"), UsageError);
}

}  // namespace
}  // namespace snell::bench
