// Literals in a user's shader: an expression of literals only is held as
// the expression (a driver may fold it in double or evaluate it in fp32,
// GLSL 4.60 section 4.3.3), not as glslang's folded number.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "derived/evaluate.h"
#include "derived/literal_names.h"
#include "derived/lower_glsl.h"
#include "oracle/interval.h"

namespace snell::test {
namespace {

std::vector<Interval> allowedOutputs(const std::string& text,
                                     const std::vector<std::string>& names = {}) {
  const derived::Program program = derived::lowerShader({"user.vert", text}, names);
  std::vector<Interval> outputs;
  for (const auto& output : derived::evaluateProgram<Interval>(program, {}, {}, 1))
    outputs.push_back(output[0]);
  return outputs;
}

TEST(DerivedLiteral, AnExpressionOfLiteralsMayBeEvaluatedAtRunTime) {
  const std::vector<Interval> allowed = allowedOutputs(R"(#version 330 core
out float folded;
out float third;
void main() {
  folded = 1e-8 + 1.0 - 1.0;
  third = 1.0 / 3.0;
}
)");
  ASSERT_EQ(allowed.size(), 2u);
  // Folded in double: 1e-8, the nearest float or its neighbour.
  EXPECT_TRUE(contains(allowed[0], 1e-8f));
  // In fp32 at run time: 1e-8 + 1.0 rounds to 1.0 (or the float above it).
  EXPECT_TRUE(contains(allowed[0], 0.0f));
  EXPECT_TRUE(contains(allowed[0], 0x1p-23f));
  // 1 / 3 within its 2.5 ULP, not only the nearest float.
  const float nearest = 1.0f / 3.0f;
  EXPECT_TRUE(contains(allowed[1], std::nextafter(nearest, 1.0f)));
  EXPECT_TRUE(contains(allowed[1], std::nextafter(std::nextafter(nearest, 0.0f), 0.0f)));
  EXPECT_FALSE(contains(allowed[1], 0.3f));
}

TEST(DerivedLiteral, ALiteralOnAFloatMidpointMayParseEitherWay) {
  const std::vector<Interval> allowed = allowedOutputs(R"(#version 330 core
out float x;
void main() { x = 1.00000005960464477539062500001; }
)");
  ASSERT_EQ(allowed.size(), 1u);
  EXPECT_TRUE(contains(allowed[0], 1.0f));
  EXPECT_TRUE(contains(allowed[0], 0x1.000002p0f));
}

TEST(DerivedLiteral, TheRenamedTextKeepsLinesCommentsAndWhatIsNotAFloat) {
  const std::string text = R"(#version 330 core
#define SCALE 2.5
// 1.0 in a comment
/* 3.0 */ out vec3 R;
void main() {
  R = vec3(SCALE * 0.5f, 2e3, 1.0lf) + vec3(float(3), .5, 0x1F);
}
)";
  const derived::NamedLiterals named = derived::withLiteralsNamed(text);
  EXPECT_EQ(std::count(named.text.begin(), named.text.end(), '\n'),
            std::count(text.begin(), text.end(), '\n'));
  std::vector<double> values;
  for (const auto& [name, value] : named.values) values.push_back(value);
  std::sort(values.begin(), values.end());
  EXPECT_EQ(values, (std::vector<double>{0.5, 0.5, 2.5, 2e3}));
  EXPECT_NE(named.text.find("// 1.0 in a comment"), std::string::npos);
  EXPECT_NE(named.text.find("/* 3.0 */ uniform float "), std::string::npos);
  EXPECT_NE(named.text.find("1.0lf"), std::string::npos);
  EXPECT_NE(named.text.find("float(3)"), std::string::npos);
  EXPECT_NE(named.text.find("0x1F"), std::string::npos);
  EXPECT_EQ(named.text.find("2.5"), std::string::npos);
}

TEST(DerivedLiteral, TheDeclarationsGoOutsideAnyConditionalBlock) {
  const std::string text = R"(#version 330 core
#ifdef GL_ES
precision highp float;
#endif
out float t;
void main() { t = 2.0 * 0.5; }
)";
  const derived::NamedLiterals named = derived::withLiteralsNamed(text);
  EXPECT_NE(named.text.find("precision highp float;\n#endif\nuniform float "), std::string::npos)
      << named.text;
  const std::vector<Interval> allowed = allowedOutputs(text);
  ASSERT_EQ(allowed.size(), 1u);
  EXPECT_TRUE(contains(allowed[0], 1.0f));
}

// An operation outside the subset on literals alone, or a literal where an
// int must be known: the text as written, as glslang folds it, as before
// literals were named.
TEST(DerivedLiteral, WhatTheNamedTextCannotLowerIsLoweredAsWritten) {
  const std::vector<Interval> allowed = allowedOutputs(R"(#version 330 core
out float t;
void main() {
  t = 0.0;
  for (int i = 0; i < int(4.0); ++i) t = t + acos(-1.0);
}
)");
  ASSERT_EQ(allowed.size(), 1u);
  EXPECT_TRUE(contains(allowed[0], 4.0f * 3.14159274f));
}

TEST(DerivedLiteral, GlslEsGlobalsKeepTheirConstantInitializers) {
  // GLSL ES allows only constant initializers for globals.
  const std::string text = R"(#version 300 es
precision highp float;
float Eta = 0.66;
out vec3 R;
void main() { R = vec3(Eta * 2.0); gl_Position = vec4(0.0); }
)";
  const derived::NamedLiterals named = derived::withLiteralsNamed(text);
  EXPECT_NE(named.text.find("float Eta = 0.66;"), std::string::npos);
  ASSERT_EQ(named.values.size(), 2u);  // 2.0 and 0.0 in main()
  const std::vector<Interval> allowed = allowedOutputs(text, {"R"});
  ASSERT_FALSE(allowed.empty());
  EXPECT_TRUE(contains(allowed[0], 0.66f * 2.0f));
}

}  // namespace
}  // namespace snell::test
