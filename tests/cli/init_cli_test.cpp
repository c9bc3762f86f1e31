// `snell init DIR` as a user runs it: a manifest written, never one
// overwritten without --force, and one clear message with exit code 2 for
// bad input.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "snell_process.h"

namespace snell {
namespace {

namespace fs = std::filesystem;
using testing::readText;
using testing::runSnell;

class InitCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           fmt::format("snell-init-{}-{}", getpid(),
                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  void copyListing() {
    // The catalog's CS 381 listing: its own stage files, no manifest.
    const fs::path listing = SNELL_SOURCE_ROOT "/shaders/cs381/refraction";
    fs::copy_file(listing / "eyespace.vert", dir_ / "eyespace.vert");
    fs::copy_file(listing / "refraction.frag", dir_ / "refraction.frag");
  }

  fs::path dir_;
};

TEST_F(InitCli, WritesTheManifestThenRefusesToOverwriteIt) {
  copyListing();
  const auto first = runSnell("init " + dir_.string());
  EXPECT_EQ(first.code, 0) << first.out;
  const std::string written = readText(dir_ / "manifest.toml");
  EXPECT_NE(written.find("stages = { vertex = \"eyespace.vert\", fragment = \"refraction.frag\" }"),
            std::string::npos)
      << written;

  std::ofstream(dir_ / "manifest.toml") << "# mine\n";
  const auto again = runSnell("init " + dir_.string());
  EXPECT_EQ(again.code, 2);
  EXPECT_NE(again.out.find("manifest.toml exists; snell init never overwrites a manifest: pass "
                           "--force to replace it"),
            std::string::npos)
      << again.out;
  EXPECT_EQ(readText(dir_ / "manifest.toml"), "# mine\n");

  const auto forced = runSnell("init --force " + dir_.string());
  EXPECT_EQ(forced.code, 0) << forced.out;
  EXPECT_EQ(readText(dir_ / "manifest.toml"), written);
}

TEST_F(InitCli, BadInputIsOneMessageAndExit2) {
  const struct {
    std::string args, message;
  } cases[] = {
      {"init " + (dir_ / "missing").string(), "no such folder"},
      {"init " + dir_.string(), "holds no GLSL vertex stage (*.vert)"},
      {"init --vertex nope.vert " + dir_.string(), "nope.vert: no such vertex stage file"},
      {"init", "dir is required"},
      {"init --id ../../escaped " + dir_.string(), "id `../../escaped` has a `..` name"},
      {"init --id '' " + dir_.string(), "the id is empty"},
  };
  for (const auto& c : cases) {
    const auto outcome = runSnell(c.args);
    EXPECT_EQ(outcome.code, 2) << c.args << "\n" << outcome.out;
    EXPECT_NE(outcome.out.find(c.message), std::string::npos) << c.args << "\n" << outcome.out;
  }
  EXPECT_FALSE(fs::exists(dir_ / "manifest.toml"));
}

// A stage file named by an absolute path was written into the manifest as
// given (a path that holds on this machine only), and the vertex file named
// as the fragment stage too was drafted, failing only at `run`. The
// manifest names each stage relative to DIR (a sibling folder's through
// "..", as the catalog does); one file for both stages is refused.
TEST_F(InitCli, StageFilesAreNamedRelativeToTheFolderAndOnceEach) {
  copyListing();
  const fs::path listing = dir_ / "listing";
  fs::create_directories(listing);
  fs::create_directories(dir_ / "elsewhere");
  fs::rename(dir_ / "eyespace.vert", dir_ / "elsewhere" / "eyespace.vert");
  fs::rename(dir_ / "refraction.frag", listing / "refraction.frag");
  const auto both =
      runSnell("init --vertex ../elsewhere/eyespace.vert --fragment ../elsewhere/eyespace.vert " +
               listing.string());
  EXPECT_EQ(both.code, 2) << both.out;
  EXPECT_NE(
      both.out.find("../elsewhere/eyespace.vert: named as both the vertex and the fragment stage"),
      std::string::npos)
      << both.out;
  EXPECT_FALSE(fs::exists(listing / "manifest.toml"));
  const auto absolute = runSnell(
      "init --vertex " + (dir_ / "elsewhere" / "eyespace.vert").string() + " " + listing.string());
  EXPECT_EQ(absolute.code, 0) << absolute.out;
  EXPECT_NE(readText(listing / "manifest.toml").find("vertex = \"../elsewhere/eyespace.vert\""),
            std::string::npos)
      << readText(listing / "manifest.toml");
}

// A stage whose every output is refused says why (here glslang's syntax
// error), not that the stage declares no outputs.
TEST_F(InitCli, OutputsThatCannotBeGatedSayWhy) {
  std::ofstream(dir_ / "a.vert") << "#version 330 core\nin vec3 aPos;\nout vec3 R;\n"
                                    "void main() { R = aPos gl_Position = vec4(aPos, 1.0); }\n";
  const auto outcome = runSnell("init " + dir_.string());
  EXPECT_EQ(outcome.code, 2) << outcome.out;
  EXPECT_NE(outcome.out.find("a.vert: nothing the derived oracle can gate: R (a.vert: glslang "
                             "cannot compile the shader"),
            std::string::npos)
      << outcome.out;
  EXPECT_NE(outcome.out.find("a.vert:4: '' :  syntax error"), std::string::npos) << outcome.out;
  EXPECT_FALSE(fs::exists(dir_ / "manifest.toml"));
}

// A Latin-1 comment on a line the draft quotes (here in the note on an
// output it cannot gate) made a manifest snell could not read ("not valid
// TOML: invalid utf-8"): the byte is spelled out as \xNN.
TEST_F(InitCli, ACommentInAnotherEncodingStillDraftsAManifestSnellReads) {
  std::ofstream(dir_ / "a.vert") << "#version 330 core\nin vec3 aPos;\nin vec3 aNormal;\n"
                                    "uniform mat4 model;\nout vec3 R;\nout vec3 Normal;\n"
                                    "void main() {\n"
                                    "  Normal = mat3(inverse(model)) * aNormal; // normale \xe9\n"
                                    "  R = refract(normalize(aPos), normalize(aNormal), 0.66);\n"
                                    "  gl_Position = vec4(aPos, 1.0);\n}\n";
  const auto outcome = runSnell("init " + dir_.string());
  EXPECT_EQ(outcome.code, 0) << outcome.out;
  std::ifstream in(dir_ / "manifest.toml");
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(text.find("// normale \\xe9"), std::string::npos) << text;
  const auto checked = runSnell("list --check --shaders " + dir_.string());
  EXPECT_EQ(checked.out.find("not valid TOML"), std::string::npos) << checked.out;
  EXPECT_EQ(checked.out.find("invalid utf-8"), std::string::npos) << checked.out;
}

// The next step the command names can be pasted as it is: the folder
// quoted when it holds a space, and the goldens blessed first, into a
// folder of the user's own, when the draft has image cases (a new case with
// no golden fails where the driver has goldens for other listings).
TEST_F(InitCli, TheNextStepIsACommandThatWorksAsPrinted) {
  const fs::path folder = dir_ / "my listing";
  fs::create_directories(folder);
  const fs::path listing = SNELL_SOURCE_ROOT "/shaders/cs381/refraction";
  fs::copy_file(listing / "eyespace.vert", folder / "eyespace.vert");
  fs::copy_file(listing / "refraction.frag", folder / "refraction.frag");
  const auto outcome = runSnell("init '" + folder.string() + "'");
  ASSERT_EQ(outcome.code, 0) << outcome.out;
  const std::string dir = "'" + folder.string() + "'";
  const std::string golden = "'" + (folder / "golden").string() + "'";
  EXPECT_NE(outcome.out.find("`mkdir -p " + golden + " && snell bless --shaders " + dir +
                             " --golden " + golden + "`"),
            std::string::npos)
      << outcome.out;
  EXPECT_NE(outcome.out.find("`snell run --shaders " + dir + " --golden " + golden + "`"),
            std::string::npos)
      << outcome.out;
  // The folder's name, space and all, is no id: the drafted one has '-'.
  EXPECT_NE(readText(folder / "manifest.toml").find("/my-listing\""), std::string::npos)
      << readText(folder / "manifest.toml");
}

TEST_F(InitCli, AStageWithoutMainIsRefused) {
  std::ofstream(dir_ / "notes.vert") << "not a shader\n";
  const auto outcome = runSnell("init " + dir_.string());
  EXPECT_EQ(outcome.code, 2) << outcome.out;
  EXPECT_NE(outcome.out.find("notes.vert: no `void main()`"), std::string::npos) << outcome.out;
  EXPECT_EQ(std::count(outcome.out.begin(), outcome.out.end(), '\n'), 1) << outcome.out;
  EXPECT_FALSE(fs::exists(dir_ / "manifest.toml"));
}

}  // namespace
}  // namespace snell

