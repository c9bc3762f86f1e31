#pragma once
// Listings edited behind the manifest's back, for the tests that show an
// edit is caught: a copy of one listing folder with one stage file changed,
// and its cases run on both backends (Vulkan under validation). The oracle
// and the CPU reference read the listing as the manifest describes it; the
// backends run the edited text.
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "backends/backend.h"
#include "core/case.h"
#include "runner/case_runner.h"

namespace snell::edited {

namespace fs = std::filesystem;

// Replaces the first `from` in `file` with `to`; a `from` that is not there
// fails the test and leaves the file as it was.
inline void replaceInFile(const fs::path& file, const std::string& from, const std::string& to) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  std::string source = text.str();
  const std::size_t at = source.find(from);
  EXPECT_NE(at, std::string::npos) << from << " not in " << file;
  if (at == std::string::npos) return;
  source.replace(at, from.size(), to);
  std::ofstream(file, std::ios::trunc) << source;
}

// Copies shaders/<listing> to a fresh temporary folder and replaces the
// first `from` in `file` with `to`; a `from` that is not there fails the test.
inline fs::path editedCopy(const std::string& listing, const std::string& file,
                           const std::string& from, const std::string& to) {
  static std::atomic<int> copies{0};
  const fs::path dir = fs::temp_directory_path() / ("snell-edited-" + std::to_string(::getpid()) +
                                                    "-" + std::to_string(copies++));
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::copy(fs::path(SNELL_SOURCE_ROOT "/shaders") / listing, dir, fs::copy_options::recursive);
  replaceInFile(dir / file, from, to);
  return dir;
}

struct EditedResult {
  std::string backend;
  Case c;
  CaseResult result;
};

// Every case of the folder's listings on gl and vk; removes the folder.
inline std::vector<EditedResult> runOnBothBackends(const fs::path& dir) {
  const std::vector<Manifest> manifests = loadManifests(dir);
  const std::vector<Case> cases = expandCases(manifests, "");
  EXPECT_FALSE(cases.empty());
  std::vector<EditedResult> results;
  for (const char* name : {"gl", "vk"}) {
    std::unique_ptr<Backend> backend = makeBackend(name, BackendOptions{.validation = true});
    OracleCache oracles;
    SceneCache scenes;
    ReferenceCache references;
    CaseRunner runner(*backend, oracles, scenes, references,
                      ImageCheckOptions{dir / "out", SNELL_SOURCE_ROOT "/golden"});
    for (const Case& c : cases) results.push_back({name, c, runner.run(c)});
  }
  fs::remove_all(dir);
  return results;
}

// Every case fails with components outside their intervals, and a case
// that draws fails its image against the CPU reference too.
inline void expectEveryCaseFails(const fs::path& dir) {
  for (const EditedResult& r : runOnBothBackends(dir)) {
    const std::string where = r.backend + " " + r.c.id + "\n" + r.result.message;
    EXPECT_EQ(r.result.status, Status::Fail) << where;
    EXPECT_GT(r.result.componentsFailed(), 0u) << where;
    if (r.c.spec.has("image")) {
      ASSERT_FALSE(r.result.images.empty()) << where;
      EXPECT_EQ(r.result.images[0].against, "reference");
      EXPECT_EQ(r.result.images[0].verdict, ImageVerdict::Fail) << where;
    }
  }
}

}  // namespace snell::edited
