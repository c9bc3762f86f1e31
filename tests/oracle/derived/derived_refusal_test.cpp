// What the derived oracle's front end refuses, and how: one UsageError
// naming the construct and FILE:LINE.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "core/errors.h"
#include "derived_listings.h"

namespace snell::test {
namespace {

std::string refusalOf(const std::string& text, derived::Stage stage = derived::Stage::Vertex,
                      const std::vector<std::string>& outputs = {}) {
  try {
    derived::lowerShader({"user.vert", text, stage}, outputs);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

bool mentions(const std::string& message, const std::string& part) {
  return message.find(part) != std::string::npos;
}

TEST(DerivedRefusal, AWhileLoopIsRefusedWithItsLine) {
  const std::string message = refusalOf(R"(#version 140
in vec4 position;
out float t;
void main() {
  t = 0.0;
  while (t < 1.0)
    t = t + 0.25;
  gl_Position = position;
}
)");
  EXPECT_TRUE(mentions(message, "user.vert:6: a while loop")) << message;
  EXPECT_TRUE(mentions(message, "`while (t < 1.0)`")) << message;  // the line as written
}

TEST(DerivedRefusal, ALoopWithoutAConstantBoundAndAnEarlyReturnAreRefusedWithTheirLines) {
  const std::string message = refusalOf(R"(#version 140
uniform int n;
out float t;
void main() {
  t = 0.0;
  for (int k = 0; k < n; ++k) t += 1.0;
}
)");
  EXPECT_TRUE(mentions(message, "user.vert:6: the int n, whose value is not known")) << message;
  EXPECT_TRUE(mentions(refusalOf(R"(#version 140
in vec4 position;
out float t;
float f(float x) {
  if (x > 0.0)
    return 1.0;
  return 2.0;
}
void main() {
  t = f(position.x);
}
)"),
                       "user.vert:6: a return before the end of f()"));
}

// An output written on one way of an if only: main() leaves it unset on
// the other. It was an internal error ("map::at") with no file or line.
TEST(DerivedRefusal, AnOutputAssignedOnOneWayOfAnIfOnlyIsRefusedWithTheIfsLine) {
  for (const char* ways : {"if (position.x < 0.5)\n    t = 1.0;",
                           "if (position.x < 0.5) {\n  } else {\n    t = 1.0;\n  }"}) {
    const std::string message = refusalOf(std::string(R"(#version 140
in vec4 position;
out float t;
void main() {
  )") + ways + R"(
  gl_Position = position;
}
)",
                                          derived::Stage::Vertex, {"t"});
    EXPECT_TRUE(mentions(message, "user.vert:5: 't' is assigned on one way of this if only"))
        << message;
  }
}

TEST(DerivedRefusal, ATextureLookupInTheVertexStageIsRefusedWithItsLine) {
  const std::string message = refusalOf(R"(#version 140
in vec4 position;
uniform samplerCube environment;
out vec4 colour;
void main() {
  vec3 direction = normalize(position.xyz);
  colour = texture(environment, direction);
  gl_Position = position;
}
)");
  EXPECT_TRUE(mentions(message, "user.vert:7: a texture lookup")) << message;
  EXPECT_TRUE(mentions(message, "needed for 'colour'")) << message;
}

// A lookup that no requested value depends on is no obstacle: CS 381's
// fragment captures its vectors before the cube map lookup.
TEST(DerivedRefusal, ALookupAfterTheCapturedValuesIsNoObstacle) {
  const derived::Program program =
      derived::lowerShader({"refraction.frag", readListing("cs381/refraction/refraction.frag"),
                            derived::Stage::Fragment},
                           {"viewdir", "refractview"});
  ASSERT_EQ(program.outputs.size(), 2u);
  EXPECT_EQ(program.inputs.size(), 2u);   // myvert, mynorm
  EXPECT_TRUE(program.uniforms.empty());  // the sampler is not read
}

// Legacy state comes from the state table; a built-in outside it does not.
TEST(DerivedRefusal, ABuiltInOutsideTheStateTableIsRefusedWithItsLine) {
  const std::string message = refusalOf(R"(#version 120
void main() {
  vec2 p = gl_FragCoord.xy;
  gl_FragColor = vec4(p, 0.0, 1.0);
}
)",
                                        derived::Stage::Fragment, {"p"});
  EXPECT_TRUE(mentions(message, "user.vert:3: the built-in gl_FragCoord")) << message;
}

TEST(DerivedRefusal, AnOutputTheShaderDoesNotComputeIsNamed) {
  const std::string message = refusalOf(readListing("orange-book/14.1-fresnel/fresnel.vert"),
                                        derived::Stage::Vertex, {"Refracted"});
  EXPECT_TRUE(mentions(message, "'Refracted'")) << message;
}

TEST(DerivedRefusal, ASyntaxErrorIsReportedWithGlslangsMessage) {
  const std::string message = refusalOf("#version 140\nvoid main() { float x = ; }\n");
  EXPECT_TRUE(mentions(message, "user.vert: glslang cannot compile")) << message;
}

// An out parameter the callee leaves unset has no value after the call;
// a uniform struct member is one snell cannot set. Each is said as such,
// not as a variable read before it is assigned.
TEST(DerivedRefusal, AnOutParameterLeftUnsetIsNamed) {
  const std::string message = refusalOf(R"(#version 330 core
uniform float a;
out float t;
void h(in float x, out float y) { float z = x; }
void main() {
  float y;
  h(a, y);
  t = y;
}
)");
  EXPECT_TRUE(mentions(message, "user.vert:7: h() may leave its out parameter y unset")) << message;
}

TEST(DerivedRefusal, AUniformStructMemberIsNamed) {
  const std::string message = refusalOf(R"(#version 330 core
uniform float a;
struct Light { float k; };
uniform Light L;
out float t;
void main() {
  t = L.k * a;
}
)");
  EXPECT_TRUE(mentions(message, "user.vert:7: the uniform struct member L.k")) << message;
}

// A function with a return before its end is refused where its value is
// needed; so are its out arguments, which it may have set on either way
// (they kept their value from before the call).
TEST(DerivedRefusal, TheOutArgumentsOfAnEarlyReturningCallAreRefused) {
  const std::string message = refusalOf(R"(#version 330 core
uniform float eta;
out float t;
float h(in float x, out float y) { if (x > 0.5) { y = 1.0; return 3.0; } y = 2.0; return 4.0; }
void main() {
  float y = 5.0;
  float r = h(eta, y);
  t = y;
}
)",
                                        derived::Stage::Vertex, {"t"});
  EXPECT_TRUE(mentions(message, "a return before the end of h()")) << message;
}

// GLSL evaluates only the chosen operand of ?:, so an out argument or an
// assignment in an operand happens on one way only: refused, where the
// lowering took both; a function called there keeps its own variables.
TEST(DerivedRefusal, AnOutArgumentOrAnAssignmentInsideASelectionIsRefused) {
  const std::string call = refusalOf(R"(#version 330 core
uniform float eta;
out float t;
float h(in float x, out float y) { y = x * 2.0; return 1.0; }
void main() {
  float y = 5.0;
  float r = (eta > 0.5) ? 0.0 : h(eta, y);
  t = y + r;
}
)");
  EXPECT_TRUE(mentions(call, "user.vert:7: a call of h() with an out parameter inside ?:")) << call;
  const std::string assigned = refusalOf(R"(#version 330 core
uniform float eta;
out float t;
void main() {
  float y = 5.0;
  float r = (eta > 0.5) ? (y = 1.0) : 2.0;
  t = y + r;
}
)");
  EXPECT_TRUE(mentions(assigned, "user.vert:6: an assignment inside ?:")) << assigned;
  EXPECT_EQ(refusalOf(R"(#version 330 core
uniform float eta;
out float t;
float twice(in float x) { float y = x; y *= 2.0; return y; }
void main() {
  t = (eta > 0.5) ? twice(eta) : 2.0;
}
)"),
            "");
}

TEST(DerivedRefusal, AUniformBlockMemberIsNamedAsOne) {
  const std::string anonymous = refusalOf(R"(#version 330 core
uniform Params { float eta; };
out float t;
void main() {
  t = eta * 2.0;
}
)");
  EXPECT_TRUE(mentions(anonymous, "user.vert:5: the uniform block member eta (")) << anonymous;
  EXPECT_FALSE(mentions(anonymous, "anon@")) << anonymous;
}

// An unsupported built-in is named, so that a line calling two says which.
TEST(DerivedRefusal, AnUnsupportedBuiltInIsNamed) {
  const std::string message = refusalOf(R"(#version 330 core
uniform float a;
out float t;
void main() {
  t = dot(vec2(a), vec2(a)) + floor(a);
}
)");
  EXPECT_TRUE(mentions(message, "user.vert:5: floor()")) << message;
  // Columns are the parsed text's, where each literal has a longer name.
  const std::string afterLiterals = refusalOf(R"(#version 330 core
uniform float a;
out float t;
void main() {
  t = 2.0 * 0.5 * fract(a) + 1.0;
}
)");
  EXPECT_TRUE(mentions(afterLiterals, "user.vert:5: fract()")) << afterLiterals;
}

// A read-back value fed in on every iteration of a loop has no single
// value the oracle could hold the iterations to.
TEST(DerivedRefusal, AFedCaptureInsideALoopIsRefused) {
  const std::string loop = R"(#version 330 core
out vec4 FragColor;
void main() {
  vec2 acc = vec2(0.0);
  for (int k = 0; k < 2; k++) {
    vec2 p = gl_FragCoord.xy * float(k + 1);
    acc = acc + p;
  }
  FragColor = vec4(acc, 0.0, 1.0);
}
)";
  try {
    derived::lowerOutputs({"user.frag", loop, derived::Stage::Fragment}, {{"p", 6}});
    FAIL() << "a fed capture inside a loop was lowered";
  } catch (const UsageError& e) {
    EXPECT_TRUE(mentions(e.what(), "inside a loop")) << e.what();
  }
}

// A bool uniform, which snell cannot set: refused where it is read (the
// program had a register without values for it, and crashed evaluating).
TEST(DerivedRefusal, ABoolUniformIsRefusedWithItsLine) {
  const std::string message = refusalOf(R"(#version 330 core
uniform bool flip;
out float t;
void main() {
  t = 1.0;
  if (flip) t = 2.0;
}
)");
  EXPECT_TRUE(mentions(message, "user.vert:6: the bool uniform flip")) << message;
}

// Swizzles and constructors cost no operation: they only pick registers.
TEST(DerivedLowering, SwizzlesAndConstructorsEmitNoOperations) {
  const derived::Program program = derived::lowerShader({"user.vert", R"(#version 140
in vec4 position;
out vec3 v;
void main() {
  vec4 p = vec4(position.zyx, position.w);
  v = p.xyz;
}
)"});
  for (const derived::Op& op : program.ops)
    EXPECT_EQ(op.code, derived::OpCode::Input) << derived::opCodeName(op.code);
  ASSERT_EQ(program.outputs.size(), 1u);
  EXPECT_EQ(program.outputs[0].components.size(), 3u);
}

}  // namespace
}  // namespace snell::test

