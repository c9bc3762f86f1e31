// The GLSL types and the remaining built-ins behave as GLSL defines them, in
// every number type.
#include <gtest/gtest.h>

#include "oracle/glsl/glsl.h"

namespace snell {
namespace {

using namespace glsl;

template <class T>
mat4<T> translationBy(T x, T y, T z) {
  mat4<T> m;
  for (int k = 0; k < 4; ++k) m[k][k] = lit<T>(1.0);
  m[3] = vec4<T>(x, y, z, lit<T>(1.0));  // column 3: GLSL is column-major
  return m;
}

TEST(OracleGlslTypes, MatrixTimesVectorIsColumnMajor) {
  const vec4<double> moved =
      translationBy(1.0, 2.0, 3.0) * vec4<double>(vec3<double>(10.0, 20.0, 30.0), 1.0);
  EXPECT_EQ(moved.xyz()[0], 11.0);
  EXPECT_EQ(moved.xyz()[1], 22.0);
  EXPECT_EQ(moved.xyz()[2], 33.0);
  EXPECT_EQ(moved.w(), 1.0);
  // A direction (w = 0) is not translated.
  const vec4<float> direction =
      translationBy(1.0f, 2.0f, 3.0f) * vec4<float>(1.0f, 0.0f, 0.0f, 0.0f);
  EXPECT_EQ(vec3<float>(direction)[0], 1.0f);
  EXPECT_EQ(vec3<float>(direction)[1], 0.0f);
}

TEST(OracleGlslTypes, Mat3RowsAndColumns) {
  mat3<double> m;
  m[0] = vec3<double>(1.0, 2.0, 3.0);  // first column
  m[1] = vec3<double>(4.0, 5.0, 6.0);
  m[2] = vec3<double>(7.0, 8.0, 9.0);
  const vec3<double> r = m * vec3<double>(1.0, 0.0, -1.0);
  EXPECT_EQ(r[0], -6.0);
  EXPECT_EQ(r[1], -6.0);
  EXPECT_EQ(r[2], -6.0);
  const vec3<double> s = m * vec3<double>(0.0, 1.0, 0.0);
  EXPECT_EQ(s[2], 6.0);
}

TEST(OracleGlslTypes, LengthAndNormalize) {
  const vec3<double> v(3.0, 0.0, 4.0);
  EXPECT_EQ(length(v), 5.0);
  EXPECT_DOUBLE_EQ(normalize(v)[2], 0.8);
  const Interval allowed =
      length(vec3<Interval>(lit<Interval>(3.0), lit<Interval>(0.0), lit<Interval>(4.0)));
  EXPECT_TRUE(contains(allowed, 5.0f));
  EXPECT_LT(width(allowed), 1e-5);
  const vec3<Interval> unit =
      normalize(vec3<Interval>(lit<Interval>(3.0), lit<Interval>(0.0), lit<Interval>(4.0)));
  EXPECT_TRUE(contains(unit[0], 0.6f));
  EXPECT_TRUE(contains(unit[2], 0.8f));
}

TEST(OracleGlslTypes, MixIsLinearBlend) {
  EXPECT_EQ(mix(2.0, 6.0, 0.25), 3.0);
  EXPECT_EQ(mix(2.0f, 6.0f, 1.0f), 6.0f);
  const vec2<double> blended = mix(vec2<double>(0.0, 10.0), vec2<double>(4.0, 20.0), 0.5);
  EXPECT_EQ(blended[0], 2.0);
  EXPECT_EQ(blended[1], 15.0);
  const Interval third = mix(lit<Interval>(0.0), lit<Interval>(3.0), lit<Interval>(1.0 / 3.0));
  EXPECT_TRUE(contains(third, 1.0f));
  EXPECT_LT(width(third), 1e-6);
}

TEST(OracleGlslTypes, LiteralsAreTheNearestFloat) {
  EXPECT_EQ(lit<double>(0.66), static_cast<double>(0.66f));
  EXPECT_NE(lit<double>(0.66), 0.66);
  const Interval point = lit<Interval>(0.66);
  EXPECT_EQ(point.lo, static_cast<double>(0.66f));
  EXPECT_EQ(point.hi, static_cast<double>(0.66f));
}

TEST(OracleGlslTypes, ScalarBuiltinsInEveryType) {
  EXPECT_EQ(inversesqrt(4.0), 0.5);
  EXPECT_EQ(inversesqrt(4.0f), 0.5f);
  EXPECT_TRUE(contains(inversesqrt(lit<Interval>(4.0)), 0.5f));
  EXPECT_EQ(exp2(3.0), 8.0);
  EXPECT_TRUE(contains(exp2(lit<Interval>(3.0)), 8.0f));
  EXPECT_EQ(log2(8.0f), 3.0f);
  EXPECT_TRUE(contains(log2(lit<Interval>(8.0)), 3.0f));
  EXPECT_EQ(pow(2.0, 5.0), 32.0);
  EXPECT_TRUE(contains(pow(lit<Interval>(2.0), lit<Interval>(5.0)), 32.0f));
  EXPECT_EQ(max(-1.0, 0.0), 0.0);
}

}  // namespace
}  // namespace snell
