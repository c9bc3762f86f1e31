// The blog's legacy listings edited behind the manifest's back must fail on
// both APIs: OpenGL runs the edited shader on its fixed-function state,
// Vulkan through the legacy adapter, and the oracle reads the constants
// and the texture units as printed.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "backends/backend.h"
#include "core/case.h"
#include "runner/case_runner.h"

namespace snell {
namespace {

namespace fs = std::filesystem;

// Copies one listing folder to a temporary place and edits one stage file.
fs::path editedCopy(const std::string& listing, const std::string& file, const std::string& from,
                    const std::string& to) {
  const fs::path dir =
      fs::temp_directory_path() / ("snell-blog-edited-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::copy(fs::path(SNELL_SOURCE_ROOT "/shaders") / listing, dir, fs::copy_options::recursive);
  std::ifstream in(dir / file);
  std::stringstream text;
  text << in.rdbuf();
  std::string source = text.str();
  const std::size_t at = source.find(from);
  EXPECT_NE(at, std::string::npos) << from << " not in " << file;
  source.replace(at, from.size(), to);
  std::ofstream(dir / file, std::ios::trunc) << source;
  return dir;
}

void expectEveryCaseFails(const fs::path& dir) {
  const std::vector<Manifest> manifests = loadManifests(dir);
  const std::vector<Case> cases = expandCases(manifests, "");
  ASSERT_FALSE(cases.empty());
  for (const char* name : {"gl", "vk"}) {
    std::unique_ptr<Backend> backend = makeBackend(name, BackendOptions{.validation = true});
    OracleCache oracles;
    SceneCache scenes;
    ReferenceCache references;
    CaseRunner runner(*backend, oracles, scenes, references,
                      ImageCheckOptions{dir / "out", SNELL_SOURCE_ROOT "/golden"});
    for (const Case& c : cases) {
      const CaseResult result = runner.run(c);
      EXPECT_EQ(result.status, Status::Fail) << name << " " << c.id << "\n" << result.message;
      EXPECT_GT(result.componentsFailed(), 0u) << name << " " << c.id;
      if (c.spec.has("image")) {
        ASSERT_FALSE(result.images.empty()) << name << " " << c.id;
        EXPECT_EQ(result.images[0].against, "reference");
        EXPECT_EQ(result.images[0].verdict, ImageVerdict::Fail) << name << " " << c.id;
      }
    }
  }
  fs::remove_all(dir);
}

TEST(BlogChangedConstant, FresnelEtaEditedFailsOnBothBackends) {
  expectEveryCaseFails(
      editedCopy("blog/fresnel", "fresnel.vert", "const float Eta=0.6;", "const float Eta=0.61;"));
}

// The refraction reads texture unit 0's matrix and the reflection unit 1's;
// the manifest binds them to different matrices, so a swap is seen.
TEST(BlogChangedConstant, FresnelTextureUnitSwappedFailsOnBothBackends) {
  expectEveryCaseFails(editedCopy("blog/fresnel", "fresnel.vert",
                                  "vec3(gl_TextureMatrix[1] * vec4(Reflect,1.0))",
                                  "vec3(gl_TextureMatrix[0] * vec4(Reflect,1.0))"));
}

TEST(BlogChangedConstant, ChromaticEtaREditedFailsOnBothBackends) {
  expectEveryCaseFails(editedCopy("blog/chromatic", "chromatic.vert", "const float EtaR=0.3;",
                                  "const float EtaR=0.31;"));
}

TEST(BlogChangedConstant, DiffractionWidthEditedFailsOnBothBackends) {
  expectEveryCaseFails(editedCopy("blog/diffraction", "diffraction.vert", "const float c = 10.0;",
                                  "const float c = 11.0;"));
}

}  // namespace
}  // namespace snell
