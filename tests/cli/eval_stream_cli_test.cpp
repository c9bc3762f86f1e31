// `snell eval` on input of several chunks (SNELL_EVAL_CHUNK makes them
// small), as a user runs it: a bad line in a later chunk is named as
// file:line on stderr with exit 2, and every other line is answered.
#include <fcntl.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <spawn.h>
#include <sys/ioctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "json_lines.h"
#include "snell_process.h"

namespace {

namespace fs = std::filesystem;
using snell::testing::jsonLines;
using snell::testing::Outcome;
using snell::testing::readText;
using snell::testing::runSnell;

fs::path writeInput(const std::string& name, const std::string& text) {
  const fs::path path = fs::temp_directory_path() / fmt::format("snell-{}-{}", name, ::getpid());
  std::ofstream(path) << text;
  return path;
}

TEST(EvalStreamCli, BadLineInALaterChunkIsExit2NamingFileAndLine) {
  std::string text;
  for (int k = 1; k <= 14; ++k)
    text += k == 11 ? "{\"fn\":\"refract\",\"I\":[0,-1,0],\"N\":[0,1,0]}\n"
                    : "{\"fn\":\"reflect\",\"I\":[0.6,-0.8],\"N\":[0,1]}\n";
  const fs::path input = writeInput("eval-chunks", text);
  for (const char* threads : {"1", "2"}) {
    const Outcome o = runSnell(fmt::format("eval {}", input.string()),
                               fmt::format("SNELL_EVAL_CHUNK=4 SNELL_EVAL_THREADS={}", threads));
    EXPECT_EQ(o.code, 2) << o.out;
    EXPECT_NE(o.out.find(fmt::format("{}:11: refract needs a number \"eta\"", input.string())),
              std::string::npos)
        << o.out;
    const auto lines = jsonLines(o.out);
    ASSERT_EQ(lines.size(), 14u) << o.out;
    EXPECT_EQ(lines[10]["error"].get<std::string>().rfind("line 11: ", 0), 0u) << o.out;
    EXPECT_EQ(lines[13]["line"].get<int>(), 14) << o.out;
  }
  fs::remove(input);
}

// Each input line is one JSON text: its error names the input's line and
// the column within it, not JSON's own "line 1".
TEST(EvalStreamCli, AJsonErrorNamesItsColumnWithinTheLine) {
  const fs::path input =
      writeInput("eval-column", "{\"fn\":\"reflect\",\"I\":[1],\"N\":[1]}\n{\"fn\": x}\n");
  const Outcome o = runSnell(fmt::format("eval {}", input.string()));
  EXPECT_EQ(o.code, 2) << o.out;
  EXPECT_NE(
      o.out.find(fmt::format("{}:2: not valid JSON (parse error at column 8:", input.string())),
      std::string::npos)
      << o.out;
  EXPECT_EQ(o.out.find("line 1"), std::string::npos) << o.out;
  fs::remove(input);
}

// JavaScript's NaN and Infinity are not JSON: the error says which strings
// the line takes instead. A NUL byte ended the line for the JSON reader,
// and what followed it was dropped without a word: the line is refused.
TEST(EvalStreamCli, NanTokensAndNulBytesAreNamedWithWhatToWrite) {
  std::string text =
      "{\"fn\":\"reflect\",\"I\":[NaN,1],\"N\":[0,1]}\n"
      "{\"fn\":\"refract\",\"I\":[0,-1],\"N\":[0,1],\"eta\":-Infinity}\n"
      "{\"fn\":\"reflect\",\"I\":[0.6,-0.8],\"N\":[0,1]}";
  text += '\0';
  text += "{\"fn\":\"refract\"}\n";
  const fs::path input = writeInput("eval-nan", text);
  const Outcome o = runSnell(fmt::format("eval {}", input.string()));
  EXPECT_EQ(o.code, 2) << o.out;
  const auto answers = snell::testing::jsonLines(o.out);
  ASSERT_EQ(answers.size(), 3u) << o.out;
  for (int k = 0; k < 2; ++k) {
    const std::string error = answers[k].value("error", "");
    EXPECT_NE(error.find("not valid JSON (parse error at column"), std::string::npos) << error;
    EXPECT_NE(error.find("JSON has no NaN or infinity: write the strings \"nan\", \"inf\" or "
                         "\"-inf\""),
              std::string::npos)
        << error;
  }
  EXPECT_EQ(answers[2].value("error", ""),
            "line 3: a NUL byte at column 42: a line is one JSON "
            "object in text; remove the byte")
      << o.out;
  fs::remove(input);
}

TEST(EvalStreamCli, BadChunkSizeOrThreadCountIsExit2NamingTheVariable) {
  const fs::path input = writeInput("eval-chunk0", "{\"fn\":\"reflect\",\"I\":[1],\"N\":[1]}\n");
  // Past the limits a mistyped value would hold the machine's memory or
  // its every thread.
  for (const std::string setting :
       {"SNELL_EVAL_CHUNK=0", "SNELL_EVAL_CHUNK=many", "SNELL_EVAL_CHUNK=-3",
        "SNELL_EVAL_CHUNK=99999999999", "SNELL_EVAL_THREADS=0", "SNELL_EVAL_THREADS=100000"}) {
    const Outcome o = runSnell(fmt::format("eval {}", input.string()), setting);
    EXPECT_EQ(o.code, 2) << setting << ": " << o.out;
    EXPECT_NE(o.out.find(setting + ": give a whole number from 1 to"), std::string::npos) << o.out;
  }
  fs::remove(input);
}

// Ctrl-C while eval waits for more input: the lines read so far are
// answered whole, a line the signal cut short is not, and stderr says where
// the rest begins, with 128 + SIGINT. The input comes through a pipe the
// test holds open: the signal is sent once eval has read it all (1000
// lines, two chunks of 500, and the start of a line) and waits for more.
TEST(EvalStreamCli, InterruptedEvalAnswersWholeLinesAndSaysWhereTheRestBegins) {
  const fs::path out = fs::temp_directory_path() / fmt::format("snell-eval-int-{}.out", ::getpid());
  const fs::path err = fs::temp_directory_path() / fmt::format("snell-eval-int-{}.err", ::getpid());
  int input[2];
  ASSERT_EQ(::pipe(input), 0);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, input[0], 0);
  posix_spawn_file_actions_addclose(&actions, input[1]);
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::string binary = SNELL_BINARY, eval = "eval", dash = "-";
  std::vector<char*> argv = {binary.data(), eval.data(), dash.data(), nullptr};
  std::vector<std::string> environment = {"SNELL_EVAL_CHUNK=500"};
  for (char** e = environ; *e; ++e) environment.emplace_back(*e);
  std::vector<char*> envp;
  for (std::string& e : environment) envp.push_back(e.data());
  envp.push_back(nullptr);
  pid_t pid = -1;
  ASSERT_EQ(posix_spawn(&pid, binary.c_str(), &actions, nullptr, argv.data(), envp.data()), 0);
  posix_spawn_file_actions_destroy(&actions);
  ::close(input[0]);
  std::string lines;
  for (int k = 0; k < 1000; ++k)
    lines += R"({"fn":"reflect","I":[0.6,-0.8],"N":[0,1]})"
             "\n";
  lines += R"({"fn":"refl)";
  ASSERT_EQ(::write(input[1], lines.data(), lines.size()), static_cast<ssize_t>(lines.size()));
  // Sent once eval has read everything in the pipe and waits for more.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  int unread = 1;
  while ((::ioctl(input[1], FIONREAD, &unread) != 0 || unread > 0) &&
         std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  ::kill(pid, SIGINT);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ::close(input[1]);
  ASSERT_TRUE(WIFEXITED(status)) << "ended by a signal, not by its own exit";
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGINT);
  const auto answers = jsonLines(readText(out));
  ASSERT_EQ(answers.size(), 1000u);
  EXPECT_EQ(answers.back().at("line"), 1000);
  const std::string message = readText(err);
  EXPECT_NE(message.find("interrupted by SIGINT: the answers written are those of input lines 1 "
                         "to 1000, each whole; the rest begins at input line 1001"),
            std::string::npos)
      << message;
  fs::remove(out);
  fs::remove(err);
}

