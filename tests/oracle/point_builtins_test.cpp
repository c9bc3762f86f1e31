// reflect() and refract() on exact inputs take a shorter road to their
// bounds (oracle/point_builtins.h). It must give the general road's bits
// in every field of every answer, and answer most calls, or it is not
// worth its place.
#include "oracle/point_builtins.h"

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "oracle/builtin_probe.h"
#include "oracle/glsl/glsl.h"
#include "oracle/precision_rules.h"

namespace snell {
namespace {

constexpr PrecisionRules kRules[] = {PrecisionRules::Glsl, PrecisionRules::Vulkan};

std::uint64_t bitsOf(double x) { return std::bit_cast<std::uint64_t>(x); }

std::string describe(const BuiltinCall& call, PrecisionRules rules) {
  std::string text = call.fn + " " + std::string(precisionRulesName(rules)) + " I=(";
  for (float x : call.I) text += std::to_string(x) + " ";
  text += ") N=(";
  for (float x : call.N) text += std::to_string(x) + " ";
  return text + ") eta=" + std::to_string(call.eta);
}

template <class T>
void expectSameBits(const Components<T>& a, const Components<T>& b, const char* field,
                    const std::string& where) {
  ASSERT_EQ(a.size(), b.size()) << field << " " << where;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if constexpr (std::same_as<T, bool>) {
      EXPECT_EQ(a[k], b[k]) << field << "[" << k << "] " << where;
    } else {
      EXPECT_EQ(bitsOf(a[k]), bitsOf(b[k]))
          << field << "[" << k << "] " << a[k] << " vs " << b[k] << " " << where;
    }
  }
}

// Every field of the two answers, bit for bit (a -0 for a +0 is a difference).
void expectSameAnswer(const BuiltinResult& shortest, const BuiltinResult& general,
                      const std::string& where) {
  expectSameBits(shortest.value, general.value, "value", where);
  expectSameBits(shortest.strict, general.strict, "strict", where);
  expectSameBits(shortest.lo, general.lo, "lo", where);
  expectSameBits(shortest.hi, general.hi, "hi", where);
  expectSameBits(shortest.undefined, general.undefined, "undefined", where);
  ASSERT_EQ(shortest.ways.size(), general.ways.size()) << "ways " << where;
  for (std::size_t w = 0; w < shortest.ways.size(); ++w) {
    expectSameBits(shortest.ways[w].value, general.ways[w].value, "way value", where);
    expectSameBits(shortest.ways[w].lo, general.ways[w].lo, "way lo", where);
    expectSameBits(shortest.ways[w].hi, general.ways[w].hi, "way hi", where);
    expectSameBits(shortest.ways[w].undefined, general.ways[w].undefined, "way undefined", where);
  }
}

// The shorter road's answer in each of its builds (oracle/fma_build.h)
// against the general road's: the portable build everywhere, the FMA build
// where this CPU runs it.
void expectEachBuildGivesTheGeneralRoadsBits(const BuiltinCall& call, PrecisionRules rules) {
  const std::string where = describe(call, rules);
  const BuiltinResult general = evaluateBuiltin(call, rules, OracleRoad::General);
  expectSameAnswer(evaluateBuiltin(call, rules, OracleRoad::Shortest, OracleBuild::Portable),
                   general, where + " (portable build)");
  if (cpuHasFmaInstructions())
    expectSameAnswer(evaluateBuiltin(call, rules, OracleRoad::Shortest, OracleBuild::Fma), general,
                     where + " (FMA build)");
}

// Whether the shorter road answers the call (with the exact evaluation's
// branch, as evaluateBuiltin gives it).
bool shortRoadAnswers(const BuiltinCall& call, PrecisionRules rules) {
  if (call.fn == "reflect") {
    const UsePrecisionRules applied(rules);
    PointBounds out;
    return reflectOnPoints(call.I, call.N, rules, out);
  }
  const auto exactTir = [&]<int Size>() {
    glsl::vec<double, Size> I, N;
    for (int k = 0; k < Size; ++k) {
      I[k] = call.I[k];
      N[k] = call.N[k];
    }
    return glsl::refractK(static_cast<double>(call.eta), glsl::dot(N, I)) < 0.0;
  };
  bool tir = false;
  switch (call.I.size()) {
    case 2:
      tir = exactTir.template operator()<2>();
      break;
    case 3:
      tir = exactTir.template operator()<3>();
      break;
    case 4:
      tir = exactTir.template operator()<4>();
      break;
    default:
      return false;
  }
  const UsePrecisionRules applied(rules);
  PointRefract out;
  return refractOnPoints(call.I, call.N, call.eta, tir, rules, out);
}

// Unit normals in every direction, incident vectors against them (and a
// few along them), eta from 0.3 to 3: refraction, total internal
// reflection and the critical angle between them.
class RandomCalls {
 public:
  explicit RandomCalls(unsigned seed) : random_(seed) {}

