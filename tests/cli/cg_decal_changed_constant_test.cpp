// The Cg Tutorial's C7E4f_refraction edited behind the manifest's back must
// fail on both backends. The edits are in the fragment program only, so the
// vertex stage's vectors still pass: the failure must come from the image
// check, against the CPU reference (which runs the listing as published)
// and against the golden.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "backends/backend.h"
#include "core/case.h"
#include "runner/case_runner.h"

namespace snell {
namespace {

namespace fs = std::filesystem;

constexpr const char* kListing = "cg-tutorial/c7e4f-refraction";
constexpr const char* kFragment = "c7e4f_refraction.frag";

// Copies the listing folder to a temporary place and edits its fragment program.
fs::path editedCopy(const std::string& from, const std::string& to) {
  const fs::path dir =
      fs::temp_directory_path() / ("snell-decal-edited-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::copy(fs::path(SNELL_SOURCE_ROOT "/shaders") / kListing, dir, fs::copy_options::recursive);
  std::ifstream in(dir / kFragment);
  std::stringstream text;
  text << in.rdbuf();
  std::string source = text.str();
  const std::size_t at = source.find(from);
  EXPECT_NE(at, std::string::npos) << from << " not in " << kFragment;
  source.replace(at, from.size(), to);
  std::ofstream(dir / kFragment, std::ios::trunc) << source;
  return dir;
}

void expectEveryImageFails(const fs::path& dir) {
  const std::vector<Manifest> manifests = loadManifests(dir);
  const std::vector<Case> cases = expandCases(manifests, "");
  ASSERT_EQ(cases.size(), 2u);
  for (const char* name : {"gl", "vk"}) {
    std::unique_ptr<Backend> backend = makeBackend(name, BackendOptions{.validation = true});
    OracleCache oracles;
    SceneCache scenes;
    ReferenceCache references;
    CaseRunner runner(*backend, oracles, scenes, references,
                      ImageCheckOptions{dir / "out", SNELL_SOURCE_ROOT "/golden"});
    for (const Case& c : cases) {
      ASSERT_TRUE(c.spec.has("image")) << c.id;
      const CaseResult result = runner.run(c);
      EXPECT_EQ(result.status, Status::Fail) << name << " " << c.id << "\n" << result.message;
      // The vertex stage was not edited: its vectors still pass.
      EXPECT_EQ(result.componentsFailed(), 0u) << name << " " << c.id;
      ASSERT_EQ(result.images.size(), 2u) << name << " " << c.id << "\n" << result.message;
      EXPECT_EQ(result.images[0].against, "reference");
      EXPECT_EQ(result.images[0].verdict, ImageVerdict::Fail) << name << " " << c.id;
      EXPECT_EQ(result.images[1].against, "golden");
      EXPECT_EQ(result.images[1].verdict, ImageVerdict::Fail) << name << " " << c.id;
    }
  }
  fs::remove_all(dir);
}

TEST(CgDecalChangedConstant, SwappedMixArgumentsFailOnBothBackends) {
  expectEveryImageFails(editedCopy("mix(decalColor, refractedColor, transmittance)",
                                   "mix(refractedColor, decalColor, transmittance)"));
}

TEST(CgDecalChangedConstant, TransmittanceUsedOtherwiseFailsOnBothBackends) {
  expectEveryImageFails(
      editedCopy("mix(decalColor, refractedColor, transmittance)",
                 "mix(decalColor, refractedColor, transmittance * transmittance)"));
}

TEST(CgDecalChangedConstant, SwappedDecalCoordinatesFailOnBothBackends) {
  expectEveryImageFails(
      editedCopy("texture(decalMap, oTexCoord)", "texture(decalMap, oTexCoord.yx)"));
}

}  // namespace
}  // namespace snell
