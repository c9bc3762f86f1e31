// The derived oracle beside the hand-written one, on the sphere scene,
// under both APIs' precision rules: the derived interval must hold the
// hand-written exact value everywhere, the two exact values must agree, and
// the widths are reported (derived / hand-written).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <regex>

#include "core/errors.h"
#include "derived_listings.h"
#include "oracle/vertex_oracle.h"
#include "oracle_comparison.h"

namespace snell::test {
namespace {

struct OracleRuns {
  std::vector<OracleVarying> hand;
  std::vector<OracleVarying> derived;
};

OracleRuns runBoth(const DerivedListing& listing, const std::string& shaderText,
                   PrecisionRules rules) {
  static const Scene sphere = makeScene("sphere");
  const BoundListing bound = bindListing(listing, sphere);
  const auto hand = makeVertexOracle(listing.oracle);
  const derived::ShaderSource source{listing.shader, shaderText, listing.stage};
  ConstantMap constants = listing.constants;
  std::unique_ptr<VertexOracle> derived;
  if (listing.readsBackItsOwnValues()) {
    // Each capture after its line, as snell run asks for it; those the
    // derived oracle cannot compute (uv reads gl_FragCoord, point_normal a
    // ray march) are fed from the read-back values, as the hand-written
    // oracle takes them.
    const Manifest m = listingManifest(listing);
    constants = m.constants;
    std::vector<derived::OutputRequest> requests;
    for (const FragmentCapture& capture : m.captureFragment)
      requests.push_back({capture.name, capture.line});
    // What the hand-written oracle computes beyond the captures, at the end.
    for (const std::string& name : hand->outputs())
      if (std::none_of(requests.begin(), requests.end(),
                       [&](const derived::OutputRequest& r) { return r.name == name; }))
        requests.push_back({name, 0});
    derived = derived::makeDerivedVectorOracle(source, requests);
    EXPECT_EQ(derived->inputs(), hand->inputs()) << listing.label();
    EXPECT_EQ(derived->outputs().size(), hand->outputs().size()) << listing.label();
  } else {
    derived = derived::makeDerivedVertexOracle(source, hand->outputs());
  }
  const OracleInput input{bound.uniforms, constants, bound.attributes, bound.count, rules};
  return OracleRuns{hand->evaluate(input), derived->evaluate(input)};
}

class DerivedCrossCheck : public ::testing::TestWithParam<std::tuple<std::size_t, PrecisionRules>> {
};

TEST_P(DerivedCrossCheck, HoldsTheHandWrittenExactValueAndReportsWidths) {
  const auto [index, rules] = GetParam();
  const DerivedListing& listing = derivedListings()[index];
  const OracleRuns run = runBoth(listing, readListing(listing.shader), rules);
  expectAgreement(listing.label(), rules, run.hand, run.derived);
}

std::string caseName(
    const ::testing::TestParamInfo<std::tuple<std::size_t, PrecisionRules>>& info) {
  return derivedListings()[std::get<0>(info.param)].label() + "_" +
         precisionRulesName(std::get<1>(info.param));
}

INSTANTIATE_TEST_SUITE_P(
    Catalog, DerivedCrossCheck,
    ::testing::Combine(::testing::Range<std::size_t>(0, derivedListings().size()),
                       ::testing::Values(PrecisionRules::Glsl, PrecisionRules::Vulkan)),
    caseName);

// Every catalog listing read back in the fragment stage with a
// hand-written oracle is in the list above (those read in the vertex stage
// are found from their manifests in derived_catalog_test.cpp).
TEST(DerivedCrossCheck, CoversEveryFragmentListingOfTheCatalog) {
  std::size_t listings = 0;
  for (const Manifest& m : loadManifests(SNELL_SOURCE_ROOT "/shaders")) {
    if (m.oracle.empty() || m.expect != Expectation::Pass || m.captureFragment.empty()) continue;
    ++listings;
    const std::string shader =
        (m.path.parent_path() / m.fragmentFile).lexically_relative(SNELL_SOURCE_ROOT "/shaders");
    EXPECT_TRUE(std::any_of(derivedListings().begin(), derivedListings().end(),
                            [&](const DerivedListing& l) { return shader == l.shader; }))
        << m.id << " (" << shader << ") is not cross-checked";
  }
  EXPECT_GE(listings, 7u);
}

// The comparator fails on bad data: with Eta edited in the shader text
// alone, the hand-written exact value (the listing's intent) falls outside
// the derived interval (what the edited text allows).
TEST(DerivedCrossCheck, AnEditedConstantPutsTheHandWrittenValueOutside) {
  const DerivedListing& fresnel = derivedListings()[0];
  ASSERT_STREQ(fresnel.oracle, "orange_book_fresnel");
  const std::string text = readListing(fresnel.shader);
  const std::string edited = std::regex_replace(text, std::regex(R"(Eta = 0\.66;)"), "Eta = 0.67;");
  ASSERT_NE(edited, text);
  const OracleRuns run = runBoth(fresnel, edited, PrecisionRules::Glsl);
  const Comparison c = compare(run.hand, run.derived);
  EXPECT_GT(c.outside, 0u);
  EXPECT_GT(c.exactMismatch, 0u);
}

// A uniform missing from the bindings is named with its line.
TEST(DerivedCrossCheck, AMissingUniformIsNamedWithItsLine) {
  const DerivedListing& fresnel = derivedListings()[0];
  const Scene sphere = makeScene("sphere");
  BoundListing bound = bindListing(fresnel, sphere);
  bound.uniforms.erase("NormalMatrix");
  const auto derived = derived::makeDerivedVertexOracle(
      {fresnel.shader, readListing(fresnel.shader), fresnel.stage});
  try {
    derived->evaluate({bound.uniforms, {}, bound.attributes, bound.count});
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("fresnel.vert:26: the uniform 'NormalMatrix'"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace snell::test
