// Every case of the repository's listings, on both backends, as a test.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

#include "backends/backend.h"
#include "core/case.h"
#include "runner/case_runner.h"

namespace snell {
namespace {

struct Conformance {
  std::vector<Manifest> manifests = loadManifests(SNELL_SOURCE_ROOT "/shaders");
  std::vector<Case> cases = expandCases(manifests, "");
  OracleCache oracles;
  SceneCache scenes;
  ReferenceCache references;
  std::filesystem::path outDir = std::filesystem::temp_directory_path() / "snell-conformance-out";
  std::map<std::string, std::unique_ptr<Backend>> backends;

  Backend& backend(const std::string& name) {
    auto& slot = backends[name];
    if (!slot) slot = makeBackend(name, BackendOptions{.validation = true});
    return *slot;
  }
  static Conformance& get() {
    // Never destroyed: tearing a GL context down from a static destructor
    // runs after Mesa's own exit handlers and crashes inside libOSMesa.
    static Conformance* instance = new Conformance;
    return *instance;
  }
};

struct Param {
  std::string backend;
  std::size_t index;
};

class ConformanceCase : public ::testing::TestWithParam<Param> {};

// Each case ends as its manifest expects: Pass against the oracle, or
// ExpectedCompileError with a diagnostic, or NotSupported with its reason.
TEST_P(ConformanceCase, EndsAsItsManifestExpects) {
  Conformance& all = Conformance::get();
  const Case& c = all.cases.at(GetParam().index);
  CaseRunner runner(all.backend(GetParam().backend), all.oracles, all.scenes, all.references,
                    ImageCheckOptions{all.outDir, SNELL_SOURCE_ROOT "/golden"});
  const CaseResult result = runner.run(c);
  const Manifest& m = *c.manifest;
  if (m.notSupported.count(GetParam().backend)) {
    EXPECT_EQ(result.status, Status::NotSupported) << result.message;
    EXPECT_EQ(result.message, m.notSupported.at(GetParam().backend));
    return;
  }
  if (m.expect == Expectation::CompileError) {
    EXPECT_EQ(result.status, Status::ExpectedCompileError) << result.message;
    EXPECT_FALSE(result.compileLog.empty());  // the diagnostic the report quotes
    return;
  }
  EXPECT_EQ(result.status, Status::Pass) << result.message;
  EXPECT_GT(result.componentsChecked(), 1000u);  // thousands of values, not a handful
  RecordProperty("worst_slack", std::to_string(result.worstSlack()));
  RecordProperty("components_checked", std::to_string(result.componentsChecked()));
}

std::vector<Param> allParams() {
  std::vector<Param> params;
  const std::size_t n = Conformance::get().cases.size();
  for (const char* backend : {"gl", "vk"})
    for (std::size_t k = 0; k < n; ++k) params.push_back({backend, k});
  return params;
}

std::string paramName(const ::testing::TestParamInfo<Param>& info) {
  std::string id = info.param.backend + "_" + Conformance::get().cases.at(info.param.index).id;
  for (char& ch : id)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return id;
}

INSTANTIATE_TEST_SUITE_P(Listings, ConformanceCase, ::testing::ValuesIn(allParams()), paramName);

}  // namespace
}  // namespace snell