namespace snell::test {
namespace {

// Every shader of the catalog, each stage with every output it writes,
// either lowers or is refused with a located message: never a crash, never
// another kind of error.
TEST(DerivedRefusal, EveryCatalogShaderLowersOrIsRefusedWithItsFile) {
  namespace fs = std::filesystem;
  std::size_t lowered = 0, refused = 0;
  for (const fs::directory_entry& entry :
       fs::recursive_directory_iterator(fs::path(SNELL_SOURCE_ROOT) / "shaders")) {
    const std::string extension = entry.path().extension().string();
    if (extension != ".vert" && extension != ".frag") continue;
    const std::string relative =
        fs::relative(entry.path(), fs::path(SNELL_SOURCE_ROOT) / "shaders").string();
    const derived::Stage stage =
        extension == ".vert" ? derived::Stage::Vertex : derived::Stage::Fragment;
    try {
      derived::lowerShader({relative, readListing(relative), stage});
      ++lowered;
    } catch (const UsageError& e) {
      ++refused;
      std::printf("[ refused  ] %s\n", e.what());
      EXPECT_TRUE(mentions(e.what(), relative + ":")) << e.what();
    }
  }
  std::printf("[ catalog  ] %zu shader stages lowered whole, %zu refused\n", lowered, refused);
  EXPECT_GE(lowered, 13u);  // every vertex stage of the cross-check, at least
}

}  // namespace
}  // namespace snell::test