namespace snell {
namespace {

// A published pair copied into ROOT/shaders/mine/NAME, with ROOT/golden
// empty, as a user starts a listing of their own.
class InitThenRun : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() /
            fmt::format("snell-init-run-{}-{}", getpid(),
                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    fs::create_directories(root_ / "golden");
  }
  void TearDown() override { fs::remove_all(root_); }

  fs::path copyListing(const std::string& name, const fs::path& published,
                       std::initializer_list<const char*> files) {
    const fs::path listing = root_ / "shaders" / "mine" / name;
    fs::create_directories(listing);
    for (const char* file : files) fs::copy_file(published / file, listing / file);
    return listing;
  }

  // The draft's citation placeholders replaced by `citation`, as its author would.
  static void fillInCitation(const fs::path& listing, const std::string& citation) {
    std::string manifest = readText(listing / "manifest.toml");
    const std::string placeholder =
        R"(file = "FILL IN: the document or URL", where = "FILL IN: the listing or section")";
    ASSERT_NE(manifest.find(placeholder), std::string::npos) << manifest;
    manifest.replace(manifest.find(placeholder), placeholder.size(), citation);
    std::ofstream(listing / "manifest.toml", std::ios::trunc) << manifest;
  }

  std::string folders(const std::string& backends) const {
    return fmt::format(" --shaders {} --golden {} --out {} --backend {}",
                       (root_ / "shaders").string(), (root_ / "golden").string(),
                       (root_ / "out").string(), backends);
  }

