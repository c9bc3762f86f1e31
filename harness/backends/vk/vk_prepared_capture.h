#pragma once
// Everything about a (program, captured outputs) pair that does not change
// from one capture to the next: the compiled program and its reflection,
// the transform feedback layout, and the pipelines. Built once, then cached.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "backends/vk/glsl_to_spirv.h"
#include "backends/vk/spirv_xfb_pass.h"
#include "backends/vk/vk_capture_pipeline.h"
#include "backends/vk/vk_device.h"

namespace snell::vk {

struct PreparedCapture {
  VulkanProgram program;             // !program.ok: nothing below is set
  std::vector<XfbVarying> varyings;  // in the order asked for
  std::uint32_t stride = 0;          // bytes per captured vertex
  std::unique_ptr<CapturePipelines> pipelines;
};

// `compiled` is `source` as compileForVulkan gave it; a compile error comes
// back inside the result. A varying that is not a vertex output is a
// UsageError, and a Vulkan failure a SetupError.
std::unique_ptr<PreparedCapture> prepareCapture(const VulkanDevice& device, VkRenderPass renderPass,
                                                const VulkanProgram& compiled,
                                                const ProgramSource& source,
                                                std::span<const std::string> varyings);

// A cache key that differs whenever the prepared capture would.
std::string preparedCaptureKey(const ProgramSource& source, std::span<const std::string> varyings);

}  // namespace snell::vk
