// `snell bench` and `snell advise` as a user runs them, on a tiny image:
// the numbers come out for every method and backend, and are ordered where
// physics says so. Timing is never asserted.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "../cli/snell_process.h"

namespace snell::testing {
namespace {

namespace fs = std::filesystem;

class BenchCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // One folder per process: ctest runs each test in a process of its own, in parallel.
    dir_ = fs::temp_directory_path() / fmt::format("snell_bench_cli_test.{}", getpid());
    fs::remove_all(dir_);
    run_ = new Outcome(runSnell(
        fmt::format("bench --resolutions 24,48 --tessellations 8,4 --repeats 2 --warmup 0 --out {}",
                    dir_.string())));
  }
  static void TearDownTestSuite() {
    delete run_;
    fs::remove_all(dir_);
  }
  static nlohmann::json results() {
    return nlohmann::json::parse(readText(dir_ / "fresnel" / "bench.json"));
  }
  static inline fs::path dir_;
  static inline Outcome* run_ = nullptr;
};

TEST_F(BenchCli, WritesARecordForEveryMethodOnEveryBackendAndTheCharts) {
  ASSERT_EQ(run_->code, 0) << run_->out;
  const nlohmann::json doc = results();
  EXPECT_EQ(doc["scene"], "sphere");
  std::set<std::pair<std::string, std::string>> seen;
  for (const auto& r : doc["records"]) {
    seen.insert({r["method"].get<std::string>(), r["backend"].get<std::string>()});
    ASSERT_EQ(r["timings"].size(), 2u);
    for (const auto& t : r["timings"]) {
      EXPECT_GT(t["median_ms"].get<double>(), 0.0);
      EXPECT_LE(t["min_ms"].get<double>(), t["median_ms"].get<double>());
      EXPECT_LE(t["median_ms"].get<double>(), t["max_ms"].get<double>());
    }
    EXPECT_EQ(r["error"]["width"], 48);
    // The tessellations asked, fewest vertices first, timed at the largest
    // resolution: 4 x 8 is (4 + 1) x (8 + 1) vertices, 8 x 16 is 9 x 17.
    ASSERT_EQ(r["timings_by_tessellation"].size(), 2u) << r["method"];
    const auto& coarse = r["timings_by_tessellation"][0];
    const auto& fine = r["timings_by_tessellation"][1];
    EXPECT_EQ(coarse["stacks"], 4);
    EXPECT_EQ(coarse["slices"], 8);
    EXPECT_EQ(coarse["vertices"], 45);
    EXPECT_EQ(fine["vertices"], 153);
    EXPECT_EQ(fine["width"], 48);
    EXPECT_GT(fine["median_ms"].get<double>(), 0.0);
    EXPECT_GT(r["error"]["compared_pixels"].get<int>(), 48 * 48 / 10);
    EXPECT_LE(r["error"]["rms"].get<double>(), r["error"]["max"].get<double>());
    EXPECT_LE(r["error"]["de_mean"].get<double>(), r["error"]["de_p95"].get<double>() + 1e-9)
        << "a mean above the 95th percentile needs a heavy tail: " << r["method"];
  }
  const std::vector<std::string> methods{"1-constant-mix",       "2-empirical",
                                         "3-schlick-vertex",     "4-schlick-fragment",
                                         "5-schlick-dense-side", "6-exact-fragment"};
  for (const char* backend : {"gl", "vk"})
    for (const std::string& method : methods)
      EXPECT_TRUE(seen.count({"methods/fresnel/" + method, backend}))
          << method << " on " << backend;
  EXPECT_EQ(seen.size(), 12u);
  EXPECT_GT(fs::file_size(dir_ / "fresnel" / "pareto.svg"), 1000u);
  EXPECT_GT(fs::file_size(dir_ / "fresnel" / "pareto.png"), 1000u);
  EXPECT_GT(fs::file_size(dir_ / "fresnel" / "vertices.svg"), 1000u);
  EXPECT_GT(fs::file_size(dir_ / "fresnel" / "vertices.png"), 1000u);
  EXPECT_NE(run_->out.find("by sphere tessellation"), std::string::npos) << run_->out;
  // With no --methods every ladder runs, each into a folder of its own, and
  // the ablation table is written beside them.
  for (const char* ladder : {"dispersion", "refraction"})
    EXPECT_TRUE(fs::exists(dir_ / ladder / "bench.json")) << ladder;
  EXPECT_TRUE(fs::exists(dir_ / "ablation.json"));
  EXPECT_NE(run_->out.find("ablation of the physics reference"), std::string::npos) << run_->out;
  EXPECT_NE(run_->out.find("Pareto front"), std::string::npos) << run_->out;
}

