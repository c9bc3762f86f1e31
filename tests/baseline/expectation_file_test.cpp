// Expectation files as Mesa keeps them, with metadata comments; every
// malformed or expired entry is exit 2 with FILE:LINE.
#include "baseline/expectation_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "core/errors.h"
#include "test_files.h"

namespace snell {
namespace {

constexpr const char* kToday = "2026-11-25";

std::string usageErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(ExpectationFile, ReadsFailsFlakesSkipsWithMetadata) {
  testing::TempDir dir;
  dir.write("gl-fails.txt",
            "# softpipe's refract rounds twice\n"
            "# reason: 13 pixels off at the rim\n"
            "# link: https://example.org/1\n"
            "# added: 2026-11-20\n"
            "# expires: 2027-01-01\n"
            "orange-book/14.1-fresnel/sphere,Fail\n"
            "\n"
            "cs381/refraction/sphere,Timeout\n");
  dir.write("gl-flakes.txt", "^shadertoy/.*/bubble\n");
  dir.write("gl-skips.txt", "# too slow\nblog/.*\n");
  const ExpectationSet set = loadExpectations(dir.path(), {"gl", "vk"}, kToday);
  const Expectations& gl = set.of("gl");
  ASSERT_EQ(gl.fails.size(), 2u);
  EXPECT_EQ(gl.fails[0].caseId, "orange-book/14.1-fresnel/sphere");
  EXPECT_EQ(gl.fails[0].status, Status::Fail);
  EXPECT_EQ(gl.fails[0].metadata.reason, "13 pixels off at the rim");
  EXPECT_EQ(gl.fails[0].metadata.link, "https://example.org/1");
  EXPECT_EQ(gl.fails[0].metadata.expires, "2027-01-01");
  EXPECT_EQ(gl.fails[0].place.line, 6);
  // The blank line ends the metadata: the second entry has none.
  EXPECT_EQ(gl.fails[1].metadata.reason, "");
  EXPECT_EQ(gl.fails[1].status, Status::Timeout);
  EXPECT_NE(gl.flake("shadertoy/lens/bubble"), nullptr);
  EXPECT_EQ(gl.flake("shadertoy/lens/sphere"), nullptr);
  EXPECT_NE(gl.skip("blog/fresnel/sphere"), nullptr);
  // No vk files: nothing expected of vk.
  EXPECT_TRUE(set.of("vk").fails.empty());
  EXPECT_EQ(set.of("vk").skip("blog/fresnel/sphere"), nullptr);
}

TEST(ExpectationFile, PrefixFileAppliesToEveryBackend) {
  testing::TempDir dir;
  const auto fails = dir.write("softpipe-fails.txt", "a/b/c,Fail\n");
  dir.write("softpipe-skips.txt", "^x/\n");
  const ExpectationSet set = loadExpectations(fails, {"gl"}, kToday);
  EXPECT_NE(set.of("gl").knownFailure("a/b/c"), nullptr);
  EXPECT_NE(set.of("gl").skip("x/y/z"), nullptr);
}

TEST(ExpectationFile, ExpiredEntryIsAnErrorAtItsLine) {
  testing::TempDir dir;
  dir.write("gl-fails.txt", "# reason: waiting for a fix\n# expires: 2026-11-24\na/b/c,Fail\n");
  const std::string error = usageErrorOf([&] { loadExpectations(dir.path(), {"gl"}, kToday); });
  EXPECT_NE(error.find("gl-fails.txt:3:"), std::string::npos) << error;
  EXPECT_NE(error.find("expired on 2026-11-24"), std::string::npos) << error;
  // Expiring today is not expired yet.
  dir.write("gl-fails.txt", "# expires: 2026-11-25\na/b/c,Fail\n");
  EXPECT_EQ(usageErrorOf([&] { loadExpectations(dir.path(), {"gl"}, kToday); }), "");
}

// A folder whose files are named for no backend, or that holds none, was
// read as no expectations: every known failure then failed the gate, or a
// wrong path passed it. A byte order mark hid the first entry.
TEST(ExpectationFile, AFolderMustHoldFilesNamedForBackends) {
  testing::TempDir dir;
  const std::string none = usageErrorOf([&] { loadExpectations(dir.path(), {"gl"}, kToday); });
  EXPECT_NE(none.find("holds no expectation files"), std::string::npos) << none;
  dir.write("vulkan-fails.txt", "a/b/c,Fail\n");
  const std::string misnamed = usageErrorOf([&] { loadExpectations(dir.path(), {"gl"}, kToday); });
  EXPECT_NE(misnamed.find("vulkan-fails.txt: `vulkan` is no backend"), std::string::npos)
      << misnamed;
  EXPECT_NE(misnamed.find("gl, "), std::string::npos) << misnamed;
  std::filesystem::remove(dir.path() / "vulkan-fails.txt");
  dir.write("vk-fails.txt",
            "\xEF\xBB\xBF"
            "a/b/c,Fail\n");
  const ExpectationSet set = loadExpectations(dir.path(), {"vk"}, kToday);
  EXPECT_NE(set.of("vk").knownFailure("a/b/c"), nullptr) << "the byte order mark kept";
}

TEST(ExpectationFile, MalformedEntriesNameFileAndLine) {
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"gl-fails.txt", "a/b/c\n"},                          // no status
      {"gl-fails.txt", "a/b/c,Passed\n"},                   // no such status
      {"gl-fails.txt", "a/b/c,Pass\n"},                     // not a failure
      {"gl-fails.txt", "a/b/c,Fail\na/b/c,Crash\n"},        // listed twice
      {"gl-fails.txt", "# expires: 2027-02-30\na,Fail\n"},  // no such date
      {"gl-fails.txt", "# added: yesterday\na,Fail\n"},
      {"gl-flakes.txt", "a/(b\n"},                  // not a regex
      {"gl-skips.txt", "x\n# reason: dangling\n"},  // metadata of no entry
  };
  for (const auto& [name, text] : bad) {
    testing::TempDir dir;
    dir.write(name, text);
    const std::string error = usageErrorOf([&] { loadExpectations(dir.path(), {"gl"}, kToday); });
    EXPECT_NE(error.find(name + ":"), std::string::npos) << text << " -> " << error;
  }
}

