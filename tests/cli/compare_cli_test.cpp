// `snell compare` on hand-made results files: exit 1 on a regression and
// only then, JSON on request, the two backends of one run side by side.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "snell_process.h"

namespace {

namespace fs = std::filesystem;

using snell::testing::Outcome;

Outcome snell(const std::string& args) { return snell::testing::runSnell(args); }

nlohmann::json record(const std::string& id, const std::string& backend, const std::string& status,
                      double slack) {
  return {{"case", id},
          {"backend", backend},
          {"status", status},
          {"message", ""},
          {"title", ""},
          {"source", {{"file", ""}, {"where", ""}}},
          {"driver",
           {{"api", ""},
            {"api_version", ""},
            {"renderer", ""},
            {"driver_version", ""},
            {"device_type", ""}}},
          {"vertices", 1},
          {"varyings",
           {{{"name", "Refract"},
             {"checked", 3},
             {"undefined", 0},
             {"failed", 0},
             {"worst_slack", slack},
             {"worst_vertex", 0},
             {"first_failures", nlohmann::json::array()}}}},
          {"images", nlohmann::json::array()},
          {"compile_log", ""},
          {"seconds", 0.1},
          {"backend_seconds", 0.1},
          {"oracle_seconds", 0.0}};
}

fs::path writeRun(const std::string& name, const std::vector<nlohmann::json>& records) {
  const fs::path path =
      fs::temp_directory_path() / fmt::format("snell-compare-{}-{}", getpid(), name);
  std::ofstream out(path);
  for (const auto& r : records) out << r.dump() << "\n";
  return path;
}

TEST(CompareCli, RegressionIsExit1AndListed) {
  const fs::path a =
      writeRun("a.jsonl", {record("x/y/z", "gl", "Pass", 0.1), record("x/y/w", "gl", "Fail", 2.0)});
  const fs::path b =
      writeRun("b.jsonl", {record("x/y/z", "gl", "Fail", 3.0), record("x/y/w", "gl", "Pass", 0.1)});
  const Outcome o = snell(fmt::format("compare {} {}", a.string(), b.string()));
  EXPECT_EQ(o.code, 1) << o.out;
  EXPECT_NE(o.out.find("1 regressions, 1 fixes"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("regression  gl x/y/z: Pass -> Fail"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("drift       gl x/y/z: worst slack 0.1 -> 3 (x30.0)"), std::string::npos)
      << o.out;
  // The other way round it is a fix and a regression again; B against
  // itself has nothing to report and exits 0.
  EXPECT_EQ(snell(fmt::format("compare {} {}", b.string(), b.string())).code, 0);
  const Outcome json =
      snell(fmt::format("compare --json {} {} {}", a.string(), b.string(), b.string()));
  EXPECT_EQ(json.code, 1) << json.out;
  const auto parsed = nlohmann::json::parse(json.out);
  ASSERT_EQ(parsed.size(), 2u);
  EXPECT_EQ(parsed[0]["regressions"][0]["key"], "gl x/y/z");
  EXPECT_TRUE(parsed[1]["regressions"].empty());
  fs::remove(a);
  fs::remove(b);
}

TEST(CompareCli, BackendHalvesOfOneRun) {
  const fs::path r =
      writeRun("r.jsonl", {record("x/y/z", "gl", "Pass", 0.1), record("x/y/z", "vk", "Pass", 0.5)});
  const Outcome o = snell(fmt::format("compare {0}@gl {0}@vk", r.string()));
  EXPECT_EQ(o.code, 0) << o.out;
  EXPECT_NE(o.out.find("drift       x/y/z: worst slack 0.1 -> 0.5"), std::string::npos) << o.out;
  // One side with a backend and one without is a usage error.
  EXPECT_EQ(snell(fmt::format("compare {0}@gl {0}", r.string())).code, 2);
  fs::remove(r);
}

TEST(CompareCli, MalformedFileIsExit2WithItsLine) {
  const fs::path bad = writeRun("bad.jsonl", {record("x/y/z", "gl", "Pass", 0.1)});
  std::ofstream(bad, std::ios::app) << "{\"case\": \"half\"}\n";
  const Outcome o = snell(fmt::format("compare {0} {0}", bad.string()));
  EXPECT_EQ(o.code, 2) << o.out;
  EXPECT_NE(o.out.find(bad.string() + ":2:"), std::string::npos) << o.out;
  fs::remove(bad);
}

// A gate that reads a mistaken or unfinished file as a run with fewer cases
// would pass with everything "removed": each of these is exit 2 instead.
TEST(CompareCli, AFileThatIsNoFinishedRunIsExit2) {
  const fs::path run = writeRun(
      "whole.jsonl", {record("x/y/z", "gl", "Pass", 0.1), record("x/y/w", "gl", "Pass", 0.1)});
  const fs::path empty = writeRun("empty.jsonl", {});
  const fs::path torn = writeRun("torn.jsonl", {record("x/y/z", "gl", "Pass", 0.1)});
  std::ofstream(torn, std::ios::app) << record("x/y/w", "gl", "Pass", 0.1).dump().substr(0, 40);
  const fs::path folder = fs::temp_directory_path() / fmt::format("snell-compare-{}-dir", getpid());
  fs::create_directories(folder);
  for (const auto& [other, expected] : std::vector<std::pair<std::string, std::string>>{
           {run.string() + "@nope", "holds no results of backend `nope` (it holds gl)"},
           {run.string() + "@", "name a backend after the @"},
           {folder.string(), "is a folder"},
           {empty.string(), "holds no results"},
           {torn.string(), torn.string() + ":2: the last record is cut off"}}) {
    const Outcome o = snell(fmt::format("compare {}{} {}", run.string(),
                                        other.find('@') != std::string::npos ? "@gl" : "", other));
    EXPECT_EQ(o.code, 2) << other << "\n" << o.out;
    EXPECT_NE(o.out.find(expected), std::string::npos) << other << "\n" << o.out;
  }
  for (const fs::path& path : {run, empty, torn, folder}) fs::remove(path);
}

// An interrupted run is compared (it is what there is), with a note that
// its missing cases were never reached; they are listed as not reached, not
// as removed, and the gate does not pass (exit 1, as merge's): the cases
// it did not reach were not checked.
TEST(CompareCli, AnInterruptedRunIsNotedAndDoesNotPass) {
  nlohmann::json unfinished = record("x/y/z", "gl", "Pass", 0.1);
  unfinished["incomplete"] = true;
  const fs::path whole =
      writeRun("w.jsonl", {record("x/y/z", "gl", "Pass", 0.1), record("x/y/w", "gl", "Pass", 0.1)});
  const fs::path part = writeRun("p.jsonl", {unfinished});
  const Outcome o = snell(fmt::format("compare {} {}", whole.string(), part.string()));
  EXPECT_EQ(o.code, 1) << o.out;
  EXPECT_NE(o.out.find("exit 1: " + part.string() + " (1 case(s) of " + whole.string() +
                       " not reached) is an interrupted run"),
            std::string::npos)
      << o.out;
  EXPECT_NE(o.out.find(part.string() + " is an interrupted run"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("0 removed, 1 not reached"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("not reached  gl x/y/w"), std::string::npos) << o.out;
  // An interrupted earlier run leaves nothing of the later one unchecked.
  const Outcome earlier = snell(fmt::format("compare {} {}", part.string(), whole.string()));
  EXPECT_EQ(earlier.code, 0) << earlier.out;
  fs::remove(whole);
  fs::remove(part);
}

}  // namespace