// Physics, not timing: the exact Fresnel method is nearest the reference and
// the constant mix farthest, on every backend and by both metrics.
TEST_F(BenchCli, ExactFresnelIsNearestTheReferenceAndTheConstantMixFarthest) {
  ASSERT_EQ(run_->code, 0) << run_->out;
  const nlohmann::json doc = results();
  for (const std::string metric : {"rms", "de_mean"}) {
    for (const std::string backend : {"gl", "vk"}) {
      std::string best, worst;
      double bestError = 1e300, worstError = -1;
      for (const auto& r : doc["records"]) {
        if (r["backend"] != backend) continue;
        const double e = r["error"][metric].get<double>();
        if (e < bestError) bestError = e, best = r["method"].get<std::string>();
        if (e > worstError) worstError = e, worst = r["method"].get<std::string>();
      }
      EXPECT_EQ(best, "methods/fresnel/6-exact-fragment") << metric << " on " << backend;
      EXPECT_EQ(worst, "methods/fresnel/1-constant-mix") << metric << " on " << backend;
    }
  }
}

// From air into glass the cosine on the less dense side is cos θi: the
// dense-side rung must draw what plain Schlick per fragment draws.
TEST_F(BenchCli, SchlickDenseSideEqualsSchlickWhenLightEntersTheGlass) {
  ASSERT_EQ(run_->code, 0) << run_->out;
  const nlohmann::json doc = results();
  for (const std::string backend : {"gl", "vk"}) {
    double plain = -1, denseSide = -1;
    for (const auto& r : doc["records"]) {
      if (r["backend"] != backend) continue;
      if (r["method"] == "methods/fresnel/4-schlick-fragment") plain = r["error"]["rms"];
      if (r["method"] == "methods/fresnel/5-schlick-dense-side") denseSide = r["error"]["rms"];
    }
    ASSERT_GT(plain, 0.0) << backend;
    EXPECT_NEAR(denseSide, plain, 1e-3 * plain) << backend;
  }
}

// The error by angle of incidence adds up to the whole image's error, and
// near normal incidence (where R0 = 0.04, not the constant 0.1) the exact
// method is far nearer physics than the constant mix.
TEST_F(BenchCli, ErrorByAngleAddsUpAndTheConstantMixMissesNormalIncidence) {
  ASSERT_EQ(run_->code, 0) << run_->out;
  const nlohmann::json doc = results();
  std::map<std::pair<std::string, std::string>, double> nearNormal;
  for (const auto& r : doc["records"]) {
    const auto& bins = r["error_by_angle"];
    ASSERT_EQ(bins.size(), 9u) << r["method"];
    std::size_t pixels = 0;
    double squares = 0;
    for (const auto& bin : bins) {
      const auto n = bin["compared_pixels"].get<std::size_t>();
      pixels += n;
      squares += n * std::pow(bin["rms"].get<double>(), 2);
    }
    const auto all = r["error"]["compared_pixels"].get<std::size_t>();
    EXPECT_EQ(pixels, all) << r["method"];
    EXPECT_NEAR(std::sqrt(squares / all), r["error"]["rms"].get<double>(), 1e-9) << r["method"];
    nearNormal[{r["method"], r["backend"]}] = bins[0]["de_mean"].get<double>();
  }
  for (const std::string backend : {"gl", "vk"}) {
    const double exact = nearNormal[std::make_pair("methods/fresnel/6-exact-fragment", backend)];
    const double constant = nearNormal[std::make_pair("methods/fresnel/1-constant-mix", backend)];
    EXPECT_LT(10 * exact, constant) << backend;
  }
  EXPECT_GT(fs::file_size(dir_ / "fresnel" / "angle.svg"), 1000u);
}