// An expiry date above a blank line belonged to no entry and was dropped,
// so the entry below never expired; a note as a third field was read as
// the status.
TEST(ExpectationFile, MetadataAboveABlankLineAndAThirdFieldAreRefused) {
  testing::TempDir dir;
  dir.write("gl-fails.txt", "# reason: flaky on CI\n# expires: 2020-01-01\n\na/b/c,Fail\n");
  const std::string orphan = usageErrorOf([&] { loadExpectations(dir.path(), {"gl"}, kToday); });
  EXPECT_NE(orphan.find("gl-fails.txt:3: a blank line below an `# expires:` comment"),
            std::string::npos)
      << orphan;
  dir.write("gl-fails.txt", "a/b/c,Fail,see issue 12\n");
  const std::string third = usageErrorOf([&] { loadExpectations(dir.path(), {"gl"}, kToday); });
  EXPECT_NE(third.find("gl-fails.txt:1: `a/b/c,Fail,see issue 12` has more than two fields"),
            std::string::npos)
      << third;
  // Free text, or a header's reason or link, above a blank line is a
  // comment like any other, and belongs to no entry.
  dir.write("gl-fails.txt",
            "# known failures of gl\n# link: https://example.org/1\n\na/b/c,Fail\n");
  const ExpectationSet set = loadExpectations(dir.path(), {"gl"}, kToday);
  EXPECT_EQ(set.of("gl").fails.at(0).metadata.link, "");
}

