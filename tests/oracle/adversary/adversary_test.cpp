// The standing proof that the oracle is sound: the adversarial machine
// (adversarial_machine.h) makes every choice the precision rules allow, on
// random and edge inputs, for the built-ins the catalog uses, for every
// catalog listing and for the derived programs of the catalog's captures,
// under the GLSL and the Vulkan rules; every vector it
// returns must fit one of the oracle's alternatives whole. Then, that the
// machine really reaches the choices it claims to make, so that a clean
// run means something.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>

#include "adversary/adversarial_machine.h"
#include "adversary/adversary_check.h"
#include "adversary/adversary_inputs.h"
#include "core/manifest.h"
#include "derived/manifest_requests.h"
#include "oracle/glsl/glsl.h"
#include "oracle/vertex_oracle.h"

namespace snell::adversary {
namespace {

constexpr PrecisionRules kRules[] = {PrecisionRules::Glsl, PrecisionRules::Vulkan};

void expectNoEscape(const Tally& tally, const char* what) {
  std::printf("%s: %llu machine evaluations, %llu escapes\n", what,
              static_cast<unsigned long long>(tally.evaluations),
              static_cast<unsigned long long>(tally.escapes));
  for (const std::string& e : tally.firstEscapes) ADD_FAILURE() << e;
  EXPECT_EQ(tally.escapes, 0u);
  EXPECT_GT(tally.evaluations, 0u);
}

TEST(Adversary, BuiltinsStayInsideTheOracle) {
  Tally tally;
  Rng rng(0x5eed0001);
  for (PrecisionRules rules : kRules)
    for (Formula f : kAllFormulas)
      for (int input = 0; input < 1500; ++input)
        checkFormula(f, formulaInputs(f, rng), rules, 8, rng.next(), tally);
  expectNoEscape(tally, "built-ins");
}

TEST(Adversary, CatalogListingsStayInsideTheOracle) {
  Tally tally;
  Rng rng(0x5eed0002);
  for (PrecisionRules rules : kRules)
    for (const ListingInputs& listing : catalogListings())
      checkListing(sampleVertices(listing, 24, rng), rules, 6, rng.next(), tally);
  expectNoEscape(tally, "catalog listings");
}

// The derived oracle (a user's own shader, lowered from its text) holds
// too: the machine makes its choices along the derived program's own
// operations, not the hand-written listing's.
TEST(Adversary, DerivedProgramsStayInsideTheDerivedOracle) {
  Tally tally;
  Rng rng(0x5eed0004);
  std::size_t listings = 0;
  for (PrecisionRules rules : kRules)
    for (const DerivedListingInputs& listing : derivedCatalogListings()) {
      const DerivedListingInputs sampled{listing.source, listing.outputs,
                                         sampleVertices(listing.bindings, 12, rng),
                                         listing.handWritten};
      checkDerivedListing(sampled, rules, 4, rng.next(), tally);
      ++listings;
    }
  std::printf("%zu listing runs, %llu of %llu components bounded\n", listings,
              static_cast<unsigned long long>(tally.boundedComponents),
              static_cast<unsigned long long>(tally.components));
  expectNoEscape(tally, "derived programs");
  // Not a pass on undefined components: nearly all of them are bounded.
  EXPECT_GT(tally.boundedComponents * 10, tally.components * 9);
}

// The hand-written listings run on the machine, against the oracle derived
// from the published text: what the lowering makes of the text must allow
// what an implementation of the listing may return.
TEST(Adversary, HandWrittenListingsStayInsideTheDerivedOracle) {
  Tally tally;
  Rng rng(0x5eed0007);
  for (PrecisionRules rules : kRules)
    for (const DerivedListingInputs& listing : derivedCatalogListings())
      checkHandWrittenAgainstDerived(
          {listing.source, listing.outputs, sampleVertices(listing.bindings, 12, rng),
           listing.handWritten},
          rules, 4, rng.next(), tally);
  std::printf("%llu of %llu components bounded\n",
              static_cast<unsigned long long>(tally.boundedComponents),
              static_cast<unsigned long long>(tally.components));
  expectNoEscape(tally, "hand-written listings against the derived oracle");
  EXPECT_GT(tally.boundedComponents * 10, tally.components * 9);
}

// The check above fails where the derived oracle reads another text than
// the hand-written listing mirrors: Listing 14.1 with Eta edited.
TEST(Adversary, AHandWrittenListingEscapesTheOracleOfAnEditedText) {
  const auto& all = derivedCatalogListings();
  const auto fresnel = std::find_if(all.begin(), all.end(), [](const DerivedListingInputs& l) {
    return l.bindings.oracle == "orange-book/14.1-fresnel" &&
           l.source.stage == derived::Stage::Vertex;
  });
  ASSERT_NE(fresnel, all.end());
  ASSERT_NE(fresnel->source.text.find("Eta = 0.66"), std::string::npos);
  Rng rng(0x5eed0008);
  DerivedListingInputs edited{fresnel->source, fresnel->outputs,
                              sampleVertices(fresnel->bindings, 12, rng), fresnel->handWritten};
  Tally own;
  checkHandWrittenAgainstDerived(edited, PrecisionRules::Glsl, 2, 11, own);
  EXPECT_EQ(own.escapes, 0u);
  EXPECT_GT(own.components, 0u);
  edited.source.text.replace(edited.source.text.find("Eta = 0.66"), 10, "Eta = 0.67");
  Tally other;
  checkHandWrittenAgainstDerived(edited, PrecisionRules::Glsl, 2, 11, other);
  EXPECT_GT(other.escapes, 0u) << "the listing with Eta = 0.66 fit the oracle of Eta = 0.67";
}

// Every capture the derived oracle gates in the catalog is run on the
// machine (a listing gated by its hand-written oracle alone may be left
// out where the derived oracle cannot read it).
TEST(Adversary, EveryDerivedGatedCaptureRunsOnTheMachine) {
  std::set<std::pair<std::string, int>> covered;
  for (const DerivedListingInputs& listing : derivedCatalogListings())
    covered.insert({listing.bindings.oracle, static_cast<int>(listing.source.stage)});
  std::size_t gated = 0;
  for (const Manifest& m : loadManifests(SNELL_SOURCE_ROOT "/shaders")) {
    if (!m.derivedOracle || m.cases.empty() || m.expect == Expectation::CompileError) continue;
    for (derived::Stage stage : {derived::Stage::Vertex, derived::Stage::Fragment}) {
      if (derived::captureRequests(m, stage).empty()) continue;
      ++gated;
      EXPECT_TRUE(covered.count({m.id, static_cast<int>(stage)}))
          << m.id << (stage == derived::Stage::Vertex ? " vertex" : " fragment");
    }
  }
  EXPECT_GT(gated, 0u);
}

// A listing of its own, refract() written out in plain arithmetic, so that
// the derived program's own operations (literals, dot, products, sums, a
// comparison, a select, sqrt) carry the machine's choices, with random unit
// I and N at 12 vertices.
DerivedListingInputs refractListing(const std::string& eta, Rng& rng) {
  const std::string text =
      "#version 330 core\nin vec3 I;\nin vec3 N;\nout vec3 R;\n"
      "void main() {\n"
      "  float d = dot(N, I);\n"
      "  float k = 1.0 - " +
      eta + " * " + eta +
      " * (1.0 - d * d);\n"
      "  R = k < 0.0 ? vec3(0.0) : " +
      eta + " * I - (" + eta +
      " * d + sqrt(k)) * N;\n"
      "  gl_Position = vec4(I, 1.0);\n}\n";
  ListingInputs bindings{"refract-" + eta, {}, {}, {}, 12};
  for (const char* name : {"I", "N"}) {
    AttributeStream stream{name, 3, {}};
    for (std::size_t v = 0; v < bindings.vertexCount; ++v) {
      const std::vector<float> unit = formulaInputs(Formula::Normalize, rng);
      const float n = std::sqrt(unit[0] * unit[0] + unit[1] * unit[1] + unit[2] * unit[2]);
      for (int k = 0; k < 3; ++k)
        stream.data.push_back(std::isfinite(n) && n > 0.0f ? unit[k] / n : (k == 2 ? 1.0f : 0.0f));
    }
    bindings.attributes.emplace(name, std::move(stream));
  }
  return {{"refract.vert", text, derived::Stage::Vertex}, {{"R", 0}}, bindings, ""};
}

TEST(Adversary, ADerivedCheckFailsWhereTheMachineRunsAnEditedText) {
  Rng rng(0x5eed0005);
  const DerivedListingInputs listing = refractListing("0.66", rng);
  const DerivedListingInputs edited = refractListing("0.67", rng);
  for (PrecisionRules rules : kRules) {
    Tally own, other;
    checkDerivedListing(listing, rules, 4, 7, own);
    checkDerivedListing(listing, edited.source, rules, 4, 7, other);
    EXPECT_EQ(own.escapes, 0u) << (own.firstEscapes.empty() ? "" : own.firstEscapes[0]);
    EXPECT_GT(other.escapes, 0u) << "an eta of 0.67 passed against 0.66's intervals";
  }
}

// The machine makes its choices along a derived program too: a vertex
// gives more than one vector over fresh seeds (were it always the same,
// the check above could pass by never leaving the strict evaluation).
TEST(Adversary, MachineChoosesAlongADerivedProgram) {
  Rng rng(0x5eed0006);
  const DerivedListingInputs listing = refractListing("0.66", rng);
  for (PrecisionRules rules : kRules) {
    std::size_t varied = 0;
    for (std::size_t vertex = 0; vertex < listing.bindings.vertexCount; ++vertex) {
      std::set<std::vector<float>> seen;
      for (std::uint64_t seed = 1; seed <= 32; ++seed)
        seen.insert(derivedOnMachine(listing, vertex, rules, seed));
      if (seen.size() > 1) ++varied;
    }
    EXPECT_GT(varied, listing.bindings.vertexCount / 2) << precisionRulesName(rules);
  }
}

TEST(Adversary, EveryRegisteredListingRunsOnTheMachine) {
  std::set<std::string> covered;
  for (const ListingInputs& listing : catalogListings()) covered.insert(listing.oracle);
  for (const std::string& name : vertexOracleNames()) {
    EXPECT_TRUE(covered.count(name)) << name << " has no catalog manifest to draw inputs from";
    const auto machine = machineListings();
    EXPECT_NE(std::find(machine.begin(), machine.end(), name), machine.end())
        << name << " has no machine run";
  }
}

TEST(Adversary, AVectorMustFitOneWayWhole) {
  // Two ways, as near the critical angle: the zero vector or a ray.
  const std::vector<std::vector<Interval>> ways = {
      {Interval(0.0, 0.0), Interval(0.0, 0.0)},
      {Interval(0.5, 0.6), Interval(-0.2, -0.1)},
  };
  EXPECT_TRUE(fitsOneWay(ways, std::vector<float>{0.0f, 0.0f}));
  EXPECT_TRUE(fitsOneWay(ways, std::vector<float>{0.55f, -0.15f}));
  EXPECT_FALSE(fitsOneWay(ways, std::vector<float>{0.0f, -0.15f})) << "a mix of the two";
  EXPECT_FALSE(fitsOneWay(ways, std::vector<float>{0.55f, -0.25f})) << "outside the ray's y";
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(fitsOneWay(ways, std::vector<float>{nan, nan})) << "NaN where the spec says a value";
  const std::vector<std::vector<Interval>> open = {{Interval::unconstrained(), Interval(1.0, 1.0)}};
  EXPECT_TRUE(fitsOneWay(open, std::vector<float>{nan, 1.0f}));
  EXPECT_FALSE(fitsOneWay(open, std::vector<float>{nan, 2.0f}));
}

// The values the machine returns for f over many runs.
template <class F>
std::set<float> spread(F f, PrecisionRules rules = PrecisionRules::Glsl, int runs = 2000) {
  std::set<float> values;
  const UsePrecisionRules use(rules);
  for (int run = 0; run < runs; ++run) {
    Machine::begin(0x1000 + static_cast<std::uint64_t>(run), rules);
    values.insert(f().value());
  }
  return values;
}

TEST(Adversary, MachineRoundsEitherWayAndFuses) {
  // 1 + 2^-30 is no float: either neighbour. a*b+c with a*b inexact: the
  // fused result differs from both roundings of the rounded product.
  const auto sum = spread([] { return Adv(1.0f) + Adv(0x1p-30f); });
  EXPECT_EQ(sum, (std::set<float>{1.0f, std::nextafter(1.0f, 2.0f)}));
  const float a = 1.0f + 0x1p-12f, c = -1.0f - 0x1p-11f;
  const auto fma = spread([&] { return Adv(a) * Adv(a) + Adv(c); });
  EXPECT_TRUE(fma.count(0x1p-24f)) << "fused: a*a + c exactly";
  EXPECT_TRUE(fma.count(0.0f)) << "rounded product first";
}

TEST(Adversary, MachineRegroupsProductsAndSums) {
  // (x*y)*z and x*(y*z) round differently for these; so do (1 + e) - 1
  // as written and 1 - 1 + e regrouped.
  const float x = 1.0f + 0x1p-23f, y = 1.0f + 0x1p-22f, z = 3.0f;
  const auto product = spread([&] { return Adv(x) * Adv(y) * Adv(z); });
  EXPECT_GE(product.size(), 3u);
  const auto sum = spread([] { return (Adv(1.0f) + Adv(0x1p-30f)) - Adv(1.0f); });
  EXPECT_TRUE(sum.count(0x1p-30f)) << "regrouped";
  EXPECT_TRUE(sum.count(0.0f)) << "as written, rounded down";
}

TEST(Adversary, MachineReachesTheEdgesOfAnUlpBound) {
  // 1/3 within 2.5 ULP: the floats from 2 below to 2 above the nearest one.
  const auto third = spread([] { return Adv(1.0f) / Adv(3.0f); });
  const float nearest = 1.0f / 3.0f;
  float lowest = nearest, highest = nearest;
  for (int k = 0; k < 2; ++k) {
    lowest = std::nextafter(lowest, 0.0f);
    highest = std::nextafter(highest, 1.0f);
  }
  EXPECT_EQ(*third.begin(), lowest);
  EXPECT_EQ(*third.rbegin(), highest);
}

TEST(Adversary, MachineMirrorsAnInheritedBuiltInUnderVulkan) {
  // sqrt(4 - 2^-21) = 2 - 2^-23 (to 2^-47): 1.0 / inversesqrt(x) reaches
  // 2 - 6 * 2^-23 below and 2 + 3 * 2^-22 above, so Vulkan's [x - E, x + E]
  // reaches 2 - 8 * 2^-23, which the formula alone never gives; GLSL takes
  // the formula's values only.
  const float x = 4.0f - 0x1p-21f;
  const auto vulkan = spread([&] { return sqrt(Adv(x)); }, PrecisionRules::Vulkan);
  const auto glsl = spread([&] { return sqrt(Adv(x)); }, PrecisionRules::Glsl);
  EXPECT_EQ(*glsl.begin(), 2.0f - 6 * 0x1p-23f);
  EXPECT_LT(*vulkan.begin(), *glsl.begin());
  EXPECT_GE(*vulkan.begin(), 2.0f - 8 * 0x1p-23f);
  const auto power = spread([] { return pow(Adv(2.0f), Adv(5.0f)); }, PrecisionRules::Vulkan);
  const auto formula = spread([] { return pow(Adv(2.0f), Adv(5.0f)); }, PrecisionRules::Glsl);
  EXPECT_LT(*power.begin(), *formula.begin());
}

TEST(Adversary, MachineDividesByAReciprocalUnderVulkan) {
  // a * (1 / b), each step at its bound, reaches past a / b's own 2.5 ULP
  // for these (an escape the oracle had under the Vulkan rules).
  const auto divide = [] { return Adv(2.13379121f) / Adv(0.85081625f); };
  const auto vulkan = spread(divide, PrecisionRules::Vulkan);
  const auto glsl = spread(divide, PrecisionRules::Glsl);
  EXPECT_GT(*vulkan.rbegin(), *glsl.rbegin());
  EXPECT_TRUE(vulkan.count(2.50793505f));
}

TEST(Adversary, MachineDistributesADividendOverTheReciprocalUnderVulkan) {
  // (a + b) / 3 as a * (1 / 3) + b * (1 / 3): 2^-25, where the exact
  // quotient is 2^-24 / 3.
  const auto divide = [] { return (Adv(1.0f) + Adv(-0.99999994f)) / Adv(3.0f); };
  EXPECT_TRUE(spread(divide, PrecisionRules::Vulkan).count(0x1p-25f));
  EXPECT_FALSE(spread(divide, PrecisionRules::Glsl).count(0x1p-25f));
}

TEST(Adversary, MachineFoldsConstantsEitherWay) {
  // 0.66 * 0.66 folded in double from the decimals: either neighbour of 0.4356.
  const auto folded = spread([] { return Adv::literal(0.66) * Adv::literal(0.66); });
  EXPECT_TRUE(folded.count(static_cast<float>(floatAtOrBelow(0.4356))));
  EXPECT_TRUE(folded.count(static_cast<float>(floatAtOrAbove(0.4356))));
}

TEST(Adversary, MachineFlushesDenormalsAndLeavesUndefinedOpen) {
  const auto flushed = spread([] { return Adv(0x1p-140f) * Adv(1.0f); });
  EXPECT_TRUE(flushed.count(0.0f));
  EXPECT_TRUE(flushed.count(0x1p-140f));
  const auto log0 = spread([] { return log2(Adv(0.0f)); }, PrecisionRules::Glsl, 10);
  ASSERT_EQ(log0.size(), 1u);
  EXPECT_TRUE(std::isnan(*log0.begin()));
  EXPECT_EQ(spread([] { return sqrt(Adv(0.0f)); }), std::set<float>{0.0f});
}

TEST(Adversary, MachineTakesBothWaysNearTheCriticalAngle) {
  // k = 1 - eta^2 (1 - d^2) within a few ULP of 0: some runs return the
  // zero vector, others a refracted ray.
  const float d = -0.7f;
  const float s = std::sqrt(1.0f - d * d);
  const float eta = 1.0f / s;
  int zero = 0, ray = 0;
  for (int run = 0; run < 2000; ++run) {
    Machine::begin(0x2000 + static_cast<std::uint64_t>(run), PrecisionRules::Glsl);
    const glsl::vec3<Adv> I(Adv(s), Adv(d), Adv(0.0f));
    const glsl::vec3<Adv> N(Adv(0.0f), Adv(1.0f), Adv(0.0f));
    const auto r = glsl::refract(I, N, Adv(eta));
    (r[0].value() == 0.0f && r[1].value() == 0.0f ? zero : ray) += 1;
  }
  EXPECT_GT(zero, 0);
  EXPECT_GT(ray, 0);
}

}  // namespace
}  // namespace snell::adversary
