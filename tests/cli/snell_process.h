#pragma once
// The `snell` binary run as a user runs it, for the CLI tests.
#include <fcntl.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

extern char** environ;

namespace snell::testing {

struct Outcome {
  int code = -1;
  std::string out;  // stdout and stderr together
};

// Runs `ENV snell ARGS` through the shell and waits; `env` is a shell
// prefix such as "GALLIUM_DRIVER=softpipe".
inline Outcome runSnell(const std::string& args, const std::string& env = "") {
  FILE* pipe = popen(fmt::format("{} {} {} 2>&1", env, SNELL_BINARY, args).c_str(), "r");
  Outcome outcome;
  std::array<char, 4096> buffer;
  while (std::size_t n = fread(buffer.data(), 1, buffer.size(), pipe))
    outcome.out.append(buffer.data(), n);
  const int status = pclose(pipe);
  outcome.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return outcome;
}

// Starts `snell ARGS` without waiting, its stdout discarded and its stderr
// written to `stderrPath`.
inline pid_t spawnSnell(const std::vector<std::string>& args,
                        const std::string& stderrPath = "/dev/null") {
  std::vector<std::string> argv = {SNELL_BINARY};
  argv.insert(argv.end(), args.begin(), args.end());
  std::vector<char*> raw;
  for (auto& a : argv) raw.push_back(a.data());
  raw.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, stderrPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  pid_t pid = -1;
  EXPECT_EQ(posix_spawn(&pid, raw[0], &actions, nullptr, raw.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

inline std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace snell::testing
