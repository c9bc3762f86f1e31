// Every catalog listing with a hand-written oracle whose vectors are read
// in the vertex stage, found from its manifest and bound as `snell run`
// binds it: the derived oracle, made by the runner from the listing's own
// text exactly as for a manifest that names both, beside the hand-written
// one on the listing's first scene that reads vertices. (Listings read in
// the fragment stage take inputs read back from a driver; they are
// cross-checked in derived_cross_check_test.cpp with inputs made here.)
#include <gtest/gtest.h>

#include "core/case.h"
#include "core/scene.h"
#include "oracle_comparison.h"
#include "runner/listing_oracles.h"

namespace snell::test {
namespace {

struct CatalogListing {
  Manifest manifest;
  std::string scene;
};

std::vector<CatalogListing> vertexListings() {
  std::vector<CatalogListing> listings;
  for (const Manifest& m : loadManifests(SNELL_SOURCE_ROOT "/shaders")) {
    if (m.oracle.empty() || m.expect != Expectation::Pass || m.captureVertex.empty()) continue;
    listings.push_back({m, m.cases.at(0).scene});
  }
  return listings;
}

class DerivedCatalog : public ::testing::TestWithParam<std::tuple<std::size_t, PrecisionRules>> {
 public:
  static const std::vector<CatalogListing>& listings() {
    static const std::vector<CatalogListing> all = vertexListings();
    return all;
  }
};

TEST_P(DerivedCatalog, HoldsTheHandWrittenExactValueAndReportsWidths) {
  const auto [index, rules] = GetParam();
  const CatalogListing& listing = listings().at(index);
  Manifest both = listing.manifest;
  both.derivedOracle = true;
  const Scene scene = makeScene(listing.scene);
  const ResolvedBindings bindings = resolveBindings(both, scene);
  const std::vector<NamedOracle> oracles = vectorOracles(both, CaptureStage::Vertex);
  ASSERT_EQ(oracles.size(), 2u);
  const OracleInput input{bindings.uniforms, both.constants, bindings.attributes,
                          bindings.vertexCount, rules};
  std::vector<OracleVarying> hand = oracles[0].oracle->evaluate(input);
  // The hand-written oracle may compute more than is captured.
  std::erase_if(hand, [&](const OracleVarying& v) {
    return std::find(both.captureVertex.begin(), both.captureVertex.end(), v.name) ==
           both.captureVertex.end();
  });
  expectAgreement(both.id, rules, hand, oracles[1].oracle->evaluate(input));
}

std::string caseName(
    const ::testing::TestParamInfo<std::tuple<std::size_t, PrecisionRules>>& info) {
  std::string name = DerivedCatalog::listings().at(std::get<0>(info.param)).manifest.id;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name + "_" + precisionRulesName(std::get<1>(info.param));
}

INSTANTIATE_TEST_SUITE_P(
    Listings, DerivedCatalog,
    ::testing::Combine(::testing::Range<std::size_t>(0, DerivedCatalog::listings().size()),
                       ::testing::Values(PrecisionRules::Glsl, PrecisionRules::Vulkan)),
    caseName);

}  // namespace
}  // namespace snell::test
