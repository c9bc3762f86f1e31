#include "core/manifest.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <tuple>

#include "core/case.h"
#include "core/errors.h"

namespace snell {
namespace {

namespace fs = std::filesystem;

class ManifestTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("snell-manifest-" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    std::ofstream(dir_ / "a.vert") << "#version 140\nvoid main() {}\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& text) {
    const fs::path path = dir_ / "manifest.toml";
    std::ofstream(path) << text;
    return path;
  }

  // kValid with its `oracle = ...` line replaced by `line` (empty: no oracle).
  static std::string withOracleLine(const std::string& line) {
    std::string text = kValid;
    const std::size_t at = text.find("oracle =");
    text.replace(at, text.find('\n', at) - at, line);
    return text;
  }

  // Loads and returns the error message, failing the test if none is thrown.
  std::string errorOf(const std::string& text) {
    try {
      loadManifest(write(text));
    } catch (const UsageError& error) {
      return error.what();
    }
    ADD_FAILURE() << "no error for:\n" << text;
    return {};
  }

  static constexpr const char* kValid = R"(id = "x/y"
title = "t"
source = { file = "f.txt", where = "Listing 1" }
stages = { vertex = "a.vert" }
oracle = "orange_book_fresnel"
constants = { Eta = 0.66 }
[inputs]
MCvertex = "scene.position"
[uniforms]
M = "scene.modelview"
S = 2.5
V = [1, 2, 3]
Q = { type = "mat3", value = [1, 0, 0, 0, 1, 0, 0, 0, 1] }
[capture]
vertex = ["Reflect"]
[[case]]
scene = "sphere"
)";

  fs::path dir_;
};

TEST_F(ManifestTest, ReadsEveryField) {
  const Manifest m = loadManifest(write(kValid));
  EXPECT_EQ(m.id, "x/y");
  EXPECT_EQ(m.source.where, "Listing 1");
  EXPECT_EQ(m.constants.at("Eta"), 0.66);
  ASSERT_EQ(m.uniforms.size(), 4u);
  ASSERT_EQ(m.inputs.size(), 1u);
  EXPECT_EQ(std::get<std::string>(m.inputs[0].source), "position");
  const auto find = [&](const std::string& name) {
    for (const Binding& b : m.uniforms)
      if (b.name == name) return b;
    ADD_FAILURE() << name;
    return Binding{};
  };
  EXPECT_EQ(std::get<Value>(find("S").source).type, ValueType::Float);
  EXPECT_EQ(std::get<Value>(find("V").source).type, ValueType::Vec3);
  EXPECT_EQ(std::get<Value>(find("Q").source).type, ValueType::Mat3);
  ASSERT_EQ(m.cases.size(), 1u);
  EXPECT_EQ(m.cases[0].checks, std::vector<std::string>{"vectors"});
  EXPECT_EQ(loadProgram(m).vertex, "#version 140\nvoid main() {}\n");
}

TEST_F(ManifestTest, MissingFieldNamesFileAndField) {
  std::string text = kValid;
  text.erase(text.find("title ="),
             text.find('\n', text.find("title =")) + 1 - text.find("title ="));
  const std::string message = errorOf(text);
  EXPECT_NE(message.find("manifest.toml:1:"), std::string::npos) << message;
  EXPECT_NE(message.find("`title`"), std::string::npos) << message;
}

TEST_F(ManifestTest, NoOracleMeansTheDerivedOracle) {
  const Manifest m = loadManifest(write(withOracleLine("")));
  EXPECT_TRUE(m.derivedOracle);
  EXPECT_EQ(m.oracle, "");
  const Manifest named = loadManifest(write(withOracleLine("oracle = \"derived\"")));
  EXPECT_TRUE(named.derivedOracle);
  EXPECT_EQ(named.oracle, "");
}

TEST_F(ManifestTest, AManifestMayNameBothOracles) {
  const Manifest both =
      loadManifest(write(withOracleLine("oracle = [\"orange_book_fresnel\", \"derived\"]")));
  EXPECT_TRUE(both.derivedOracle);
  EXPECT_EQ(both.oracle, "orange_book_fresnel");
  const Manifest handWritten =
      loadManifest(write(withOracleLine("oracle = \"orange_book_fresnel\"")));
  EXPECT_FALSE(handWritten.derivedOracle);
  EXPECT_EQ(handWritten.oracle, "orange_book_fresnel");
}

// `oracle = "derivd"` was taken for a hand-written oracle's name, and the
// first message was about what that oracle mirrors: the near miss is said.
TEST_F(ManifestTest, ANearMissOfDerivedIsSaid) {
  for (const char* line :
       {"oracle = \"derivd\"", "oracle = [\"orange_book_fresnel\", \"Derived\"]"}) {
    const std::string message = errorOf(withOracleLine(line));
    EXPECT_NE(message.find("did you mean \"derived\""), std::string::npos)
        << line << ": " << message;
  }
}

