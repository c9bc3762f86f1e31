// evaluateBuiltin: single reflect/refract calls of 1 to 4 components, as
// `snell eval` makes them.
#include "oracle/builtin_probe.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/errors.h"

namespace snell {
namespace {

void expectConsistent(const BuiltinResult& r, std::size_t size) {
  ASSERT_EQ(r.value.size(), size);
  ASSERT_EQ(r.strict.size(), size);
  ASSERT_EQ(r.lo.size(), size);
  ASSERT_EQ(r.hi.size(), size);
  for (std::size_t k = 0; k < size; ++k) {
    EXPECT_LE(r.lo[k], r.value[k]);
    EXPECT_LE(r.value[k], r.hi[k]);
    EXPECT_LE(r.lo[k], r.strict[k]);
    EXPECT_LE(r.strict[k], r.hi[k]);
  }
}

TEST(OracleBuiltinProbe, ReflectsInOneToFourComponents) {
  // A ray heading down and to the right off a floor: the vertical flips.
  const BuiltinResult one = evaluateBuiltin({"reflect", {-1.0f}, {1.0f}, 1.0f});
  expectConsistent(one, 1);
  EXPECT_EQ(one.value[0], 1.0);
  const BuiltinResult two = evaluateBuiltin({"reflect", {0.6f, -0.8f}, {0.0f, 1.0f}, 1.0f});
  expectConsistent(two, 2);
  EXPECT_NEAR(two.value[0], 0.6, 1e-7);
  EXPECT_NEAR(two.value[1], 0.8, 1e-7);
  const BuiltinResult three =
      evaluateBuiltin({"reflect", {0.6f, -0.8f, 0.0f}, {0.0f, 1.0f, 0.0f}, 1.0f});
  expectConsistent(three, 3);
  EXPECT_NEAR(three.value[1], 0.8, 1e-7);
  const BuiltinResult four =
      evaluateBuiltin({"reflect", {0.0f, 0.6f, -0.8f, 0.0f}, {0.0f, 0.0f, 1.0f, 0.0f}, 1.0f});
  expectConsistent(four, 4);
  EXPECT_NEAR(four.value[2], 0.8, 1e-7);
}

TEST(OracleBuiltinProbe, RefractFollowsSnellsLawIn2d) {
  const float s = 0.6f;  // sin(theta_i)
  const float eta = 0.66f;
  const BuiltinResult r = evaluateBuiltin({"refract", {s, -0.8f}, {0.0f, 1.0f}, eta});
  expectConsistent(r, 2);
  const double sinT = double(eta) * s;
  EXPECT_NEAR(r.value[0], sinT, 1e-7);
  EXPECT_NEAR(r.value[1], -std::sqrt(1.0 - sinT * sinT), 1e-7);
  EXPECT_LT(r.hi[0] - r.lo[0], 1e-5);  // a real bound, not the whole line
}

TEST(OracleBuiltinProbe, RefractPastTheCriticalAngleIsZero) {
  const BuiltinResult r =
      evaluateBuiltin({"refract", {0.8f, -0.6f, 0.0f}, {0.0f, 1.0f, 0.0f}, 1.5f});
  expectConsistent(r, 3);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(r.value[k], 0.0);
    EXPECT_EQ(r.strict[k], 0.0f);
    EXPECT_EQ(r.lo[k], 0.0);
    EXPECT_EQ(r.hi[k], 0.0);
  }
}

TEST(OracleBuiltinProbe, RejectsUnknownFunctionsAndBadLengths) {
  EXPECT_THROW(evaluateBuiltin({"refraction", {1.0f}, {1.0f}, 1.0f}), UsageError);
  EXPECT_THROW(evaluateBuiltin({"reflect", {1.0f, 0.0f}, {1.0f}, 1.0f}), UsageError);
  EXPECT_THROW(evaluateBuiltin({"reflect", {}, {}, 1.0f}), UsageError);
  EXPECT_THROW(evaluateBuiltin({"refract", {1, 0, 0, 0, 0}, {1, 0, 0, 0, 0}, 1.0f}), UsageError);
  try {
    evaluateBuiltin({"normalize", {1.0f}, {1.0f}, 1.0f});
    FAIL() << "no UsageError";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("normalize"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace snell