TEST_F(BenchCli, AdviseReadsTheLastBenchAndAnswersInJson) {
  ASSERT_EQ(run_->code, 0) << run_->out;
  const std::string results = (dir_ / "fresnel" / "bench.json").string();
  // A budget nothing but a perfect method meets: exit 1, the nearest miss named.
  const Outcome none = runSnell("advise --scene sphere --budget 0 --results " + results);
  EXPECT_EQ(none.code, 1) << none.out;
  EXPECT_NE(none.out.find("no method within"), std::string::npos) << none.out;
  // A budget every method meets: the cheapest is named with a runner-up.
  const Outcome all = runSnell("advise --scene sphere --budget 1000 --json --results " + results);
  ASSERT_EQ(all.code, 0) << all.out;
  const nlohmann::json doc = nlohmann::json::parse(all.out);
  ASSERT_EQ(doc["backends"].size(), 2u);
  for (const auto& b : doc["backends"]) {
    EXPECT_FALSE(b["choice"].is_null());
    EXPECT_FALSE(b["runner_up"].is_null());
    EXPECT_LE(b["choice"]["ms_per_frame"].get<double>(),
              b["runner_up"]["ms_per_frame"].get<double>());
  }
}

TEST(BenchCliInput, BadInputIsOneMessageAndExitTwo) {
  const std::string badOut = fmt::format("/tmp/snell_bench_bad.{}", getpid());
  Outcome o = runSnell("advise --scene sphere --budget 1 --results /nonexistent/bench.json");
  EXPECT_EQ(o.code, 2) << o.out;
  EXPECT_NE(o.out.find("run `snell bench` first"), std::string::npos) << o.out;
  o = runSnell("advise --ladder nonexistent --scene sphere --budget 1");
  EXPECT_EQ(o.code, 2) << o.out;
  EXPECT_NE(o.out.find("nonexistent/bench.json"), std::string::npos) << o.out;
  o = runSnell("bench --scene torus --resolutions 16 --repeats 1 --out " + badOut);
  EXPECT_EQ(o.code, 2) << o.out;
  EXPECT_NE(o.out.find("analytic sphere"), std::string::npos) << o.out;
  o = runSnell("bench --tessellations 1 --out " + badOut);
  EXPECT_EQ(o.code, 2) << o.out;
  EXPECT_NE(o.out.find("--tessellations: 1 stacks"), std::string::npos) << o.out;
  // The scene is refused first: dropping --tessellations would not help.
  o = runSnell("bench --scene torus --tessellations 8 --out " + badOut);
  EXPECT_EQ(o.code, 2) << o.out;
  EXPECT_NE(o.out.find("bench the `sphere` scene, not `torus`"), std::string::npos) << o.out;
  o = runSnell("bench --metric psnr --out " + badOut);
  EXPECT_EQ(o.code, 2) << o.out;
  EXPECT_NE(o.out.find("unknown error metric"), std::string::npos) << o.out;
  std::filesystem::remove_all(badOut);
}

// --budget '' was taken as 0 (exit 1, "no method within de_mean 0") and
// --budget abc met a bare "Could not convert"; --resolutions '' and
// --tessellations '' were said to hold 0, out of range. Each is exit 2,
// naming the option and what it takes.
TEST(BenchCliInput, AnEmptyOrNonNumericValueNamesItsOption) {
  const std::string badOut = fmt::format("/tmp/snell_bench_empty.{}", getpid());
  const std::string results = "--results /nonexistent/bench.json";
  Outcome o = runSnell("advise --scene sphere --budget '' " + results);
  EXPECT_EQ(o.code, 2) << o.out;
  EXPECT_NE(o.out.find("--budget: empty; give the largest error allowed"), std::string::npos)
      << o.out;
  o = runSnell("advise --scene sphere --budget abc " + results);
  EXPECT_EQ(o.code, 2) << o.out;
  EXPECT_NE(o.out.find("--budget: `abc` is not a number; give the largest error allowed"),
            std::string::npos)
      << o.out;
  o = runSnell("bench --resolutions '' --out " + badOut);
  EXPECT_EQ(o.code, 2) << o.out;
  EXPECT_NE(o.out.find("--resolutions: an empty list of sizes"), std::string::npos) << o.out;
  o = runSnell("bench --tessellations '' --out " + badOut);
  EXPECT_EQ(o.code, 2) << o.out;
  EXPECT_NE(o.out.find("--tessellations: an empty list of stacks"), std::string::npos) << o.out;
  EXPECT_FALSE(std::filesystem::exists(badOut));
}

}  // namespace
}  // namespace snell::testing
