#include "backends/vk/vk_prepared_render.h"

#include "backends/vk/program_descriptors.h"
#include "backends/vk/spirv_validate.h"
#include "core/errors.h"

namespace snell::vk {

namespace {

std::string programFiles(const ProgramSource& source) {
  return (source.vertexPath.empty() ? "<vertex shader>" : source.vertexPath) + ", " +
         (source.fragmentPath.empty() ? "<fragment shader>" : source.fragmentPath);
}

void requireValid(const std::vector<std::uint32_t>& spirv, const std::string& files,
                  const char* stage) {
  if (const std::string invalid = validateSpirvForVulkan(spirv); !invalid.empty()) {
    throw SetupError(files + ": rewriting the " + stage +
                     " stage's descriptor bindings produced invalid SPIR-V:\n" + invalid);
  }
}

}  // namespace

std::unique_ptr<PreparedRender> prepareRender(const VulkanDevice& device, VkRenderPass renderPass,
                                              std::uint32_t colourTargets,
                                              const VulkanProgram& compiled,
                                              const ProgramSource& source) {
  auto prepared = std::make_unique<PreparedRender>();
  prepared->program = compiled;
  if (!prepared->program.ok) return prepared;

  const std::string files = programFiles(source);
  BoundProgram bound = [&] {
    try {
      return bindProgramDescriptors(compiled.vertexSpirv, compiled.fragmentSpirv);
    } catch (const SetupError& error) {
      throw SetupError(files + ": " + error.what());
    }
  }();
  requireValid(bound.vertexSpirv, files, "vertex");
  requireValid(bound.fragmentSpirv, files, "fragment");

  for (const ProgramDescriptor& descriptor : bound.descriptors) {
    if (descriptor.kind == DescriptorKind::UniformBuffer &&
        descriptor.name == kDefaultUniformBlock) {
      prepared->uniformBinding = descriptor.binding;
    } else if (descriptor.kind == DescriptorKind::CombinedImageSampler && descriptor.cube) {
      prepared->samplers.push_back({descriptor.name, descriptor.binding});
    } else if (descriptor.kind == DescriptorKind::CombinedImageSampler && descriptor.plain2D) {
      prepared->textures2D.push_back({descriptor.name, descriptor.binding});
    } else {
      throw UsageError(files + ": the program uses '" + descriptor.name +
                       "'; a Vulkan render can bind only loose uniforms, samplerCube and "
                       "sampler2D uniforms");
    }
  }
  if (prepared->uniformBinding && !compiled.uniformBlock) {
    throw SetupError(files + ": the program uses " + kDefaultUniformBlock +
                     " but reflection does not list it");
  }
  prepared->pipelines = std::make_unique<RenderPipelines>(device, renderPass, colourTargets, bound.vertexSpirv,
                                                          bound.fragmentSpirv, bound.descriptors);
  return prepared;
}

}  // namespace snell::vk