// The derived oracle follows the listing through both stages; a
// hand-written one mirrors one stage, so both captures beside it are refused.
TEST_F(ManifestTest, OnlyTheDerivedOracleAloneMayCaptureBothStages) {
  std::string text = kValid;
  const auto replace = [&](const std::string& from, const std::string& to) {
    text.replace(text.find(from), from.size(), to);
  };
  replace("stages = { vertex = \"a.vert\" }",
          "stages = { vertex = \"a.vert\", fragment = \"a.frag\" }");
  replace("vertex = [\"Reflect\"]",
          "vertex = [\"Reflect\"]\nfragment = [{ name = \"R\", type = \"vec3\", line = 3 }]");
  const std::string derived = [&] {
    std::string t = text;
    const std::size_t at = t.find("oracle =");
    return t.replace(at, t.find('\n', at) - at, "");
  }();
  const Manifest m = loadManifest(write(derived));
  EXPECT_EQ(m.captureVertex, std::vector<std::string>{"Reflect"});
  ASSERT_EQ(m.captureFragment.size(), 1u);
  const std::string message = errorOf(text);
  EXPECT_NE(message.find("lists both vertex outputs and fragment values, and oracle "
                         "`orange_book_fresnel` mirrors one stage"),
            std::string::npos)
      << message;
}

TEST_F(ManifestTest, AnOracleFieldOfTheWrongShapeNamesItsLine) {
  for (const char* bad : {"oracle = 3", "oracle = []", "oracle = [\"a\", \"b\"]",
                          "oracle = [\"a\", 3]", "oracle = [\"a\", \"derived\", \"c\"]"}) {
    const std::string message = errorOf(withOracleLine(bad));
    EXPECT_NE(message.find("manifest.toml:5:"), std::string::npos) << bad << ": " << message;
    EXPECT_NE(message.find("`oracle`"), std::string::npos) << bad << ": " << message;
  }
}

TEST_F(ManifestTest, WrongTypeNamesTheLine) {
  std::string text = kValid;
  text.replace(text.find("title = \"t\""), 11, "title = 3");
  const std::string message = errorOf(text);
  EXPECT_NE(message.find("manifest.toml:2:"), std::string::npos) << message;
}

TEST_F(ManifestTest, WrongVectorLengthIsRejected) {
  std::string text = kValid;
  text.replace(text.find("[1, 0, 0, 0, 1, 0, 0, 0, 1]"), 27, "[1, 0, 0, 0, 1, 0, 0, 0]");
  const std::string message = errorOf(text);
  EXPECT_NE(message.find("manifest.toml:13:"), std::string::npos) << message;
  EXPECT_NE(message.find("mat3 has 9"), std::string::npos) << message;
}

TEST_F(ManifestTest, BindingStringMustBeASemantic) {
  std::string text = kValid;
  text.replace(text.find("\"scene.modelview\""), 17, "\"modelview\"");
  EXPECT_NE(errorOf(text).find("starts with \"scene.\""), std::string::npos);
}

TEST_F(ManifestTest, BrokenTomlGivesLine) {
  EXPECT_NE(errorOf("id = \"x\"\ntitle = \n").find("manifest.toml:2:"), std::string::npos);
}

TEST_F(ManifestTest, MissingStageFileIsAUsageError) {
  std::string text = kValid;
  text.replace(text.find("a.vert"), 6, "gone.vert");
  const Manifest m = loadManifest(write(text));
  EXPECT_THROW(loadProgram(m), UsageError);
}

TEST_F(ManifestTest, UnknownSemanticNamesTheLineAndTheScene) {
  std::string text = kValid;
  text.replace(text.find("scene.modelview"), 15, "scene.nonsense");
  const Manifest m = loadManifest(write(text));
  try {
    resolveBindings(m, makeScene("sphere"));
    FAIL() << "no error";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("manifest.toml:10:"), std::string::npos)
        << error.what();
    EXPECT_NE(std::string(error.what()).find("scene.nonsense"), std::string::npos);
  }
}

// An input bound to a uniform's semantic (or a uniform to a per-vertex
// one) was told the scene "does not provide" what the same message then
// listed: it says which kind each takes.
TEST_F(ManifestTest, ASemanticOfTheOtherKindIsNamedAsSuch) {
  for (const auto& [from, to, expected] :
       std::vector<std::tuple<std::string, std::string, std::string>>{
           {"MCvertex = \"scene.position\"", "MCvertex = \"scene.modelview\"",
            "input `MCvertex` is bound to scene.modelview, which is one value for the whole draw "
            "(a uniform's); bind a per-vertex semantic: scene."},
           {"M = \"scene.modelview\"", "M = \"scene.position\"",
            "uniform `M` is bound to scene.position, which is per vertex (an input's); bind a "
            "value for the draw: scene."}}) {
    std::string text = kValid;
    text.replace(text.find(from), from.size(), to);
    const Manifest m = loadManifest(write(text));
    try {
      resolveBindings(m, makeScene("sphere"));
      FAIL() << "no error for " << to;
    } catch (const UsageError& error) {
      EXPECT_NE(std::string(error.what()).find(expected), std::string::npos) << error.what();
      EXPECT_EQ(std::string(error.what()).find("does not provide"), std::string::npos)
          << error.what();
    }
  }
}

