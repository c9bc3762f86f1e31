// if/else, ?: and loops in the derived oracle: each way is lowered, and where the
// condition may go either way the result holds both.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>

#include "derived_listings.h"
#include "oracle/interval.h"

namespace snell::test {
namespace {

AttributeMap oneInput(const std::string& name, std::vector<float> values) {
  AttributeMap inputs;
  inputs[name] = AttributeStream{name, 1, std::move(values)};
  return inputs;
}

TEST(DerivedBranch, IfElseAndTernaryFollowTheCondition) {
  const derived::Program program = derived::lowerShader({"user.vert", R"(#version 140
in float x;
out float y;
out float z;
void main() {
  y = 0.5;
  if (x > 0.0)
    y = 1.0;
  else
    y = 2.0 * y + 1.0;
  z = x < 1.0 ? -x : x * 3.0;
}
)"});
  const AttributeMap inputs = oneInput("x", {-1.0f, 2.0f});
  const auto exact = derived::evaluateProgram<double>(program, {}, inputs, 2);
  EXPECT_EQ(exact[0], (std::vector<double>{2.0, 1.0}));
  EXPECT_EQ(exact[1], (std::vector<double>{1.0, 6.0}));
  const auto allowed = derived::evaluateProgram<Interval>(program, {}, inputs, 2);
  EXPECT_TRUE(contains(allowed[0][0], 2.0f));
  EXPECT_FALSE(contains(allowed[0][0], 1.0f));
  EXPECT_TRUE(contains(allowed[1][1], 6.0f));
}

// clamp(x, minVal, maxVal) is undefined where minVal > maxVal (GLSL 4.60
// section 8.3): any result is allowed wherever an allowed evaluation of the
// bounds may cross them, and none is where they cannot.
TEST(DerivedBranch, ClampWhoseBoundsMayCrossIsUndefined) {
  const derived::Program program = derived::lowerShader({"user.vert", R"(#version 140
in float x;
out float y;
out float z;
void main() {
  y = clamp(5.0, x, 1.0);
  z = clamp(5.0, 0.0, 1.0);
}
)"});
  const AttributeMap inputs = oneInput("x", {0.5f, 2.0f, 1.0f});
  const auto allowed = derived::evaluateProgram<Interval>(program, {}, inputs, 3);
  EXPECT_FALSE(allowed[0][0].undefined);
  EXPECT_TRUE(contains(allowed[0][0], 1.0f));
  EXPECT_FALSE(contains(allowed[0][0], 2.0f));
  EXPECT_TRUE(allowed[0][1].undefined);   // 2 > 1: undefined
  EXPECT_FALSE(allowed[0][2].undefined);  // 1 = 1: min(max(5, 1), 1) = 1
  EXPECT_FALSE(contains(allowed[0][2], 2.0f));
  EXPECT_FALSE(allowed[1][0].undefined);
  EXPECT_TRUE(contains(allowed[1][0], 1.0f));
  EXPECT_FALSE(contains(allowed[1][0], 0.0f));
}

// A text that tests VULKAN is another text on a Vulkan driver, whose
// compiler defines it: the derived oracle follows each API's text, and
// answers by the rules (only a Vulkan driver is judged by Vulkan's). It
// followed the OpenGL text for both, and failed a correct Vulkan driver.
TEST(DerivedBranch, AShaderThatTestsVulkanIsFollowedOnEachApi) {
  const std::string text = R"(#version 140
in float x;
out float y;
#ifdef VULKAN
#define SCALE 3.0
#else
#define SCALE 2.0
#endif
void main() { y = SCALE * x; }
)";
  EXPECT_TRUE(derived::testsVulkanMacro(text));
  EXPECT_FALSE(derived::testsVulkanMacro("#define NOT_VULKAN_ 1\nfloat VULKANISH;"));
  const auto oracle = derived::makeDerivedVertexOracle({"user.vert", text});
  const AttributeMap inputs = oneInput("x", {1.0f});
  const UniformMap uniforms;
  const ConstantMap constants;
  for (const auto& [rules, expected] :
       {std::pair{PrecisionRules::Glsl, 2.0}, std::pair{PrecisionRules::Vulkan, 3.0}}) {
    const std::vector<OracleVarying> y = oracle->evaluate({uniforms, constants, inputs, 1, rules});
    ASSERT_EQ(y.size(), 1u);
    EXPECT_EQ(y[0].reference[0], expected) << precisionRulesName(rules);
    EXPECT_LE(y[0].lo[0], expected);
    EXPECT_GE(y[0].hi[0], expected);
  }
  // A Vulkan branch in Vulkan-only GLSL does not lower through the OpenGL
  // front end: the text is held against its OpenGL reading on both APIs,
  // as before, instead of stopping every run of the listing.
  const auto vulkanOnly = derived::makeDerivedVertexOracle({"user.vert", R"(#version 450
in float x;
out float y;
#ifdef VULKAN
layout(constant_id = 0) const float SCALE = 3.0;
#else
const float SCALE = 2.0;
#endif
void main() { y = SCALE * x; }
)"});
  for (const PrecisionRules rules : {PrecisionRules::Glsl, PrecisionRules::Vulkan})
    EXPECT_EQ(vulkanOnly->evaluate({uniforms, constants, inputs, 1, rules})[0].reference[0], 2.0);
}

// A for loop with a constant bound is unrolled; float(m) is its counter.
TEST(DerivedLoop, AForLoopWithAConstantBoundRunsItsIterations) {
  const derived::Program program = derived::lowerShader({"user.vert", R"(#version 140
in float x;
out float t;
const int orders = 3;
void main() {
  t = 0.0;
  for (int m = 1; m <= orders; ++m)
    t += x / float(m);
}
)"});
  const auto exact = derived::evaluateProgram<double>(program, {}, oneInput("x", {6.0f}), 1);
  EXPECT_EQ(exact[0][0], 6.0 + 3.0 + 2.0);
}

// GLSL's refract() written out with if/else in a user's shader, on the
// glass-to-air binding of the Cg listing, where k < 0 may go either way
// near the critical angle: its interval holds the exact value of the
// listing's built-in refract() at every sample.
TEST(DerivedBranch, AnIfElseRefractHoldsTheBuiltInsExactValue) {
  const std::string builtin =
      readListing("cg-tutorial/c7e3v-refraction-builtin/c7e3v_refraction_builtin.vert");
  std::string written = builtin;
  const std::string call = "T = refract(I, N, etaRatio);";
  written.replace(written.find(call), call.size(), "T = writtenRefract(I, N, etaRatio);");
  written.insert(written.find("void main()"), R"(vec3 writtenRefract(vec3 I, vec3 N, float eta)
{
  float d = dot(N, I);
  float k = 1.0 - eta * eta * (1.0 - d * d);
  vec3 R;
  if (k < 0.0)
    R = vec3(0.0);
  else
    R = eta * I - (eta * d + sqrt(max(k, 0.0))) * N;
  return R;
}

)");
  const DerivedListing& glassToAir = derivedListings()[5];
  ASSERT_EQ(glassToAir.label(), "cg_refraction_glass_to_air");
  const BoundListing bound = bindListing(glassToAir, makeScene("sphere"));
  const auto varyingsOf = [&](const std::string& text) {
    return derived::evaluateVaryings(
        derived::lowerShader({"user.vert", text, derived::Stage::Vertex}, {"T"}), bound.uniforms,
        bound.attributes, bound.count, PrecisionRules::Glsl)[0];
  };
  const OracleVarying reference = varyingsOf(builtin);
  const OracleVarying user = varyingsOf(written);
  std::size_t compared = 0, outside = 0, totalReflection = 0;
  for (std::size_t i = 0; i < reference.reference.size(); ++i) {
    if (reference.undefined[i] || user.undefined[i]) continue;
    ++compared;
    if (reference.reference[i] == 0.0) ++totalReflection;
    if (!(user.lo[i] <= reference.reference[i] && reference.reference[i] <= user.hi[i])) ++outside;
  }
  EXPECT_GT(compared, reference.reference.size() / 2);
  EXPECT_GT(totalReflection, 0u);  // both ways are taken somewhere
  EXPECT_EQ(outside, 0u);
}

// Directions across the critical angle of eta = 1.5, dense enough that
// refract()'s k < 0 (or the written-out if) cannot be decided at some:
// there each way is kept apart, whole (one choice per condition, not one
// per component), with its own exact value.
TEST(DerivedBranch, NearTheCriticalAngleTheTwoWaysAreKeptApart) {
  const std::string header = R"(#version 140
in vec3 I;
in vec3 N;
uniform float eta;
out vec3 R;
)";
  const std::string builtin = header + "void main() { R = refract(I, N, eta); }\n";
  const std::string written = header + R"(void main() {
  float d = dot(N, I);
  float k = 1.0 - eta * eta * (1.0 - d * d);
  if (k < 0.0)
    R = vec3(0.0);
  else
    R = eta * I - (eta * d + sqrt(max(k, 0.0))) * N;
}
)";
  const double critical = std::asin(1.0 / 1.5);
  AttributeMap inputs;
  inputs["I"] = AttributeStream{"I", 3, {}};
  inputs["N"] = AttributeStream{"N", 3, {}};
  const std::size_t count = 2001;
  for (std::size_t k = 0; k < count; ++k) {
    const double angle = critical + 2e-6 * (static_cast<double>(k) / (count - 1) - 0.5);
    inputs["I"].data.insert(inputs["I"].data.end(), {static_cast<float>(std::sin(angle)),
                                                     static_cast<float>(-std::cos(angle)), 0.0f});
    inputs["N"].data.insert(inputs["N"].data.end(), {0.0f, 1.0f, 0.0f});
  }
  const UniformMap uniforms{{"eta", Value{ValueType::Float, {1.5f}}}};
  for (const std::string& text : {builtin, written}) {
    const OracleVarying R =
        derived::evaluateVaryings(derived::lowerShader({"user.vert", text, derived::Stage::Vertex}),
                                  uniforms, inputs, count, PrecisionRules::Glsl)[0];
    ASSERT_GT(R.alternatives.size(), 0u) << text;
    for (const SampleAlternatives& sample : R.alternatives) {
      ASSERT_EQ(sample.ways.size(), 2u) << text;
      std::size_t zeroWays = 0;
      for (const OracleAlternative& way : sample.ways) {
        bool zero = true;
        for (std::size_t c = 0; c < 3; ++c) {
          zero = zero && way.lo[c] == 0.0 && way.hi[c] == 0.0;
          EXPECT_LE(way.lo[c], way.reference[c]);
          EXPECT_LE(way.reference[c], way.hi[c]);
          // The hull of the ways is the sample's range.
          EXPECT_LE(R.lo[sample.sample * 3 + c], way.lo[c]);
          EXPECT_GE(R.hi[sample.sample * 3 + c], way.hi[c]);
        }
        zeroWays += zero ? 1 : 0;
      }
      EXPECT_EQ(zeroWays, 1u) << text;  // total reflection one way, a ray the other
    }
  }
}

}  // namespace
}  // namespace snell::test
