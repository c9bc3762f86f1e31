// Real faults in real workers: a listing that never finishes on either
// backend, and a worker killed from outside. Each costs only its own case.
#include <fcntl.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "snell_process.h"

namespace {

namespace fs = std::filesystem;

constexpr std::size_t kFresnelCases = 4;  // sphere, sweep, torus, stretched

// The published Listing 14.1 beside the endless-loop fault.
fs::path shadersWithFault() {
  const fs::path dir = fs::temp_directory_path() / fmt::format("snell-isolation-{}", getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::copy(SNELL_SOURCE_ROOT "/shaders/orange-book/14.1-fresnel", dir / "fresnel");
  fs::copy(SNELL_SOURCE_ROOT "/tests/faults/endless-loop", dir / "endless-loop");
  return dir;
}

std::map<std::string, nlohmann::json> resultsByKey(const fs::path& file) {
  std::map<std::string, nlohmann::json> out;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    const auto j = nlohmann::json::parse(line);
    out[j["backend"].get<std::string>() + " " + j["case"].get<std::string>()] = j;
  }
  return out;
}

using snell::testing::runSnell;
using snell::testing::spawnSnell;

int exitCode(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The `snell worker` children of `parent`, read from /proc.
std::vector<pid_t> workersOf(pid_t parent) {
  std::vector<pid_t> workers;
  for (const auto& entry : fs::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream stat(entry.path() / "stat");
    std::string text((std::istreambuf_iterator<char>(stat)), {});
    const std::size_t close = text.rfind(')');
    if (close == std::string::npos) continue;
    std::istringstream rest(text.substr(close + 2));
    char state;
    pid_t ppid = 0;
    rest >> state >> ppid;
    if (ppid != parent || state == 'Z') continue;  // a reaped-to-be probe is no worker
    // `worker --describe` only brings a driver up to see that it can: it is
    // over before the cases start and runs none of them.
    std::ifstream cmdline(entry.path() / "cmdline");
    const std::string args((std::istreambuf_iterator<char>(cmdline)), {});
    // An exiting process's cmdline reads empty: only a worker that says so counts.
    if (args.find("worker") == std::string::npos || args.find("--describe") != std::string::npos)
      continue;
    workers.push_back(std::stoi(name));
  }
  return workers;
}

TEST(Isolation, EndlessListingTimesOutOnBothBackendsAndOthersPass) {
  const fs::path shaders = shadersWithFault();
  const fs::path json = shaders / "results.jsonl";
  const pid_t pid = spawnSnell(
      {"run", "-j", "2", "--reruns", "0", "--shaders", shaders.string(), "--json", json.string()});
  EXPECT_EQ(exitCode(pid), 1);
  const auto results = resultsByKey(json);
  ASSERT_EQ(results.size(), 2u * (1 + kFresnelCases));
  for (const auto& [key, result] : results)
    EXPECT_EQ(result["status"],
              key.find("faults/endless-loop") != std::string::npos ? "Timeout" : "Pass")
        << key;
  // A timed-out case keeps what the catalog and the driver probe know (its
  // record had an empty title, source and driver), and its phases add up to
  // its time (all zero, against seconds of it).
  for (const char* backend : {"gl", "vk"}) {
    const auto& lost = results.at(std::string(backend) + " faults/endless-loop/sweep");
    EXPECT_FALSE(lost["title"].get<std::string>().empty()) << lost;
    EXPECT_FALSE(lost["source"]["file"].get<std::string>().empty()) << lost;
    EXPECT_FALSE(lost["driver"]["renderer"].get<std::string>().empty()) << lost;
    double phases = 0;
    for (const auto& [phase, seconds] : lost["phases"].items()) phases += seconds.get<double>();
    EXPECT_NEAR(phases, lost["seconds"].get<double>(), 1e-6) << lost;
  }
  fs::remove_all(shaders);
}

// A real `snell worker`, in the middle of a case, gets a fatal signal from
// outside: SIGKILL as an out-of-memory killer sends, SIGABRT as an assertion
// inside a driver raises.
class IsolationSignal : public ::testing::TestWithParam<int> {};

TEST_P(IsolationSignal, WorkerKilledFromOutsideIsACrashOfItsCaseOnly) {
  const int signal = GetParam();
  const fs::path shaders = shadersWithFault();
  const fs::path json = shaders / "results.jsonl";
  // One worker, the endless case first: it is the case running when the
  // worker is killed; the Fresnel cases after it need a fresh worker.
  const fs::path out = shaders / "out";
  const pid_t pid =
      spawnSnell({"run", "-j", "1", "--backend", "gl", "--timeout", "120", "--reruns", "0",
                  "--shaders", shaders.string(), "--out", out.string(), "--json", json.string()});
  std::vector<pid_t> workers;
  for (int k = 0; k < 200 && workers.empty(); ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    workers = workersOf(pid);
  }
  ASSERT_EQ(workers.size(), 1u);
  std::this_thread::sleep_for(std::chrono::seconds(1));  // well inside the endless case
  // What a worker killed while writing its image leaves: removed with it;
  // another process's temporary is kept.
  const fs::path caseOut = out / "faults" / "endless-loop" / "sweep";
  fs::create_directories(caseOut);
  const fs::path left = caseOut / fmt::format("gl.exr.tmp{}.exr", workers[0]);
  const fs::path others = caseOut / fmt::format("gl.exr.tmp{}1.exr", workers[0]);
  std::ofstream(left) << "half an image";
  std::ofstream(others) << "another process's";
  kill(workers[0], signal);
  EXPECT_EQ(exitCode(pid), 1);
  const auto results = resultsByKey(json);
  ASSERT_EQ(results.size(), 1 + kFresnelCases);
  const auto& killed = results.at("gl faults/endless-loop/sweep");
  EXPECT_EQ(killed["status"], "Crash");
  EXPECT_FALSE(fs::exists(left));
  EXPECT_TRUE(fs::exists(others));
  EXPECT_NE(killed["message"].get<std::string>().find(fmt::format("signal {}", signal)),
            std::string::npos)
      << killed;
  for (const auto& [key, result] : results)
    if (key.find("orange-book/14.1-fresnel") != std::string::npos) {
      EXPECT_EQ(result["status"], "Pass") << key;
    }
  fs::remove_all(shaders);
}

INSTANTIATE_TEST_SUITE_P(Signals, IsolationSignal, ::testing::Values(SIGKILL, SIGABRT));

// snell rebuilt (or replaced) while a run goes on: the workers started after
// that are still the run's own build, not whatever now lies at its path
// (here a script that would exit 3 as every later worker).
TEST(Isolation, WorkersStartedAfterTheBinaryIsReplacedAreStillThisBuild) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("snell-replaced-{}", getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path binary = dir / "snell";
  fs::copy_file(SNELL_BINARY, binary);
  std::vector<std::string> args = {binary.string(),
                                   "run",
                                   "--backend",
                                   "gl,vk",
                                   "-j",
                                   "1",
                                   "--filter",
                                   "orange-book/14.1-fresnel/*",
                                   "--oracle-cache",
                                   "off",
                                   "--json",
                                   (dir / "r.jsonl").string(),
                                   "--out",
                                   (dir / "out").string()};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, (dir / "stderr").c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  ASSERT_EQ(posix_spawn(&pid, binary.c_str(), &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  // Once the first gl result is in, before the vk worker starts (one slot,
  // the gl cases first).
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (snell::testing::readText(dir / "r.jsonl.partial").empty() &&
         std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  std::ofstream(dir / "snell.new") << "#!/bin/sh\nexit 3\n";
  fs::permissions(dir / "snell.new", fs::perms::owner_all);
  fs::rename(dir / "snell.new", binary);
  EXPECT_EQ(exitCode(pid), 0) << snell::testing::readText(dir / "stderr");
  const auto results = resultsByKey(dir / "r.jsonl");
  EXPECT_EQ(results.size(), 2 * kFresnelCases);
  for (const auto& [key, result] : results)
    EXPECT_EQ(result["status"], "Pass") << key << ": " << result["message"];
  fs::remove_all(dir);
}

// A -j past the open-file limit failed part way through the run with "Too
// many open files": it is refused before anything is written, naming the
// -j that fits, and that -j runs. A soft limit below the hard one is raised
// as far as the workers need.
TEST(Isolation, JobsPastTheOpenFileLimitAreRefusedNamingTheJobsThatFit) {
  const fs::path out = fs::temp_directory_path() / fmt::format("snell-jobs-{}", ::getpid());
  fs::remove_all(out);
  const std::string run =
      fmt::format("--out {} --filter 'blog/chromatic/sphere' --backend vk", out.string());
  const auto refused = runSnell("run -j 30 " + run, "ulimit -n 40;");
  EXPECT_EQ(refused.code, 2) << refused.out;
  EXPECT_NE(refused.out.find("-j 30: the open-file limit is 40 (ulimit -n"), std::string::npos)
      << refused.out;
  EXPECT_FALSE(fs::exists(out)) << "written before the refusal";
  const std::string marker = "use -j ";
  const std::size_t at = refused.out.find(marker);
  ASSERT_NE(at, std::string::npos) << refused.out;
  const int fits = std::atoi(refused.out.c_str() + at + marker.size());
  ASSERT_GE(fits, 1) << refused.out;
  const auto fitting = runSnell(fmt::format("run -j {} {}", fits, run), "ulimit -n 40;");
  EXPECT_EQ(fitting.code, 0) << fitting.out;
  const auto raised = runSnell("run -j 30 " + run, "ulimit -Sn 40; ulimit -Hn 200;");
  EXPECT_EQ(raised.code, 0) << raised.out;
  const auto none = runSnell("run -j 1 " + run, "ulimit -n 12;");
  EXPECT_EQ(none.code, 2) << none.out;
  EXPECT_NE(none.out.find("not even one worker fits: the open-file limit is 12"), std::string::npos)
      << none.out;
  fs::remove_all(out);
}

}  // namespace
