// Every malformed input in tests/malformed gives its exit code and one clear
// message, and leaves an existing result file as it was.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace {

namespace fs = std::filesystem;

const fs::path kCorpus = SNELL_SOURCE_ROOT "/tests/malformed";

std::vector<std::string> corpus() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(kCorpus))
    if (entry.is_directory()) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string readAll(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every file below `dir` with its contents: nothing may change them.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.is_regular_file()) files[entry.path().string()] = readAll(entry.path());
  return files;
}

class Malformed : public ::testing::TestWithParam<std::string> {};

TEST_P(Malformed, ClearMessageAndExitCodeAndNothingLost) {
  const fs::path dir = kCorpus / GetParam();
  std::istringstream expect(readAll(dir / "expect.txt"));
  int expectedCode = 0;
  std::string expectedText;
  expect >> expectedCode;
  expect.ignore();
  std::getline(expect, expectedText);

  const fs::path results =
      fs::temp_directory_path() / fmt::format("snell-malformed-{}.jsonl", getpid());
  std::ofstream(results) << "previous results\n";
  const fs::path errors =
      fs::temp_directory_path() / fmt::format("snell-malformed-{}.err", getpid());
  // A folder with its own golden/ tests damaged goldens; the others use the
  // repository's.
  const fs::path golden =
      fs::exists(dir / "golden") ? dir / "golden" : fs::path(SNELL_SOURCE_ROOT "/golden");
  const fs::path out = fs::temp_directory_path() / fmt::format("snell-malformed-out-{}", getpid());
  const std::string command = fmt::format(
      "{} run --backend gl -j 1 --shaders {} --golden {} --out {} --json {} >/dev/null 2>{}",
      SNELL_BINARY, dir.string(), golden.string(), out.string(), results.string(), errors.string());
  const auto goldenBefore = snapshot(golden);
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), expectedCode);
  const std::string stderrText = readAll(errors);
  if (expectedCode == 2) {
    // One line, naming what is wrong.
    EXPECT_EQ(std::count(stderrText.begin(), stderrText.end(), '\n'), 1) << stderrText;
    EXPECT_EQ(stderrText.rfind("snell: ", 0), 0u) << stderrText;
    EXPECT_NE(stderrText.find(expectedText), std::string::npos)
        << "expected `" << expectedText << "` in: " << stderrText;
    EXPECT_EQ(readAll(results), "previous results\n");  // a failing command changes no file
    EXPECT_FALSE(fs::exists(results.string() + ".partial"));
  } else {
    EXPECT_NE(readAll(results).find(expectedText), std::string::npos) << readAll(results);
  }
  EXPECT_EQ(stderrText.find("terminate called"), std::string::npos) << stderrText;
  EXPECT_EQ(snapshot(golden), goldenBefore) << "a golden changed";
  fs::remove_all(out);
  fs::remove(results);
  fs::remove(errors);
}

INSTANTIATE_TEST_SUITE_P(Corpus, Malformed, ::testing::ValuesIn(corpus()), [](const auto& info) {
  std::string name = info.param;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
});

TEST(MalformedCorpus, HasAtLeastThirtyInputs) { EXPECT_GE(corpus().size(), 30u); }

// The cases are validated while the workers say whether their drivers come
// up: when both go wrong, the case's own error is the one message.
TEST(MalformedCorpus, ACaseErrorComesBeforeADriverThatDoesNotComeUp) {
  const fs::path errors = fs::temp_directory_path() / fmt::format("snell-both-{}.err", getpid());
  const fs::path out = fs::temp_directory_path() / fmt::format("snell-both-out-{}", getpid());
  const std::string command = fmt::format(
      "{} run --backend vk --device no-such-device -j 1 --shaders {} --out {} >/dev/null 2>{}",
      SNELL_BINARY, (kCorpus / "unknown-oracle").string(), out.string(), errors.string());
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  const std::string stderrText = readAll(errors);
  EXPECT_EQ(std::count(stderrText.begin(), stderrText.end(), '\n'), 1) << stderrText;
  EXPECT_NE(stderrText.find("manifest.toml:6:"), std::string::npos) << stderrText;
  EXPECT_EQ(stderrText.find("no-such-device"), std::string::npos) << stderrText;
  // Without the case, the driver's error is the message.
  const std::string alone =
      fmt::format("{} run --backend vk --device no-such-device -j 1 --out {} >/dev/null 2>{}",
                  SNELL_BINARY, out.string(), errors.string());
  const int aloneStatus = std::system(alone.c_str());
  ASSERT_TRUE(WIFEXITED(aloneStatus));
  EXPECT_EQ(WEXITSTATUS(aloneStatus), 2);
  EXPECT_NE(readAll(errors).find("cannot be brought up"), std::string::npos) << readAll(errors);
  fs::remove_all(out);
  fs::remove(errors);
}

}  // namespace
