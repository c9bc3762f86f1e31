#include "core/glsl_declarations.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace snell {
namespace {

std::string listing141() {
  std::ifstream in(SNELL_SOURCE_ROOT "/shaders/orange-book/14.1-fresnel/fresnel.vert");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(GlslDeclarations, ReadsListing141) {
  const auto d = readGlobalDeclarations(listing141());
  std::vector<std::string> seen;
  for (const auto& x : d) seen.push_back(x.qualifier + " " + x.type + " " + x.name);
  const std::vector<std::string> expected = {
      "in vec4 MCvertex",          "in vec3 MCnormal",          "uniform mat4 MVMatrix",
      "uniform mat4 MVPMatrix",    "uniform mat3 NormalMatrix", "uniform mat4 TextureMatrix",
      "out vec3 Reflect",          "out vec3 Refract",          "out float Ratio"};
  EXPECT_EQ(seen, expected);
  EXPECT_EQ(d[0].line, 3);
}

TEST(GlslDeclarations, SkipsCommentsFunctionsAndLocals) {
  const auto d = readGlobalDeclarations(
      "#version 140\n"
      "// uniform mat4 Commented;\n"
      "/* uniform mat4 Block;\n uniform vec3 More; */\n"
      "layout(location = 0) in vec4 A, B;\n"
      "flat out float C[2];\n"
      "const float K = (1.0 - 0.5) * 2.0;\n"
      "float helper(vec3 x) { uniform_like(); return 0.0; }\n"
      "uniform samplerCube Env;\n"
      "void main() { vec3 inner = vec3(0.0); }\n");
  std::vector<std::string> seen;
  for (const auto& x : d) seen.push_back(x.qualifier + " " + x.type + " " + x.name);
  EXPECT_EQ(seen, (std::vector<std::string>{"in vec4 A", "in vec4 B", "out float C",
                                            "uniform samplerCube Env"}));
}

}  // namespace
}  // namespace snell
