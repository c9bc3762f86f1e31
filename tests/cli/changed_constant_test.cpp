// A listing edited behind the manifest's back must fail: the oracle reads
// the constants as printed, the backend runs the edited shader.
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

// Copies one listing folder to a temporary place and edits one stage file.
fs::path editedCopy(const std::string& listing, const std::string& file, const std::string& from,
                    const std::string& to) {
  const fs::path dir = fs::temp_directory_path() / ("snell-edited-" + std::to_string(::getpid()));
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
      EXPECT_EQ(result.status, Status::Fail) << name << " " << c.id;
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

TEST(ChangedConstant, FresnelEtaEditedFailsOnBothBackends) {
  expectEveryCaseFails(editedCopy("orange-book/14.1-fresnel", "fresnel.vert",
                                  "const float Eta = 0.66;", "const float Eta = 0.67;"));
}

TEST(ChangedConstant, FresnelPowerEditedFailsOnBothBackends) {
  expectEveryCaseFails(editedCopy("orange-book/14.1-fresnel", "fresnel.vert",
                                  "const float FresnelPower = 5.0;",
                                  "const float FresnelPower = 4.0;"));
}

TEST(ChangedConstant, SwappedReflectArgumentsFailOnBothBackends) {
  expectEveryCaseFails(editedCopy("orange-book/14.1-fresnel", "fresnel.vert", "reflect(i, n)",
                                  "reflect(n, i)"));
}

TEST(ChangedConstant, ChromaticEtaREditedFailsOnBothBackends) {
  expectEveryCaseFails(editedCopy("orange-book/14.3-chromatic", "chromatic.vert",
                                  "const float EtaR = 0.65;", "const float EtaR = 0.66;"));
}

TEST(ChangedConstant, CgRefractConstantEditedFailsOnBothBackends) {
  expectEveryCaseFails(editedCopy("cg-tutorial/c7e3v-refraction", "c7e3v_refraction.vert",
                                  "float cosT2 = 1.0f", "float cosT2 = 1.01f"));
}

TEST(ChangedConstant, DiffractionWidthEditedFailsOnBothBackends) {
  expectEveryCaseFails(editedCopy("orange-book/14.2-diffraction", "diffraction.vert",
                                  "const float c = 10.0;", "const float c = 11.0;"));
}

}  // namespace
}  // namespace snell
