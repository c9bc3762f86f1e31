// Which value the derived oracle computes for a requested name: outputs
// that share their name with a local or a struct member, 32-bit ints, and
// a capture on a line that a loop runs several times.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "derived/evaluate.h"
#include "derived/lower_glsl.h"
#include "oracle/interval.h"

namespace snell::test {
namespace {

std::vector<double> exactOutputs(const std::string& text, const std::vector<std::string>& names,
                                 derived::Stage stage = derived::Stage::Vertex) {
  const derived::Program program = derived::lowerShader({"user.vert", text, stage}, names);
  std::vector<double> values;
  for (const auto& output : derived::evaluateProgram<double>(program, {}, {}, 1))
    values.insert(values.end(), output.begin(), output.end());
  return values;
}

TEST(DerivedNames, AnOutputIsNotTakenOverByALocalOfItsName) {
  const std::vector<double> R = exactOutputs(R"(#version 330 core
out float R;
void main() {
  R = 1.5;
  {
    float R = 3.0;
    gl_Position = vec4(R);
  }
}
)",
                                             {"R"});
  EXPECT_EQ(R, std::vector<double>{1.5});
}

TEST(DerivedNames, AnOutputIsNotTakenOverByAStructMemberOfItsName) {
  const std::vector<double> R = exactOutputs(R"(#version 330 core
out float R;
struct Ray { float R; };
void main() {
  R = 1.5;
  Ray ray;
  ray.R = 3.0;
  gl_Position = vec4(ray.R);
}
)",
                                             {"R"});
  EXPECT_EQ(R, std::vector<double>{1.5});
}

// An out or inout parameter is the caller's variable after the call: the
// callee's value is copied out when it returns (GLSL 4.60 section 6.1.1),
// into a local or a pipeline output alike.
TEST(DerivedNames, AnOutParameterIsTheCallersVariableAfterTheCall) {
  const std::vector<double> values = exactOutputs(R"(#version 330 core
out float R;
out vec3 S;
void h(in float x, out float y) { y = x * 2.0; }
void g(inout vec3 v, out vec3 w) { v.y += 1.0; w = v * 2.0; }
void main() {
  float y;
  h(1.25, y);
  R = y;
  vec3 v = vec3(1.0, 2.0, 3.0);
  g(v, S);
  S += v;
  h(R, y);
  gl_Position = vec4(y);
}
)",
                                                  {"R", "S"});
  EXPECT_EQ(values, (std::vector<double>{2.5, 3.0, 9.0, 9.0}));
}

TEST(DerivedNames, IntsWrapToTheirLow32Bits) {
  const std::vector<double> values = exactOutputs(R"(#version 330 core
out float big;
out float u;
out float down;
void main() {
  int n = 65536;
  big = float(n * n);
  uint v = 0u;
  v -= 1u;
  u = float(v);
  int m = -2147483647;
  m--;
  m--;
  down = float(m);
}
)",
                                                  {"big", "u", "down"});
  // 2^32 wraps to 0; 0u - 1u is 4294967295u, and INT_MIN - 1 is INT_MAX (each
  // then the nearest float).
  EXPECT_EQ(values, (std::vector<double>{0.0, 4294967296.0, 2147483648.0}));
}

TEST(DerivedNames, ACaptureInsideALoopKeepsTheLastIterationsValue) {
  const std::string text = R"(#version 330 core
out vec4 FragColor;
void main()
{
    float R = 1.0;
    for (int k = 0; k < 3; k++) {
        R = R + 1.0;
        R = R * 2.0;
    }
    FragColor = vec4(R);
}
)";
  // After line 7 on each iteration: 2, then 4 + 1, then 10 + 1.
  const derived::Program program =
      derived::lowerOutputs({"user.frag", text, derived::Stage::Fragment}, {{"R", 7}});
  const auto values = derived::evaluateProgram<double>(program, {}, {}, 1);
  ASSERT_EQ(values.size(), 1u);
  EXPECT_EQ(values[0], std::vector<double>{11.0});
}

// A capture on the then way's last line, with an else: the then way's
// value, as the probe writes it there (not the value from before the if).
TEST(DerivedNames, ACaptureOnTheLastLineOfAThenWayIsThatWaysValue) {
  const std::string text = R"(#version 330 core
out vec4 FragColor;
void main() {
  float R = 1.0;
  if (R > 0.5) {
    R = 2.0;
  } else {
    R = 3.0;
  }
  FragColor = vec4(R);
}
)";
  const derived::Program program =
      derived::lowerOutputs({"user.frag", text, derived::Stage::Fragment}, {{"R", 6}});
  const auto values = derived::evaluateProgram<double>(program, {}, {}, 1);
  ASSERT_EQ(values.size(), 1u);
  EXPECT_EQ(values[0], std::vector<double>{2.0});
}

}  // namespace
}  // namespace snell::test
