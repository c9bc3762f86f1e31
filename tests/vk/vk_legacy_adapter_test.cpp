// Legacy listings on Vulkan through the legacy adapter (core/legacy_adapter.h):
// the blog's corrected shaders compile, diagnostics name the published
// lines, values given under gl_ names reach the renamed variables, and GL's
// derived state is computed from them.
#include <gtest/gtest.h>

#include <algorithm>

#include "backends/vk/glsl_to_spirv.h"
#include "backends/vk/vk_backend.h"
#include "vk_test_support.h"

namespace snell {
namespace {

Backend& backend() {
  static std::unique_ptr<Backend> shared = makeVkBackend(BackendOptions{.validation = true});
  return *shared;
}

ProgramSource legacyProgram(const std::string& vertex, const std::string& fragment,
                            const std::string& name) {
  ProgramSource program;
  program.vertex = vertex;
  program.fragment = fragment;
  program.vertexPath = name + ".vert";
  program.fragmentPath = fragment.empty() ? "" : name + ".frag";
  program.profile = Profile::Compatibility;
  return program;
}

ProgramSource blogListing(const std::string& folder, const std::string& stem) {
  const std::string dir = "shaders/blog/" + folder + "/";
  return legacyProgram(vktest::readSourceFile(dir + stem + ".vert"),
                       vktest::readSourceFile(dir + stem + ".frag"), dir + stem);
}

std::vector<std::string> memberNames(const vk::VulkanProgram& compiled) {
  std::vector<std::string> names;
  if (compiled.uniformBlock)
    for (const vk::BlockMember& member : compiled.uniformBlock->members)
      names.push_back(member.name);
  return names;
}

std::vector<std::string> inputNames(const vk::VulkanProgram& compiled) {
  std::vector<std::string> names;
  for (const vk::VertexInput& input : compiled.vertexInputs) names.push_back(input.name);
  return names;
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

TEST(VkLegacyAdapter, BlogCorrectedShadersCompileWithGlNames) {
  for (const auto& [folder, stem] :
       {std::pair{"fresnel", "fresnel"}, std::pair{"chromatic", "chromatic"},
        std::pair{"diffraction", "diffraction"}}) {
    const vk::VulkanProgram compiled = vk::compileForVulkan(blogListing(folder, stem));
    ASSERT_TRUE(compiled.ok) << folder << "\n" << compiled.log;
    const std::vector<std::string> members = memberNames(compiled);
    EXPECT_TRUE(contains(members, "gl_ModelViewMatrix")) << folder;
    EXPECT_TRUE(contains(members, "gl_NormalMatrix")) << folder;
    EXPECT_TRUE(contains(members, "gl_ModelViewProjectionMatrix")) << folder;
    EXPECT_TRUE(compiled.uniformBlock->derivesLegacyState);
    const std::vector<std::string> inputs = inputNames(compiled);
    EXPECT_TRUE(contains(inputs, "gl_Vertex")) << folder;
    EXPECT_TRUE(contains(inputs, "gl_Normal")) << folder;
    for (const std::string& name : members) EXPECT_EQ(name.rfind("snell_", 0), std::string::npos);
  }
  const vk::VulkanProgram fresnel = vk::compileForVulkan(blogListing("fresnel", "fresnel"));
  EXPECT_TRUE(contains(memberNames(fresnel), "gl_TextureMatrix[0]"));
  EXPECT_TRUE(contains(memberNames(fresnel), "gl_TextureMatrix[1]"));
  const vk::VulkanProgram diffraction =
      vk::compileForVulkan(blogListing("diffraction", "diffraction"));
  EXPECT_TRUE(contains(inputNames(diffraction), "Tangent"));
}

// glslang numbers the line after `#line N` N + 1 below GLSL 3.30: every
// published line keeps its number in the diagnostics.
TEST(VkLegacyAdapter, DiagnosticsPointAtThePublishedLines) {
  const vk::VulkanProgram fresnel =
      vk::compileForVulkan(blogListing("fresnel-as-published", "fresnel"));
  EXPECT_FALSE(fresnel.ok);
  EXPECT_NE(fresnel.log.find("fresnel-as-published/fresnel.frag:4:"), std::string::npos)
      << fresnel.log;
  const vk::VulkanProgram diffraction =
      vk::compileForVulkan(blogListing("diffraction-as-published", "diffraction"));
  EXPECT_FALSE(diffraction.ok);
  EXPECT_NE(diffraction.log.find("diffraction-as-published/diffraction.vert:3:"), std::string::npos)
      << diffraction.log;

  // With a #version line of its own, and declarations added after it.
  const vk::VulkanProgram versioned = vk::compileForVulkan(legacyProgram(
      "#version 110\nvarying vec4 p;\nvoid main() {\n  p = gl_Vertex;\n  p = missing;\n"
      "  gl_Position = ftransform();\n}\n",
      "", "probes/versioned"));
  EXPECT_FALSE(versioned.ok);
  EXPECT_NE(versioned.log.find("probes/versioned.vert:5:"), std::string::npos) << versioned.log;
  EXPECT_NE(versioned.log.find("missing"), std::string::npos) << versioned.log;
}

// GLSL 1.40 converts int to float where 1.10 does not: the adapter cannot
// hold a listing to 1.10's stricter rule (the Vulkan side of
// blog/diffraction-as-published reports only its other error).
TEST(VkLegacyAdapter, IntToFloatConversionsCompileAsGlsl140Does) {
  const vk::VulkanProgram compiled = vk::compileForVulkan(legacyProgram(
      "varying float y;\nvoid main() { y = 2 * gl_Vertex.x; gl_Position = gl_Vertex; }\n", "",
      "probes/int-times-float"));
  EXPECT_TRUE(compiled.ok) << compiled.log;
}

TEST(VkLegacyAdapter, CaptureBindsValuesGivenUnderGlNamesAndDerivesTheRest) {
  const char* const vertex =
      "varying vec4 eye;\nvarying vec3 normal;\nvarying vec4 clip;\nvarying vec4 coords;\n"
      "varying vec4 clipByHand;\n"
      "void main() {\n"
      "  eye = gl_ModelViewMatrix * gl_Vertex;\n"
      "  normal = gl_NormalMatrix * gl_Normal;\n"
      "  coords = gl_TextureMatrix[1] * gl_MultiTexCoord1;\n"
      "  clipByHand = gl_ProjectionMatrix * eye;\n"
      "  clip = ftransform();\n"
      "  gl_Position = clip;\n"
      "}\n";
  CaptureJob job;
  job.program = legacyProgram(vertex, "", "probes/legacy-capture");
  job.vertexCount = 1;
  job.varyings = {"eye", "normal", "clip", "coords", "clipByHand"};
  job.attributes["gl_Vertex"] = AttributeStream{"gl_Vertex", 4, {1, 2, 3, 1}};
  job.attributes["gl_Normal"] = AttributeStream{"gl_Normal", 3, {1, 1, 1}};
  job.attributes["gl_MultiTexCoord1"] = AttributeStream{"gl_MultiTexCoord1", 4, {1, 0, 0, 1}};
  // A scale and a move: every result below is exact in fp32.
  job.uniforms["gl_ModelViewMatrix"] =
      Value{ValueType::Mat4, {2, 0, 0, 0, 0, 4, 0, 0, 0, 0, 0.5f, 0, 3, 0, 0, 1}};
  job.uniforms["gl_ProjectionMatrix"] =
      Value{ValueType::Mat4, {0.25f, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, -1, 0, 0, 1, 0}};
  job.uniforms["gl_TextureMatrix[1]"] =
      Value{ValueType::Mat4, {0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 5, 6, 7, 1}};
  // Derived state given by hand is not used, as GL never takes it.
  job.uniforms["gl_NormalMatrix"] = Value{ValueType::Mat3, std::vector<float>(9, 100.0f)};

  const CaptureOutcome outcome = backend().captureVertexOutputs(job);
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  ASSERT_EQ(outcome.varyings.size(), 5u);
  EXPECT_EQ(outcome.varyings[0].data, (std::vector<float>{5, 8, 1.5f, 1}));
  EXPECT_EQ(outcome.varyings[1].data, (std::vector<float>{0.5f, 0.25f, 2}));
  EXPECT_EQ(outcome.varyings[2].data, (std::vector<float>{1.25f, 8, 2.5f, -1.5f}));
  EXPECT_EQ(outcome.varyings[3].data, (std::vector<float>{5, 7, 7, 1}));
  EXPECT_EQ(outcome.varyings[4].data, outcome.varyings[2].data);
}

}  // namespace
}  // namespace snell
