// The advisor's choice on a small hand-made results file.
#include "bench/advisor.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

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

BenchResults read(const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / "snell_advisor_test.json";
  std::ofstream(path) << text;
  struct Remove {
    std::filesystem::path path;
    ~Remove() { std::filesystem::remove(path); }
  } remove{path};
  return readBenchResults(path);
}

BenchResults handMade() { return read(kResults); }

// The message of the UsageError `f` throws, or "" when it throws none.
template <class F>
std::string refusal(F f) {
  try {
    f();
  } catch (const UsageError& error) {
    return error.what();
  }
  return "";
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
  // What to ask instead: the measured scene, the measured backends.
  EXPECT_NE(refusal([] {
              advise(handMade(), "cube", 1.0, "de_mean");
            }).find("not `cube`: ask about `sphere`"),
            std::string::npos);
  EXPECT_NE(refusal([] {
              advise(handMade(), "sphere", 1.0, "de_mean", "foo");
            }).find("they measure gl, vk"),
            std::string::npos);
}

// A file no advice can come from is refused as it is read: no records, an
// error that is no distance (it would be the most accurate), a method
// measured twice (it would be its own runner-up).
TEST(Advisor, ResultsThatMeasureNothingSoundAreRefused) {
  const std::string first = R"({"method": "m/1", "backend": "gl", "timings": [{"width": 64,
      "height": 64, "median_ms": 1.0}], "error": {"rms": 0.1, "max": 0.5, "de_mean": 6.0,
      "de_p95": 12.0}})";
  std::string negative = first;
  negative.replace(negative.find("6.0"), 3, "-6.0");
  for (const auto& [records, expected] : std::vector<std::pair<std::string, std::string>>{
           {"", "it holds no measurement"},
           {negative, "m/1 on gl has an error of -6"},
           {first + "," + first, "m/1 on gl is measured twice"}}) {
    const std::string message =
        refusal([&] { read(R"({"scene": "sphere", "records": [)" + records + "]}"); });
    EXPECT_NE(message.find(expected), std::string::npos) << records << ": " << message;
  }
  EXPECT_EQ(refusal([&] { read(R"({"scene": "sphere", "records": [)" + first + "]}"); }), "");
}

}  // namespace
}  // namespace snell::bench
