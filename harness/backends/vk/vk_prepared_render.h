#pragma once
// Everything about a program that does not change from one render to the
// next: the compiled program, where its uniform block and samplers are
// bound once both stages share one descriptor set, and its pipelines.
// Built once, then cached.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "backends/vk/glsl_to_spirv.h"
#include "backends/vk/vk_device.h"
#include "backends/vk/vk_render_pipelines.h"

namespace snell::vk {

struct SamplerBinding {
  std::string name;  // the samplerCube or sampler2D uniform's GLSL name
  std::uint32_t binding = 0;
};

struct PreparedRender {
  VulkanProgram program;                        // !program.ok: nothing below is set
  std::optional<std::uint32_t> uniformBinding;  // gl_DefaultUniformBlock's, in both stages
  std::vector<SamplerBinding> samplers;         // samplerCube uniforms
  std::vector<SamplerBinding> textures2D;       // sampler2D uniforms
  std::unique_ptr<RenderPipelines> pipelines;
};

// `compiled` is `source` as compileForVulkan gave it, fragment stage
// included; a compile error comes back inside the result. A descriptor
// other than loose uniforms, samplerCube and sampler2D is a UsageError
// naming it, and a Vulkan failure a SetupError.
std::unique_ptr<PreparedRender> prepareRender(const VulkanDevice& device, VkRenderPass renderPass,
                                              std::uint32_t colourTargets,
                                              const VulkanProgram& compiled,
                                              const ProgramSource& source);

}  // namespace snell::vk
