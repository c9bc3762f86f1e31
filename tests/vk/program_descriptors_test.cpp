// Both stages of a linked program must agree on one descriptor set layout.
// The rewritten modules are read back here with the test's own SPIR-V
// reader (vk_test_support.h), not with the code under test.
#include "backends/vk/program_descriptors.h"

#include <gtest/gtest.h>

#include "backends/vk/glsl_to_spirv.h"
#include "backends/vk/spirv_descriptor_rebind.h"
#include "backends/vk/spirv_validate.h"
#include "core/errors.h"
#include "vk_test_support.h"

namespace snell::vk {
namespace {

// Loose uniforms in both stages and a samplerCube: the shape in which
// glslang puts the fragment stage's copy of the block at another binding
// than the vertex stage's, and the sampler on top of one of them.
ProgramSource sharedBlockAndSampler() {
  ProgramSource program;
  program.vertex = R"(#version 140
in vec4 Position;
uniform float Depth;
void main() { gl_Position = vec4(Position.xy, Depth, 1.0); }
)";
  program.fragment = R"(#version 140
uniform samplerCube Env;
uniform vec3 Direction;
out vec4 FragColor;
void main() { FragColor = texture(Env, Direction); }
)";
  program.vertexPath = "probes/shared.vert";
  program.fragmentPath = "probes/shared.frag";
  return program;
}

const ProgramDescriptor* descriptorNamed(const BoundProgram& bound, const std::string& name) {
  for (const ProgramDescriptor& d : bound.descriptors) {
    if (d.name == name) return &d;
  }
  return nullptr;
}

TEST(VkProgramDescriptors, SharedBlockHasOneBindingInBothStagesAndTheSamplerItsOwn) {
  const VulkanProgram compiled = compileForVulkan(sharedBlockAndSampler());
  ASSERT_TRUE(compiled.ok) << compiled.log;
  const BoundProgram bound = bindProgramDescriptors(compiled.vertexSpirv, compiled.fragmentSpirv);

  const auto vertexBlock = vktest::descriptorSlot(bound.vertexSpirv, kDefaultUniformBlock);
  const auto fragmentBlock = vktest::descriptorSlot(bound.fragmentSpirv, kDefaultUniformBlock);
  const auto sampler = vktest::descriptorSlot(bound.fragmentSpirv, "Env");
  ASSERT_TRUE(vertexBlock && fragmentBlock && sampler);
  EXPECT_EQ(vertexBlock->set, 0u);
  EXPECT_EQ(fragmentBlock->set, 0u);
  EXPECT_EQ(sampler->set, 0u);
  EXPECT_EQ(vertexBlock->binding, fragmentBlock->binding);
  EXPECT_NE(sampler->binding, fragmentBlock->binding);

  ASSERT_EQ(bound.descriptors.size(), 2u);
  const ProgramDescriptor* block = descriptorNamed(bound, kDefaultUniformBlock);
  const ProgramDescriptor* env = descriptorNamed(bound, "Env");
  ASSERT_TRUE(block && env);
  EXPECT_EQ(block->kind, DescriptorKind::UniformBuffer);
  EXPECT_EQ(block->binding, vertexBlock->binding);
  EXPECT_TRUE(block->inVertexStage && block->inFragmentStage);
  EXPECT_EQ(env->kind, DescriptorKind::CombinedImageSampler);
  EXPECT_TRUE(env->cube);
  EXPECT_EQ(env->binding, sampler->binding);
  EXPECT_FALSE(env->inVertexStage);
  EXPECT_TRUE(env->inFragmentStage);

  EXPECT_EQ(validateSpirvForVulkan(bound.vertexSpirv), "");
  EXPECT_EQ(validateSpirvForVulkan(bound.fragmentSpirv), "");
}

TEST(VkProgramDescriptors, OnlyDecorationWordsChange) {
  const VulkanProgram compiled = compileForVulkan(sharedBlockAndSampler());
  ASSERT_TRUE(compiled.ok) << compiled.log;
  const BoundProgram bound = bindProgramDescriptors(compiled.vertexSpirv, compiled.fragmentSpirv);
  const std::vector<vktest::Words> before = vktest::instructionsOf(compiled.fragmentSpirv);
  const std::vector<vktest::Words> after = vktest::instructionsOf(bound.fragmentSpirv);
  ASSERT_EQ(before.size(), after.size());
  constexpr std::uint32_t kOpDecorate = 71, kBinding = 33, kDescriptorSet = 34;
  for (std::size_t i = 0; i < before.size(); ++i) {
    const bool slotDecoration = (before[i][0] & 0xffff) == kOpDecorate &&
                                (before[i][2] == kBinding || before[i][2] == kDescriptorSet);
    if (slotDecoration) {
      EXPECT_EQ(std::vector(before[i].begin(), before[i].end() - 1),
                std::vector(after[i].begin(), after[i].end() - 1))
          << "instruction " << i;
    } else {
      EXPECT_EQ(before[i], after[i]) << "instruction " << i;
    }
  }
}

TEST(VkSpirvDescriptorRebind, AVariableWithoutDecorationsIsAnError) {
  const VulkanProgram compiled = compileForVulkan(sharedBlockAndSampler());
  ASSERT_TRUE(compiled.ok) << compiled.log;
  // Id 1 is never a descriptor variable in glslang's output (it is the GLSL.std.450 import).
  const RebindResult result = rebindDescriptors(compiled.fragmentSpirv, {{1u, {0, 5}}});
  EXPECT_FALSE(result.ok());
  EXPECT_NE(result.error.find("%1 lacks"), std::string::npos) << result.error;
  EXPECT_TRUE(result.spirv.empty());
}

TEST(VkSpirvDescriptorRebind, MalformedModulesGiveErrorsNotCrashes) {
  const std::vector<std::uint32_t> truncated = {0x07230203u, 0x00010300u,      0, 10,
                                                0,           (9u << 16) | 71u, 1u};
  EXPECT_FALSE(rebindDescriptors(truncated, {}).ok());
  EXPECT_FALSE(rebindDescriptors(std::vector<std::uint32_t>{1, 2, 3}, {}).ok());
  EXPECT_THROW(bindProgramDescriptors(truncated, truncated), SetupError);
}

}  // namespace
}  // namespace snell::vk