// A case id becomes a folder below --out and --golden: an id that leaves
// them (or names nothing) is refused at its line, before any file is written.
TEST_F(ManifestTest, AnIdThatWouldLeaveItsFolderIsRefused) {
  for (const char* bad :
       {"../../escaped", "/tmp/absolute", "a/../b", "a//b", "a/", "./a", "a b/c", ""}) {
    std::string text = kValid;
    text.replace(text.find("\"x/y\""), 5, fmt::format("\"{}\"", bad));
    const std::string message = errorOf(text);
    EXPECT_NE(message.find("manifest.toml:1:"), std::string::npos) << bad << ": " << message;
    EXPECT_NE(message.find("becomes a folder below --out and --golden"), std::string::npos)
        << bad << ": " << message;
  }
  EXPECT_EQ(listingIdProblem("orange-book/14.1-fresnel"), "");
  EXPECT_EQ(listingIdProblem("methods/fresnel/1-constant-mix"), "");
}

// A scene's name ends the case's id, a folder below --out and --golden: a
// path there put the case's images and goldens outside both, and on top of
// each other's. Refused at its line.
TEST_F(ManifestTest, ASceneThatIsAPathIsRefused) {
  for (const char* bad :
       {"../../../work/main/scenes/sphere", "..", ".", "a/sphere", "/tmp/x", ""}) {
    std::string text = kValid;
    text.replace(text.find("scene = \"sphere\""), 16, fmt::format("scene = \"{}\"", bad));
    const std::string message = errorOf(text);
    EXPECT_NE(message.find("manifest.toml:"), std::string::npos) << bad << ": " << message;
    EXPECT_NE(message.find("is not a scene's name"), std::string::npos) << bad << ": " << message;
  }
}

// TOML's nan and inf are numbers; a tolerance or a time limit must be a
// finite one in its range, and a line number one that fits.
TEST_F(ManifestTest, NumbersOutOfTheirRangeNameTheirLine) {
  // An image is the fragment stage's: the listing has one here.
  std::string withImage = std::string(kValid) +
                          "checks = [\"vectors\", \"image\"]\n"
                          "image = { fail = 0.004, warn = 0.002, failpercent = 0.0, "
                          "hardfail = 0.05 }\n";
  withImage.replace(withImage.find("vertex = \"a.vert\""), 17,
                    "vertex = \"a.vert\", fragment = \"a.frag\"");
  EXPECT_EQ(loadManifest(write(withImage)).cases[0].image.fail, 0.004);
  for (const auto& [from, to, expected] :
       std::vector<std::tuple<std::string, std::string, std::string>>{
           {"fail = 0.004", "fail = nan", "`image.fail` must be a finite number"},
           {"warn = 0.002", "warn = inf", "`image.warn` must be a finite number"},
           {"failpercent = 0.0", "failpercent = 250.0", "`image.failpercent` is a percentage"}}) {
    std::string text = withImage;
    text.replace(text.find(from), from.size(), to);
    const std::string message = errorOf(text);
    EXPECT_NE(message.find("manifest.toml:19: " + expected), std::string::npos)
        << to << ": " << message;
  }
  for (const char* timeout : {"timeout = 1e300", "timeout = nan", "timeout = 0"}) {
    const std::string message = errorOf(std::string(timeout) + "\n" + kValid);
    EXPECT_NE(message.find("manifest.toml:1:"), std::string::npos) << timeout << ": " << message;
    EXPECT_NE(message.find("`timeout`"), std::string::npos) << timeout << ": " << message;
  }
  EXPECT_EQ(loadManifest(write("timeout = 86400\n" + std::string(kValid))).timeoutSeconds, 86400);
  std::string text = kValid;
  text.replace(text.find("vertex = \"a.vert\""), 17, "vertex = \"a.vert\", fragment = \"a.frag\"");
  text.replace(text.find("vertex = [\"Reflect\"]"), 20,
               "fragment = [{ name = \"r\", type = \"vec3\", line = 4294967309 }]");
  EXPECT_NE(errorOf(text).find("`line` must be the fragment file's line"), std::string::npos)
      << errorOf(text);
}

TEST_F(ManifestTest, FilterMatchesCaseIds) {
  std::vector<Manifest> manifests{loadManifest(write(kValid))};
  EXPECT_EQ(expandCases(manifests, "").size(), 1u);
  EXPECT_EQ(expandCases(manifests, "x/*").size(), 1u);
  EXPECT_EQ(expandCases(manifests, "x/y/sphere").size(), 1u);
  EXPECT_EQ(expandCases(manifests, "z/*").size(), 0u);
}

TEST(RepositoryManifests, AllLoadAndResolve) {
  const std::vector<Manifest> manifests = loadManifests(SNELL_SOURCE_ROOT "/shaders");
  ASSERT_FALSE(manifests.empty());
  for (const Case& c : expandCases(manifests, "")) {
    EXPECT_NO_THROW(loadProgram(*c.manifest)) << c.id;
    EXPECT_NO_THROW(resolveBindings(*c.manifest, makeScene(c.spec.scene))) << c.id;
  }
}

}  // namespace
}  // namespace snell