// A folder's files for a backend the run leaves out are read too: their
// malformed or expired entries are found by every job that reads the
// folder, though their entries apply only where that backend runs.
TEST(ExpectationFile, EveryBackendsFilesInAFolderAreChecked) {
  testing::TempDir dir;
  dir.write("gl-fails.txt", "a/b/c,Fail\n");
  dir.write("vk-fails.txt", "# expires: 2020-01-01\na/b/c,Fail\n");
  const std::string expired = usageErrorOf([&] { loadExpectations(dir.path(), {"gl"}, kToday); });
  EXPECT_NE(expired.find("vk-fails.txt:2: this entry expired"), std::string::npos) << expired;
  dir.write("vk-fails.txt", "a/b/c,Fail\n");
  dir.write("vk-flakes.txt", "((\n");
  const std::string bad = usageErrorOf([&] { loadExpectations(dir.path(), {"gl"}, kToday); });
  EXPECT_NE(bad.find("vk-flakes.txt:1:"), std::string::npos) << bad;
  std::filesystem::remove(dir.path() / "vk-flakes.txt");
  const ExpectationSet set = loadExpectations(dir.path(), {"gl"}, kToday);
  EXPECT_NE(set.of("gl").knownFailure("a/b/c"), nullptr);
  EXPECT_EQ(set.byBackend.count("vk"), 0u);
}

// An entry for no case of the catalog (a typo, or the backend in front of
// the id as results.csv writes it) is noted with its line, once.
TEST(ExpectationFile, EntriesForNoCaseAreNoted) {
  testing::TempDir dir;
  dir.write("gl-fails.txt",
            "a/b/c,Fail\n"
            "a/b/d,Fail\n"
            "gl/a/b/e,Fail\n");
  dir.write("gl-skips.txt", "^a/\nnowhere\n");
  dir.write("vk-fails.txt", "a/b/d,Fail\n");
  const ExpectationSet set = loadExpectations(dir.path(), {"gl", "vk"}, kToday);
  const std::vector<std::string> notes = entriesMatchingNoCase(set, {"a/b/c", "a/b/e"});
  ASSERT_EQ(notes.size(), 4u) << ::testing::PrintToString(notes);
  const auto has = [&](const std::string& text) {
    return std::any_of(notes.begin(), notes.end(),
                       [&](const std::string& n) { return n.find(text) != std::string::npos; });
  };
  EXPECT_TRUE(has("gl-fails.txt:2: `a/b/d` is no case of the catalog"));
  EXPECT_TRUE(
      has("gl-fails.txt:3: `gl/a/b/e` is no case id; drop the backend in front of it "
          "(`a/b/e`)"));
  EXPECT_TRUE(has("gl-skips.txt:2: `nowhere` matches no case"));
  EXPECT_TRUE(has("vk-fails.txt:1: `a/b/d` is no case of the catalog"));
  // The same file serving every backend (a prefix) is noted once per line.
  const auto prefix = dir.write("one-fails.txt", "a/b/zz,Fail\n");
  EXPECT_EQ(entriesMatchingNoCase(loadExpectations(prefix, {"gl", "vk"}, kToday), {"a/b/c"}).size(),
            1u);
}

TEST(ExpectationFile, SourceThatIsNeitherFolderNorPrefixFileIsAnError) {
  testing::TempDir dir;
  const auto other = dir.write("fails.csv", "a,Fail\n");
  EXPECT_NE(usageErrorOf([&] { loadExpectations(other, {"gl"}, kToday); }), "");
  EXPECT_NE(usageErrorOf([&] { loadExpectations(dir.path() / "none-fails.txt", {"gl"}, kToday); }),
            "");
}

TEST(ExpectationFile, TodayIsADate) {
  const std::string today = todayUtc();
  ASSERT_EQ(today.size(), 10u);
  EXPECT_EQ(today[4], '-');
  EXPECT_GE(today, "2026-01-01");
}

}  // namespace
}  // namespace snell
