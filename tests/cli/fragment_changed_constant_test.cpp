// A fragment-stage listing edited behind the manifest's back must fail: the
// oracle reads the local constants as printed (the manifest's `constants`),
// the backend runs the edited shader, and the values read back from the
// fragment stage leave their intervals.
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
  const fs::path dir =
      fs::temp_directory_path() / ("snell-fragment-edited-" + std::to_string(::getpid()));
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
      EXPECT_GT(result.componentsFailed(), 0u) << name << " " << c.id << "\n" << result.message;
    }
  }
  fs::remove_all(dir);
}

TEST(FragmentChangedConstant, Cs381IndexEditedFailsOnBothBackends) {
  expectEveryCaseFails(editedCopy("cs381/refraction", "refraction.frag", "float index = 1.1;",
                                  "float index = 1.2;"));
}

TEST(FragmentChangedConstant, ShadertoyLensKoefEditedFailsOnBothBackends) {
  expectEveryCaseFails(editedCopy("shadertoy/lens", "lens.frag", "float refract_koef = 1.02;",
                                  "float refract_koef = 1.03;"));
}

}  // namespace
}  // namespace snell