// `snell eval` as a co-process: a tool writes one line, waits for its
// answer, then writes the next. Each answer comes while the input is still
// open (eval once held them until 1 MiB of input or its end, and both sides
// waited on each other).
TEST(EvalStreamCli, ACoProcessGetsEachAnswerBeforeItSendsTheNextLine) {
  int input[2], output[2];
  ASSERT_EQ(::pipe(input), 0);
  ASSERT_EQ(::pipe(output), 0);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, input[0], 0);
  posix_spawn_file_actions_adddup2(&actions, output[1], 1);
  for (int fd : {input[0], input[1], output[0], output[1]})
    posix_spawn_file_actions_addclose(&actions, fd);
  std::string binary = SNELL_BINARY, eval = "eval", dash = "-";
  std::vector<char*> argv = {binary.data(), eval.data(), dash.data(), nullptr};
  pid_t pid = -1;
  ASSERT_EQ(posix_spawn(&pid, binary.c_str(), &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  ::close(input[0]);
  ::close(output[1]);
  std::string answers;
  const auto answerOf = [&](const std::string& line) -> std::string {
    if (::write(input[1], line.data(), line.size()) != static_cast<ssize_t>(line.size())) return "";
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    for (;;) {
      if (const auto newline = answers.find('\n'); newline != std::string::npos) {
        std::string answer = answers.substr(0, newline);
        answers.erase(0, newline + 1);
        return answer;
      }
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
          deadline - std::chrono::steady_clock::now());
      pollfd ready{output[0], POLLIN, 0};
      if (left.count() <= 0 || ::poll(&ready, 1, static_cast<int>(left.count())) <= 0) return "";
      char buffer[4096];
      const ssize_t got = ::read(output[0], buffer, sizeof buffer);
      if (got <= 0) return "";
      answers.append(buffer, static_cast<std::size_t>(got));
    }
  };
  const std::string first = answerOf(R"({"fn":"reflect","I":[0.6,-0.8],"N":[0,1]})"
                                     "\n");
  ASSERT_FALSE(first.empty()) << "no answer to the first line while the input stays open";
  EXPECT_EQ(jsonLines(first + "\n").at(0).at("line"), 1);
  // The second line is sent in two writes: the part sent first is kept
  // until its end comes.
  ASSERT_EQ(::write(input[1], R"({"fn":"refract",)", 16), 16);
  const std::string second = answerOf(R"("I":[0.6,-0.8],"N":[0,1],"eta":0.66})"
                                      "\n");
  ASSERT_FALSE(second.empty()) << "no answer to the second line while the input stays open";
  EXPECT_EQ(jsonLines(second + "\n").at(0).at("line"), 2);
  ::close(input[1]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ::close(output[0]);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

}  // namespace
