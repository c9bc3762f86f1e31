#include "backends/vk/vk_prepared_capture.h"

#include <optional>

#include "backends/vk/program_key.h"
#include "backends/vk/spirv_resources.h"
#include "backends/vk/spirv_validate.h"
#include "core/errors.h"

namespace snell::vk {

namespace {

// The vertex module's own binding, not the linked program's reflection:
// glslang 12 may give the same merged block different bindings per stage.
std::optional<UniformBinding> defaultBlockBinding(std::span<const std::uint32_t> spirv,
                                                  const std::string& file) {
  const DescriptorResources found = listDescriptorResources(spirv);
  if (!found.error.empty())
    throw SetupError(file + ": cannot read the vertex SPIR-V: " + found.error);
  std::optional<UniformBinding> binding;
  for (const DescriptorResource& resource : found.resources) {
    if (resource.kind == DescriptorKind::UniformBuffer && resource.name == kDefaultUniformBlock) {
      binding = UniformBinding{resource.set, resource.binding};
      continue;
    }
    throw UsageError(
        file + ": the vertex stage uses '" + resource.name +
        "'; a Vulkan capture can bind only loose uniforms (gl_DefaultUniformBlock) so far");
  }
  return binding;
}

}  // namespace

std::unique_ptr<PreparedCapture> prepareCapture(const VulkanDevice& device, VkRenderPass renderPass,
                                                const VulkanProgram& compiled,
                                                const ProgramSource& source,
                                                std::span<const std::string> varyings) {
  auto prepared = std::make_unique<PreparedCapture>();
  prepared->program = compiled;
  if (!prepared->program.ok) return prepared;

  const std::string file = source.vertexPath.empty() ? "<vertex shader>" : source.vertexPath;
  XfbPassResult xfb = addTransformFeedback(prepared->program.vertexSpirv, varyings);
  if (!xfb.ok()) throw UsageError(file + ": cannot capture: " + xfb.error);
  if (const std::string invalid = validateSpirvForVulkan(xfb.spirv); !invalid.empty()) {
    throw SetupError(file + ": the transform feedback post-pass produced invalid SPIR-V:\n" +
                     invalid);
  }
  if (xfb.stride > device.maxTransformFeedbackStride()) {
    throw UsageError(file + ": the captured outputs take " + std::to_string(xfb.stride) +
                     " bytes per vertex; " + device.driverInfo().renderer + " captures at most " +
                     std::to_string(device.maxTransformFeedbackStride()));
  }
  const std::optional<UniformBinding> binding = defaultBlockBinding(xfb.spirv, file);
  if (binding && !prepared->program.uniformBlock) {
    throw SetupError(
        file + ": the vertex stage uses gl_DefaultUniformBlock but reflection does not list it");
  }
  prepared->pipelines = std::make_unique<CapturePipelines>(device, renderPass, xfb.spirv, binding);
  prepared->varyings = std::move(xfb.varyings);
  prepared->stride = xfb.stride;
  return prepared;
}

std::string preparedCaptureKey(const ProgramSource& source, std::span<const std::string> varyings) {
  std::string key = programKey(source);
  for (const std::string& varying : varyings) appendKeyField(key, varying);
  return key;
}

}  // namespace snell::vk
