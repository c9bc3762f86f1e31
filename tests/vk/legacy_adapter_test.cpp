// The Vulkan legacy adapter as text: each mapping, identifier boundaries,
// declarations only for what is used, published lines at their numbers,
// probe lines passed through.
#include "backends/vk/legacy_adapter.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace snell {
namespace {

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::string readShader(const std::string& relative) {
  std::ifstream in(SNELL_SOURCE_ROOT "/shaders/" + relative);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The adapted text as the compiler numbers it: `#line N` (GLSL below 3.30)
// numbers the next line N + 1. Index k holds line k (index 0 unused); lines
// before the directive are the prologue, not numbered here.
std::vector<std::string> numberedLines(const std::string& adapted) {
  const std::vector<std::string> all = lines(adapted);
  std::vector<std::string> numbered{""};
  std::size_t first = 0;
  int next = 1;
  for (std::size_t k = 0; k < all.size(); ++k)
    if (all[k].rfind("#line ", 0) == 0) {
      first = k + 1;
      next = std::stoi(all[k].substr(6)) + 1;
    }
  if (first == 0) return {};  // no directive: not expected from the adapter
  numbered.resize(static_cast<std::size_t>(next));
  for (std::size_t k = first; k < all.size(); ++k) numbered.push_back(all[k]);
  return numbered;
}

std::string vertexText(const std::string& source) {
  return adaptLegacyForVulkan(source, LegacyStage::Vertex).text;
}
std::string fragmentText(const std::string& source) {
  return adaptLegacyForVulkan(source, LegacyStage::Fragment).text;
}

bool has(const std::string& text, const std::string& piece) {
  return text.find(piece) != std::string::npos;
}

TEST(LegacyAdapter, SourceWithoutVersionGetsVersion140BeforeItsFirstLine) {
  const std::string text = vertexText("void main() { gl_Position = vec4(0.0); }\n");
  EXPECT_EQ(lines(text).front(), "#version 140");
  const std::vector<std::string> numbered = numberedLines(text);
  ASSERT_EQ(numbered.size(), 2u) << text;
  EXPECT_EQ(numbered[1], "void main() { gl_Position = vec4(0.0); }");
}

TEST(LegacyAdapter, VersionLineIsReplacedInPlace) {
  const std::string text = vertexText("#version 120\nvoid main() {}\n");
  EXPECT_EQ(text, "#version 140\nvoid main() {}\n");
  // A #version later than comments stays on its line too.
  EXPECT_EQ(vertexText("// legacy\n#  version 110\nvoid main() {}\n"),
            "// legacy\n#version 140\nvoid main() {}\n");
}

TEST(LegacyAdapter, DeclarationsAfterAVersionLineKeepTheNumbering) {
  const std::string source = "#version 110\n\nvoid main() { gl_Position = gl_Vertex; }\n";
  const std::string text = vertexText(source);
  EXPECT_EQ(lines(text)[0], "#version 140");
  EXPECT_TRUE(has(text, "\n#line 1\n")) << text;
  const std::vector<std::string> numbered = numberedLines(text);
  ASSERT_EQ(numbered.size(), 4u) << text;
  EXPECT_EQ(numbered[2], "");
  EXPECT_EQ(numbered[3], "void main() { gl_Position = snell_Vertex; }");
}

TEST(LegacyAdapter, AttributeAndVaryingByStage) {
  const std::string vertex = vertexText("attribute vec3 Tangent;\nvarying vec4 Color;\n");
  EXPECT_TRUE(has(vertex, "\nin vec3 Tangent;\nout vec4 Color;\n")) << vertex;
  const std::string fragment = fragmentText("varying vec4 Color;\n");
  EXPECT_TRUE(has(fragment, "\nin vec4 Color;\n")) << fragment;
}

TEST(LegacyAdapter, TextureLookupsBecomeTheirGlsl140Overloads) {
  const std::string text = fragmentText(
      "void main() { vec4 a = texture2D(s, p) + textureCube(c, d) + texture1D(o, x) +"
      " texture3D(t, q) + texture2DProj(s, r) + textureCubeLod(c, d, 0.0) +"
      " texture2DProjLod(s, r, 1.0); }\n");
  EXPECT_TRUE(has(text,
                  "texture(s, p) + texture(c, d) + texture(o, x) + texture(t, q) +"
                  " textureProj(s, r) + textureLod(c, d, 0.0) + textureProjLod(s, r, 1.0)"))
      << text;
}

TEST(LegacyAdapter, FragColorBecomesADeclaredOutput) {
  const LegacyAdapted adapted =
      adaptLegacyForVulkan("void main() { gl_FragColor = vec4(1.0); }\n", LegacyStage::Fragment);
  EXPECT_TRUE(has(adapted.text, "out vec4 snell_FragColor;")) << adapted.text;
  EXPECT_TRUE(has(adapted.text, "void main() { snell_FragColor = vec4(1.0); }")) << adapted.text;
  ASSERT_EQ(adapted.renamings.size(), 1u);
  EXPECT_EQ(adapted.renamings[0].kind, LegacyRenaming::Kind::Output);
  EXPECT_EQ(adapted.renamings[0].builtin, "gl_FragColor");
  EXPECT_EQ(adapted.renamings[0].renamed, "snell_FragColor");
}

// Vulkan counts gl_FragCoord's rows from the top, OpenGL from the bottom:
// the adapted shader mirrors y with the height the backend supplies.
TEST(LegacyAdapter, FragCoordCountsRowsFromTheBottomAsInOpenGL) {
  const LegacyAdapted adapted = adaptLegacyForVulkan(
      "void main() { gl_FragColor = vec4(gl_FragCoord.xy, 0.0, 1.0); }\n", LegacyStage::Fragment);
  EXPECT_TRUE(has(adapted.text, "uniform float snell_FramebufferHeight;")) << adapted.text;
  EXPECT_TRUE(has(adapted.text, "vec4 snell_FragCoord() { return vec4(gl_FragCoord.x, "
                                "snell_FramebufferHeight - gl_FragCoord.y, gl_FragCoord.zw); }"))
      << adapted.text;
  EXPECT_TRUE(has(adapted.text, "snell_FragColor = vec4(snell_FragCoord().xy, 0.0, 1.0);"))
      << adapted.text;
  ASSERT_EQ(adapted.renamings.size(), 2u);
  EXPECT_EQ(adapted.renamings[0].kind, LegacyRenaming::Kind::Uniform);
  EXPECT_EQ(adapted.renamings[0].builtin, kFramebufferHeightUniform);
  // A vertex shader has no gl_FragCoord: nothing is mapped there.
  EXPECT_FALSE(has(adaptLegacyForVulkan("float gl_FragCoord;\n", LegacyStage::Vertex).text,
                   "snell_FragCoord"));
}

TEST(LegacyAdapter, FragDataWithALiteralIndexBecomesAnOutputAtThatLocation) {
  const std::string text =
      fragmentText("void main() { gl_FragData[0] = vec4(1.0); gl_FragData [ 2 ] = vec4(0.0); }\n");
  EXPECT_TRUE(has(text, "#extension GL_ARB_explicit_attrib_location : enable")) << text;
  EXPECT_TRUE(has(text, "layout(location = 0) out vec4 snell_FragData0;")) << text;
  EXPECT_TRUE(has(text, "layout(location = 2) out vec4 snell_FragData2;")) << text;
  EXPECT_TRUE(has(text, "snell_FragData0 = vec4(1.0); snell_FragData2 = vec4(0.0);")) << text;
}

TEST(LegacyAdapter, VertexInputsBecomeDeclaredInputs) {
  const LegacyAdapted adapted = adaptLegacyForVulkan(
      "void main() { gl_Position = gl_Vertex + vec4(gl_Normal, 0.0) + gl_MultiTexCoord3; }\n",
      LegacyStage::Vertex);
  EXPECT_TRUE(has(adapted.text,
                  "in vec4 snell_Vertex; in vec3 snell_Normal; in vec4 snell_MultiTexCoord3;"))
      << adapted.text;
  EXPECT_TRUE(has(adapted.text,
                  "gl_Position = snell_Vertex + vec4(snell_Normal, 0.0) + snell_MultiTexCoord3;"))
      << adapted.text;
  ASSERT_EQ(adapted.renamings.size(), 3u);
  EXPECT_EQ(adapted.renamings[2].builtin, "gl_MultiTexCoord3");
  EXPECT_EQ(adapted.renamings[2].kind, LegacyRenaming::Kind::Input);
}

TEST(LegacyAdapter, MatricesBecomeUniformsWithSnellNames) {
  const LegacyAdapted adapted = adaptLegacyForVulkan(
      "void main() { gl_Position = gl_ProjectionMatrix * gl_ModelViewMatrix * vec4(0.0) +"
      " gl_ModelViewProjectionMatrix * vec4(gl_NormalMatrix * vec3(1.0), 1.0); }\n",
      LegacyStage::Vertex);
  EXPECT_TRUE(has(adapted.text,
                  "uniform mat4 snell_ModelViewMatrix; uniform mat4 snell_ProjectionMatrix; "
                  "uniform mat4 snell_ModelViewProjectionMatrix; uniform mat3 "
                  "snell_NormalMatrix;"))
      << adapted.text;
  EXPECT_FALSE(has(adapted.text, "gl_ModelView")) << adapted.text;
  EXPECT_FALSE(has(adapted.text, "gl_NormalMatrix")) << adapted.text;
  ASSERT_EQ(adapted.renamings.size(), 4u);
  EXPECT_EQ(adapted.renamings[3].builtin, "gl_NormalMatrix");
  EXPECT_EQ(adapted.renamings[3].kind, LegacyRenaming::Kind::Uniform);
}

TEST(LegacyAdapter, TextureMatricesWithALiteralIndexBecomeOneUniformEach) {
  const LegacyAdapted adapted = adaptLegacyForVulkan(
      "void main() { gl_Position = gl_TextureMatrix[1] * gl_TextureMatrix[0] * vec4(1.0); }\n",
      LegacyStage::Vertex);
  EXPECT_TRUE(has(adapted.text,
                  "uniform mat4 snell_TextureMatrix0; uniform mat4 "
                  "snell_TextureMatrix1;"))
      << adapted.text;
  EXPECT_TRUE(has(adapted.text, "snell_TextureMatrix1 * snell_TextureMatrix0 * vec4(1.0)"))
      << adapted.text;
  ASSERT_EQ(adapted.renamings.size(), 2u);
  EXPECT_EQ(adapted.renamings[0].builtin, "gl_TextureMatrix[0]");
  EXPECT_EQ(adapted.renamings[1].builtin, "gl_TextureMatrix[1]");
  EXPECT_EQ(adapted.renamings[1].renamed, "snell_TextureMatrix1");
}

TEST(LegacyAdapter, TextureMatrixWithAComputedIndexIsLeftForTheCompiler) {
  const std::string text = vertexText("void main() { int k = 1; mat4 m = gl_TextureMatrix[k]; }\n");
  EXPECT_TRUE(has(text, "gl_TextureMatrix[k]")) << text;
  EXPECT_FALSE(has(text, "snell_TextureMatrix")) << text;
}

TEST(LegacyAdapter, FtransformBecomesItsDefinition) {
  const LegacyAdapted adapted =
      adaptLegacyForVulkan("void main() { gl_Position = ftransform ( ); }\n", LegacyStage::Vertex);
  EXPECT_TRUE(has(adapted.text, "gl_Position = (snell_ModelViewProjectionMatrix * snell_Vertex);"))
      << adapted.text;
  EXPECT_TRUE(has(adapted.text,
                  "in vec4 snell_Vertex; uniform mat4 "
                  "snell_ModelViewProjectionMatrix;"))
      << adapted.text;
  ASSERT_EQ(adapted.renamings.size(), 2u);
  EXPECT_EQ(adapted.renamings[0].builtin, "gl_Vertex");
  EXPECT_EQ(adapted.renamings[1].builtin, "gl_ModelViewProjectionMatrix");
}

TEST(LegacyAdapter, OnlyWholeIdentifiersAreMapped) {
  const std::string source =
      "uniform vec4 my_gl_Vertex;\nuniform vec4 gl_VertexColour2;\nfloat varyingScale;\n"
      "float attributes;\nvec4 texture2DScaled(vec4 v) { return v; }\n"
      "void main() { gl_Position = my_gl_Vertex + texture2DScaled(gl_VertexColour2) * 1e5; }\n";
  const LegacyAdapted adapted = adaptLegacyForVulkan(source, LegacyStage::Vertex);
  EXPECT_TRUE(adapted.renamings.empty());
  const std::vector<std::string> numbered = numberedLines(adapted.text);
  ASSERT_EQ(numbered.size(), 7u) << adapted.text;
  EXPECT_EQ(numbered[1], "uniform vec4 my_gl_Vertex;");
  EXPECT_EQ(numbered[3], "float varyingScale;");
  EXPECT_EQ(numbered[4], "float attributes;");
  EXPECT_EQ(numbered[5], "vec4 texture2DScaled(vec4 v) { return v; }");
}

TEST(LegacyAdapter, StageDecidesWhatIsMapped) {
  // `attribute` and the vertex inputs mean nothing in a fragment shader, and
  // gl_FragColor nothing in a vertex shader: left for the compiler to report.
  EXPECT_TRUE(has(fragmentText("attribute vec4 a;\n"), "attribute vec4 a;"));
  EXPECT_TRUE(has(fragmentText("vec4 v = gl_Vertex;\n"), "gl_Vertex"));
  EXPECT_TRUE(has(vertexText("void main() { gl_FragColor = vec4(0.0); }\n"), "gl_FragColor"));
}

TEST(LegacyAdapter, CommentsAreLeftAlone) {
  const std::string text = vertexText(
      "// varying gl_Vertex texture2D\n/* attribute\n gl_ModelViewMatrix */ void main() {}\n");
  EXPECT_TRUE(has(text, "// varying gl_Vertex texture2D\n/* attribute\n gl_ModelViewMatrix */"))
      << text;
  EXPECT_FALSE(has(text, "snell_")) << text;
}

TEST(LegacyAdapter, OnlyWhatIsUsedIsDeclared) {
  const std::string text = vertexText("void main() { gl_Position = gl_Vertex; }\n");
  EXPECT_TRUE(has(text, "in vec4 snell_Vertex;")) << text;
  EXPECT_FALSE(has(text, "uniform")) << text;
  EXPECT_FALSE(has(text, "snell_Normal")) << text;
  EXPECT_FALSE(has(text, "#extension")) << text;
}

TEST(LegacyAdapter, ABreakInsideAMappedTokenKeepsTheLineCount) {
  const std::string source = "void main() {\nmat4 m = gl_TextureMatrix[\n0];\nfloat after;\n}\n";
  const std::vector<std::string> numbered = numberedLines(vertexText(source));
  ASSERT_EQ(numbered.size(), 6u);
  EXPECT_EQ(numbered[4], "float after;");
  EXPECT_EQ(numbered[5], "}");
}

TEST(LegacyAdapter, ProbeLinesPassThroughUnchanged) {
  const std::string source =
      "varying vec3 Refract;\n"
      "uniform samplerCube tex;\n"
      "layout(location = 1) out vec4 snell_probe_1; void main(void)\n"
      "{ snell_probe_1 = vec4(0.0);\n"
      "vec3 c = vec3(textureCube(tex, Refract)); snell_probe_1 = vec4((c), 1.0);\n"
      "gl_FragColor = vec4(c, 1.0);\n"
      "}\n";
  const std::string text = fragmentText(source);
  const std::vector<std::string> numbered = numberedLines(text);
  ASSERT_EQ(numbered.size(), 8u) << text;
  EXPECT_EQ(numbered[3], "layout(location = 1) out vec4 snell_probe_1; void main(void)");
  EXPECT_EQ(numbered[4], "{ snell_probe_1 = vec4(0.0);");
  EXPECT_EQ(numbered[5], "vec3 c = vec3(texture(tex, Refract)); snell_probe_1 = vec4((c), 1.0);");
  // Beside explicitly placed outputs the listing's own takes location 0,
  // and GLSL 1.40 needs the extension for layout(location).
  EXPECT_TRUE(has(text, "#extension GL_ARB_explicit_attrib_location : enable")) << text;
  EXPECT_TRUE(has(text, "layout(location = 0) out vec4 snell_FragColor;")) << text;
}

TEST(LegacyAdapter, ProbesWithoutLocationsLeaveTheOutputUnplaced) {
  const std::string text = fragmentText(
      "out vec4 snell_probe_1; void main() { snell_probe_1 = vec4(0.0); gl_FragColor = "
      "vec4(1.0); }\n");
  EXPECT_TRUE(has(text, "\nout vec4 snell_FragColor;\n")) << text;
  EXPECT_FALSE(has(text, "location")) << text;
}

// The blog's corrected Fresnel pair: every published line, adapted, at its
// own number.
TEST(LegacyAdapter, BlogFresnelKeepsEveryLineAtItsNumber) {
  for (const auto& [file, stage] :
       {std::pair{"blog/fresnel/fresnel.vert", LegacyStage::Vertex},
        std::pair{"blog/fresnel/fresnel.frag", LegacyStage::Fragment}}) {
    const std::string source = readShader(file);
    ASSERT_FALSE(source.empty()) << file;
    const std::vector<std::string> published = lines(source);
    const std::vector<std::string> numbered =
        numberedLines(adaptLegacyForVulkan(source, stage).text);
    ASSERT_EQ(numbered.size(), published.size() + 1) << file;
    for (std::size_t k = 0; k < published.size(); ++k) {
      // Lines the adapter does not touch are identical; the others start
      // the same way (the blog's statements start with their target).
      const std::string& line = published[k];
      const bool touched = line.find("gl_") != std::string::npos ||
                           line.find("texture") != std::string::npos ||
                           line.find("varying") != std::string::npos;
      if (!touched) {
        EXPECT_EQ(numbered[k + 1], line) << file << ":" << k + 1;
      }
    }
    EXPECT_EQ(numbered[4],
              stage == LegacyStage::Vertex ? "out vec3 Reflect;" : "uniform samplerCube tex;");
  }
}

}  // namespace
}  // namespace snell