  BuiltinCall next(const std::string& fn, std::size_t size) {
    BuiltinCall call;
    call.fn = fn;
    call.N = unit(size);
    call.I = unit(size);
    double along = 0.0;
    for (std::size_t k = 0; k < size; ++k) along += call.I[k] * call.N[k];
    if (along > 0.0 && coin_(random_) > 0.05)
      for (float& x : call.I) x = -x;
    if (fn == "refract") call.eta = eta_(random_);
    return call;
  }

 private:
  std::vector<float> unit(std::size_t size) {
    for (;;) {
      std::vector<float> v(size);
      double length = 0.0;
      for (float& x : v) {
        x = normal_(random_);
        length += static_cast<double>(x) * x;
      }
      length = std::sqrt(length);
      if (length < 1e-3) continue;
      for (float& x : v) x = static_cast<float>(x / length);
      return v;
    }
  }

  std::mt19937 random_;
  std::normal_distribution<float> normal_;
  std::uniform_real_distribution<float> eta_{0.3f, 3.0f};
  std::uniform_real_distribution<double> coin_{0.0, 1.0};
};

TEST(PointBuiltins, GiveTheGeneralRoadsBitsOnRandomCalls) {
  RandomCalls calls(20261129);
  for (const std::string fn : {"reflect", "refract"})
    for (PrecisionRules rules : kRules)
      for (std::size_t size = 2; size <= 4; ++size) {
        constexpr int kCalls = 6000;
        int answered = 0;
        for (int c = 0; c < kCalls; ++c) {
          const BuiltinCall call = calls.next(fn, size);
          expectEachBuildGivesTheGeneralRoadsBits(call, rules);
          if (shortRoadAnswers(call, rules)) ++answered;
          if (HasFailure()) return;
        }
        // Declining is always right; declining most calls would make the
        // road pointless (refract declines an undecidable branch: about 1%
        // here; reflect has none).
        const int least = fn == "reflect" ? kCalls : kCalls * 95 / 100;
        EXPECT_GE(answered, least) << fn << " " << precisionRulesName(rules) << " size " << size;
      }
}

// Zeros, powers of two, normal and grazing incidence, eta 1, tiny and
// large components, the critical angle, and inputs it must decline.
TEST(PointBuiltins, GiveTheGeneralRoadsBitsOnEdgeCalls) {
  const float tiny = 0x1p-60f;
  const float large = 0x1p15f;
  const float denormal = 0x1p-130f;
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float s = std::sqrt(1.0f - 0.6f * 0.6f);
  const std::vector<BuiltinCall> calls = {
      {"refract", {0.0f, -1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 0.66f},
      {"refract", {0.0f, -1.0f}, {0.0f, 1.0f}, 1.0f},
      {"refract", {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 0.66f},
      {"refract", {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 1.5f},
      {"refract", {0.6f, -0.8f, 0.0f}, {0.0f, 1.0f, 0.0f}, 0.66f},
      {"refract", {0.6f, -0.8f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f, 0.0f}, 1.0f / 0.8f},
      {"refract", {s, -0.6f, 0.0f}, {0.0f, 1.0f, 0.0f}, 1.0f / s},
      {"refract", {0.5f, -0.5f, 0.5f, -0.5f}, {0.5f, 0.5f, 0.5f, 0.5f}, 2.0f},
      {"refract", {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 0.66f},
      {"refract", {0.6f, -0.8f, 0.0f}, {0.0f, 0.0f, 0.0f}, 0.66f},
      {"refract", {0.6f, -0.8f, 0.0f}, {0.0f, 1.0f, 0.0f}, 0.0f},
      {"refract", {tiny, -tiny, 0.0f}, {0.0f, 1.0f, 0.0f}, 0.66f},
      {"refract", {0.6f, -0.8f, 0.0f}, {0.0f, tiny, 0.0f}, 0.66f},
      {"refract", {large, -large, 3.0f}, {0.0f, 1.0f, 0.0f}, 0.66f},
      {"refract", {0.6f, -0.8f, 0.0f}, {0.0f, 1.0f, 0.0f}, large},
      {"refract", {-0.0f, -1.0f, -0.0f}, {-0.0f, 1.0f, 0.0f}, 0.66f},
      // Declined: past 2^16, a denormal, an infinity, NaN, one component.
      {"refract", {0x1p17f, -1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 0.66f},
      {"refract", {denormal, -1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 0.66f},
      {"refract", {inf, -1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 0.66f},
      {"refract", {0.6f, -0.8f, 0.0f}, {0.0f, 1.0f, 0.0f}, nan},
      {"refract", {-1.0f}, {1.0f}, 0.66f},
  };
  for (PrecisionRules rules : kRules)
    for (BuiltinCall call : calls) {
      expectEachBuildGivesTheGeneralRoadsBits(call, rules);
      call.fn = "reflect";
      expectEachBuildGivesTheGeneralRoadsBits(call, rules);
    }
}

TEST(PointBuiltins, DeclineWhatTheyDoNotMirror) {
  const std::vector<float> I{0.6f, -0.8f, 0.0f};
  const std::vector<float> N{0.0f, 1.0f, 0.0f};
  for (PrecisionRules rules : kRules) {
    const UsePrecisionRules applied(rules);
    PointBounds bounds;
    ASSERT_TRUE(reflectOnPoints(I, N, rules, bounds)) << precisionRulesName(rules);
    EXPECT_FALSE(
        reflectOnPoints(std::vector<float>{-1.0f}, std::vector<float>{1.0f}, rules, bounds));
    EXPECT_FALSE(reflectOnPoints(std::vector<float>{0x1p17f, -0.8f, 0.0f}, N, rules, bounds));
    EXPECT_FALSE(reflectOnPoints(
        I, std::vector<float>{0.0f, std::numeric_limits<float>::quiet_NaN(), 0.0f}, rules, bounds));
    EXPECT_FALSE(reflectOnPoints(I, std::vector<float>{0.0f, 1.0f}, rules, bounds));
    PointRefract out;
    ASSERT_TRUE(refractOnPoints(I, N, 0.66f, false, rules, out)) << precisionRulesName(rules);
    // The exact evaluation's branch against the intervals' decided one.
    EXPECT_FALSE(refractOnPoints(I, N, 0.66f, true, rules, out));
    EXPECT_FALSE(refractOnPoints(std::vector<float>{-1.0f}, std::vector<float>{1.0f}, 0.66f, false,
                                 rules, out));
    EXPECT_FALSE(refractOnPoints(I, N, std::numeric_limits<float>::quiet_NaN(), false, rules, out));
    EXPECT_FALSE(refractOnPoints(I, N, std::numeric_limits<float>::infinity(), false, rules, out));
    EXPECT_FALSE(refractOnPoints(I, N, 0x1p17f, false, rules, out));
    EXPECT_FALSE(
        refractOnPoints(std::vector<float>{0x1p-130f, -0.8f, 0.0f}, N, 0.66f, false, rules, out));
    // At the critical angle the branch is undecidable: two ways, the
    // general road's business.
    const float d = -0.6f;
    const float s = std::sqrt(1.0f - d * d);
    EXPECT_FALSE(refractOnPoints(std::vector<float>{s, d, 0.0f}, N, 1.0f / s, false, rules, out));
    EXPECT_FALSE(refractOnPoints(std::vector<float>{s, d, 0.0f}, N, 1.0f / s, true, rules, out));
  }
}

// This machine's CPU and the build its calls take. (Where it has no FMA
// instructions, the tests above hold the portable build alone.)
TEST(PointBuiltins, TheFmaBuildRunsWhereTheCpuHasIt) {
  RecordProperty("cpu_has_fma", cpuHasFmaInstructions() ? "yes" : "no");
  EXPECT_EQ(fastestOracleBuild(),
            cpuHasFmaInstructions() ? OracleBuild::Fma : OracleBuild::Portable);
  if (!cpuHasFmaInstructions()) GTEST_SKIP() << "this CPU has no FMA instructions";
}

// The comparison above sees a bound one float away.
TEST(PointBuiltins, TheComparisonSeesOneFloatOfDifference) {
  const BuiltinCall call{"refract", {0.6f, -0.8f, 0.0f}, {0.0f, 1.0f, 0.0f}, 0.66f};
  const BuiltinResult general = evaluateBuiltin(call, PrecisionRules::Glsl, OracleRoad::General);
  BuiltinResult moved = general;
  moved.ways[0].hi[1] = std::nextafter(static_cast<float>(moved.ways[0].hi[1]),
                                       std::numeric_limits<float>::infinity());
  EXPECT_NONFATAL_FAILURE(expectSameAnswer(moved, general, "moved"), "way hi[1]");
  BuiltinResult signedZero = general;
  ASSERT_EQ(general.strict[2], 0.0f);
  signedZero.strict[2] = -signedZero.strict[2];
  EXPECT_NONFATAL_FAILURE(expectSameAnswer(signedZero, general, "signed zero"), "strict[2]");
}

}  // namespace
}  // namespace snell
