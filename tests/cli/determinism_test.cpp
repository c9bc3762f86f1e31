// Verdicts that do not wobble: the same build on the same driver gives the
// same statuses and metric values, bit for bit, whatever the run, the
// number of llvmpipe/lavapipe threads and the number of workers.
// SNELL_DETERMINISM_RUNS sets how many times the same run is repeated
// (default 3, so CI stays short; ci/nightly asks for 10), and
// SNELL_DETERMINISM_FILTER which cases (default Listing 14.1's: vectors
// from the vertex stage, images on two scenes; ci/nightly asks for the
// whole catalog).
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;

// The results of one run with timings removed: everything else must repeat.
std::string filter() {
  const char* text = std::getenv("SNELL_DETERMINISM_FILTER");
  return text == nullptr ? "orange-book/14.1-fresnel/*" : text;
}

std::string runResults(const std::string& environment, int jobs) {
  const fs::path json =
      fs::temp_directory_path() / fmt::format("snell-determinism-{}.jsonl", getpid());
  const std::string command = fmt::format("{} {} run -j {} --filter '{}' --json {} >/dev/null 2>&1",
                                          environment, SNELL_BINARY, jobs, filter(), json.string());
  const int status = std::system(command.c_str());
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << command;
  std::ifstream in(json);
  std::string out;
  for (std::string line; std::getline(in, line);) {
    nlohmann::json j = nlohmann::json::parse(line);
    for (const char* timing : {"seconds", "backend_seconds", "oracle_seconds", "phases",
                               "oracle_results", "oracle_stored"})
      j.erase(timing);
    out += j.dump() + "\n";
  }
  fs::remove(json);
  return out;
}

int repeats() {
  const char* text = std::getenv("SNELL_DETERMINISM_RUNS");
  if (text == nullptr) return 3;
  const int runs = std::atoi(text);
  EXPECT_GE(runs, 2) << "SNELL_DETERMINISM_RUNS must be at least 2, not '" << text << "'";
  return runs;
}

// Every run computes its oracle results afresh (no stored ones), so the
// oracle's own determinism is under test too.
constexpr const char* kFresh = "SNELL_ORACLE_CACHE=off";

TEST(Determinism, RepeatedRunsThreadCountsAndWorkerCountsAgreeBitForBit) {
  const std::string first = runResults(kFresh, 2);
  ASSERT_FALSE(first.empty());
  const int runs = repeats();
  for (int run = 1; run < runs; ++run) EXPECT_EQ(runResults(kFresh, 2), first) << "run " << run;
  for (const char* threads : {"0", "1", "2"})
    for (int jobs : {1, 2})
      EXPECT_EQ(runResults(fmt::format("{} LP_NUM_THREADS={}", kFresh, threads), jobs), first)
          << "LP_NUM_THREADS=" << threads << " -j " << jobs;
}

// A run that reads its oracle results from the store (written by the run
// before it) gives the verdicts of one that computes them.
TEST(Determinism, StoredOracleResultsGiveTheVerdictsOfComputedOnes) {
  const fs::path store =
      fs::temp_directory_path() / fmt::format("snell-determinism-store-{}", getpid());
  fs::remove_all(store);
  const std::string computed = runResults(kFresh, 2);
  ASSERT_FALSE(computed.empty());
  const std::string withStore = fmt::format("SNELL_ORACLE_CACHE={}", store.string());
  EXPECT_EQ(runResults(withStore, 2), computed) << "the run that stores them";
  ASSERT_TRUE(fs::exists(store));
  EXPECT_EQ(runResults(withStore, 1), computed) << "a run that reads them";
  fs::remove_all(store);
}

}  // namespace
