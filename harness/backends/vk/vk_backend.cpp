#include "backends/vk/vk_backend.h"

#include <exception>
#include <utility>

#include "backends/vk/glsl_to_spirv.h"
#include "backends/vk/lru_cache.h"
#include "backends/vk/uniform_block_layout.h"
#include "backends/vk/vertex_streams.h"
#include "backends/vk/vk_capture.h"
#include "backends/vk/vk_check.h"
#include "backends/vk/vk_device.h"
#include "backends/vk/vk_instance.h"
#include "backends/vk/vk_prepared_capture.h"
#include "core/errors.h"

namespace snell {

namespace {

using namespace snell::vk;

// Enough for every listing and probe a suite run uses, small enough that a
// stream of distinct programs cannot pile up pipelines without bound.
constexpr std::size_t kCachedPrograms = 256;
// Keeps vertexCount * stride far inside 32-bit sizes and a minute's work on llvmpipe.
constexpr std::size_t kMaxVertices = std::size_t{1} << 24;

std::vector<CapturedVarying> splitRecords(std::span<const float> records,
                                          const PreparedCapture& prepared,
                                          std::size_t vertexCount) {
  const std::size_t floatsPerVertex = prepared.stride / sizeof(float);
  std::vector<CapturedVarying> varyings;
  for (const XfbVarying& varying : prepared.varyings) {
    CapturedVarying out{varying.name, varying.components, {}};
    out.data.reserve(vertexCount * static_cast<std::size_t>(varying.components));
    const std::size_t first = varying.offset / sizeof(float);
    for (std::size_t vertex = 0; vertex < vertexCount; ++vertex) {
      const float* at = records.data() + vertex * floatsPerVertex + first;
      out.data.insert(out.data.end(), at, at + varying.components);
    }
    varyings.push_back(std::move(out));
  }
  return varyings;
}

class VkBackend final : public Backend {
 public:
  explicit VkBackend(const BackendOptions& options)
      : instance_(options.validation),
        device_(instance_),
        runner_(device_),
        cache_(kCachedPrograms) {
    instance_.validationLog().throwIfAny("Vulkan start-up");
  }

  std::string name() const override { return "vk"; }
  DriverInfo driverInfo() const override { return device_.driverInfo(); }

  CompileOutcome compile(const ProgramSource& program) override {
    return validated("compile", [&] {
      const VulkanProgram compiled = compileForVulkan(program);
      if (compiled.ok) {
        // The driver (and the validation layer) get to see both modules too.
        checkShaderModule(compiled.vertexSpirv);
        if (!compiled.fragmentSpirv.empty()) checkShaderModule(compiled.fragmentSpirv);
      }
      return CompileOutcome{compiled.ok, compiled.log};
    });
  }

  CaptureOutcome captureVertexOutputs(const CaptureJob& job) override {
    return validated("captureVertexOutputs", [&] { return capture(job); });
  }

 private:
  // Runs `work`, then reports any validation message it caused as a SetupError.
  template <class Work>
  auto validated(const char* call, Work&& work) -> decltype(work()) {
    try {
      auto result = work();
      instance_.validationLog().throwIfAny(call);
      return result;
    } catch (const std::exception& error) {
      // A failure that also upset the validation layer is most likely a
      // Vulkan misuse: report the messages with the symptom, and leave none
      // behind to be blamed on the next call.
      instance_.validationLog().throwIfAny(call, error.what());
      throw;
    }
  }

  void checkShaderModule(const std::vector<std::uint32_t>& spirv) {
    VkShaderModuleCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    info.codeSize = spirv.size() * sizeof(std::uint32_t);
    info.pCode = spirv.data();
    VkShaderModule module = VK_NULL_HANDLE;
    check(vkCreateShaderModule(device_.handle(), &info, nullptr, &module), "vkCreateShaderModule");
    vkDestroyShaderModule(device_.handle(), module, nullptr);
  }

  CaptureOutcome capture(const CaptureJob& job) {
    PreparedCapture& prepared = cache_.getOrMake(
        preparedCaptureKey(job.program, job.varyings),
        [&] { return prepareCapture(device_, runner_.renderPass(), job.program, job.varyings); });
    CaptureOutcome outcome;
    outcome.compile = {prepared.program.ok, prepared.program.log};
    if (!prepared.program.ok) return outcome;
    if (job.vertexCount > kMaxVertices) {
      throw UsageError("a capture of " + std::to_string(job.vertexCount) +
                       " vertices is more than the " + std::to_string(kMaxVertices) +
                       " one call may ask for");
    }

    const VertexStreams streams =
        matchVertexStreams(prepared.program.vertexInputs, job.attributes, job.vertexCount);
    std::size_t uniformBytes = 0;
    if (const auto& layout = prepared.program.uniformBlock) {
      uniformBytes = layout->size;
      packUniforms(*layout, job.uniforms, runner_.uniformBlock(uniformBytes));
    }
    if (job.vertexCount == 0) {
      outcome.varyings = splitRecords({}, prepared, 0);
      return outcome;
    }

    CaptureDraw draw;
    draw.pipeline = prepared.pipelines->pipeline(streams.formats);
    draw.layout = prepared.pipelines->layout();
    draw.descriptorSet = prepared.pipelines->descriptorSet();
    if (const auto binding = prepared.pipelines->uniformBinding())
      draw.uniformBinding = binding->binding;
    draw.uniformBytes = uniformBytes;
    draw.streams = streams.streams;
    // The pipeline draws triangles; the padding vertices are dropped below.
    draw.vertexCount = static_cast<std::uint32_t>((job.vertexCount + 2) / 3 * 3);
    draw.stride = prepared.stride;
    outcome.varyings = splitRecords(runner_.run(draw), prepared, job.vertexCount);
    return outcome;
  }

  // Declared in the order they are built; destroyed in reverse.
  VulkanInstance instance_;
  VulkanDevice device_;
  CaptureRunner runner_;
  LruCache<PreparedCapture> cache_;
};

}  // namespace

std::unique_ptr<Backend> makeVkBackend(const BackendOptions& options) {
  return std::make_unique<VkBackend>(options);
}

}  // namespace snell