  fs::path root_;
};

// From nothing to a passing gated case on both backends, as shaders/README.md
// walks through it: the LearnOpenGL refraction pair, `snell init`, the
// citation filled in, `snell bless` for the goldens, `snell run`. The
// vertex stage's Normal (through inverse()) is left out, saying why.
TEST_F(InitThenRun, ALearnOpenGLPairRunsAsDraftedOnceTheCitationIsFilledIn) {
  const fs::path listing =
      copyListing("refraction", SNELL_SOURCE_ROOT "/shaders/learnopengl/refraction",
                  {"cubemaps.vert", "refraction.frag"});
  ASSERT_EQ(runSnell("init " + listing.string()).code, 0);
  const std::string manifest = readText(listing / "manifest.toml");
  EXPECT_NE(manifest.find("# Not captured: Normal (cubemaps.vert:14: inverse() has no precision"),
            std::string::npos)
      << manifest;
  const auto unfilled = runSnell("run --shaders " + (root_ / "shaders").string());
  EXPECT_EQ(unfilled.code, 2) << unfilled.out;
  fillInCitation(
      listing,
      R"(file = "https://learnopengl.com/Advanced-OpenGL/Cubemaps", where = "Refraction")");
  // Their goldens do not go to the catalog's folder in snell's source
  // tree: without --golden the bless is refused, and writes nothing there.
  const auto intoCatalog = runSnell("bless --backend gl --shaders " + (root_ / "shaders").string() +
                                    " --out " + (root_ / "out").string());
  EXPECT_EQ(intoCatalog.code, 2) << intoCatalog.out;
  EXPECT_NE(
      intoCatalog.out.find("mine/refraction/sphere, mine/refraction/stretched are not among "
                           "snell's catalog's cases: give --golden DIR, a folder of your own"),
      std::string::npos)
      << intoCatalog.out;
  EXPECT_FALSE(fs::exists(SNELL_SOURCE_ROOT "/golden/mine"));
  EXPECT_EQ(runSnell("bless" + folders("gl,vk")).code, 0);
  const auto run = runSnell("run" + folders("gl,vk"));
  EXPECT_EQ(run.code, 0) << run.out;
  EXPECT_NE(run.out.find("6 results: 6 Pass"), std::string::npos) << run.out;
  // A change that drops normalize() from the normal: the derived oracle
  // follows the text, and the sphere's and torus's normals are unit, but the
  // stretched sphere's image is off its golden.
  const fs::path fragment = listing / "refraction.frag";
  std::string text = readText(fragment);
  const auto at = text.find("normalize(Normal)");
  ASSERT_NE(at, std::string::npos) << text;
  text.replace(at, std::string("normalize(Normal)").size(), "Normal");
  std::ofstream(fragment, std::ios::trunc) << text;
  const auto changed = runSnell("run" + folders("gl,vk"));
  EXPECT_EQ(changed.code, 1) << changed.out;
  EXPECT_NE(changed.out.find("6 results: 2 Fail, 4 Pass"), std::string::npos) << changed.out;
  EXPECT_NE(changed.out.find("mine/refraction/stretched on gl: Fail"), std::string::npos)
      << changed.out;
}

// Listing 14.1 of the Orange Book: its fragment stage only looks colours up
// (no direction is computed there), so the draft captures the vertex
// outputs alone and runs once the citation is filled in.
TEST_F(InitThenRun, TheOrangeBookFresnelPairRunsAsDrafted) {
  const fs::path listing =
      copyListing("fresnel", SNELL_SOURCE_ROOT "/shaders/orange-book/14.1-fresnel",
                  {"fresnel.vert", "fresnel.frag"});
  ASSERT_EQ(runSnell("init " + listing.string()).code, 0);
  EXPECT_EQ(readText(listing / "manifest.toml").find("fragment = ["), std::string::npos)
      << readText(listing / "manifest.toml");
  fillInCitation(listing, R"(file = "OpenGL Shading Language, 3rd ed.", where = "Listing 14.1")");
  const auto run = runSnell("run" + folders("gl"));
  EXPECT_EQ(run.code, 0) << run.out;
  EXPECT_NE(run.out.find("3 results: 3 Pass"), std::string::npos) << run.out;
}

}  // namespace
}  // namespace snell
