// Two oracles, two questions, on both backends (Vulkan under validation):
// the hand-written oracle is the listing's intent, so an edited shader
// fails against it; the derived oracle is the spec for the text as it
// stands, so the same edit passes it, and a backend that computes anything
// else fails it.
#include <regex>

#include "edited_listing.h"

namespace snell {
namespace {

using edited::editedCopy;
using edited::replaceInFile;
namespace fs = std::filesystem;

void setOracleLine(const fs::path& manifest, const std::string& line) {
  std::ifstream in(manifest);
  std::stringstream text;
  text << in.rdbuf();
  const std::string replaced =
      std::regex_replace(text.str(), std::regex("(^|\n)oracle *=[^\n]*"), "$1" + line);
  ASSERT_NE(replaced, text.str()) << manifest;
  std::ofstream(manifest, std::ios::trunc) << replaced;
}

bool fromDerived(const VaryingCheck& v) { return v.name.ends_with(" (derived)"); }

TEST(DerivedOracle, AnEditedShaderFailsTheHandWrittenOracleAndPassesTheDerivedOne) {
  const fs::path dir = editedCopy("orange-book/14.1-fresnel", "fresnel.vert",
                                  "const float Eta = 0.66;", "const float Eta = 0.67;");
  setOracleLine(dir / "manifest.toml", R"(oracle = ["orange_book_fresnel", "derived"])");
  for (const edited::EditedResult& r : edited::runOnBothBackends(dir)) {
    const std::string where = r.backend + " " + r.c.id + "\n" + r.result.message;
    EXPECT_EQ(r.result.status, Status::Fail) << where;
    std::size_t handFailed = 0, derivedChecked = 0;
    for (const VaryingCheck& v : r.result.varyings) {
      if (fromDerived(v)) {
        derivedChecked += v.checked;
        EXPECT_EQ(v.failed, 0u) << v.name << " " << where;
      } else {
        handFailed += v.failed;
      }
    }
    EXPECT_GT(handFailed, 0u) << where;
    EXPECT_GT(derivedChecked, 0u) << where;
    EXPECT_NE(r.result.message.find("against oracle orange_book_fresnel:"), std::string::npos)
        << where;
    EXPECT_EQ(r.result.message.find("against oracle derived:"), std::string::npos) << where;
  }
}

// The derived oracle evaluates the listing as it stood when the run began;
// the shader is then edited on disk, as if the driver computed something
// else: every component that moved must leave its interval.
TEST(DerivedOracle, ABackendThatComputesSomethingElseFailsTheDerivedOracle) {
  const fs::path dir = editedCopy("orange-book/14.1-fresnel", "fresnel.vert",
                                  "const float Eta = 0.66;", "const float Eta = 0.66;");
  setOracleLine(dir / "manifest.toml", R"(oracle = "derived")");
  const std::vector<Manifest> manifests = loadManifests(dir);
  const std::vector<Case> cases = expandCases(manifests, "*/sphere");
  ASSERT_EQ(cases.size(), 1u);
  for (const char* name : {"gl", "vk"}) {
    std::unique_ptr<Backend> backend = makeBackend(name, BackendOptions{.validation = true});
    OracleCache oracles;
    SceneCache scenes;
    ReferenceCache references;
    CaseRunner runner(*backend, oracles, scenes, references,
                      ImageCheckOptions{dir / "out", dir / "golden"});
    const CaseResult before = runner.run(cases[0]);
    EXPECT_EQ(before.componentsFailed(), 0u) << name << "\n" << before.message;
    EXPECT_GT(before.componentsChecked(), 0u) << name;
    replaceInFile(dir / "fresnel.vert", "Eta = 0.66;", "Eta = 0.67;");
    const CaseResult after = runner.run(cases[0]);
    EXPECT_EQ(after.status, Status::Fail) << name << "\n" << after.message;
    EXPECT_GT(after.componentsFailed(), 0u) << name;
    ASSERT_FALSE(after.images.empty()) << name;
    EXPECT_EQ(after.images[0].verdict, ImageVerdict::Fail) << name;
    replaceInFile(dir / "fresnel.vert", "Eta = 0.67;", "Eta = 0.66;");  // for the next backend
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace snell
