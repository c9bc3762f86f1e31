// `snell eval` on input of several chunks (SNELL_EVAL_CHUNK makes them
// small), as a user runs it: a bad line in a later chunk is named as
// file:line on stderr with exit 2, and every other line is answered.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "json_lines.h"
#include "snell_process.h"

namespace {

namespace fs = std::filesystem;
using snell::testing::jsonLines;
using snell::testing::Outcome;
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

}  // namespace
