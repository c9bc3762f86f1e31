#include "backends/vk/vk_backend.h"

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <iterator>
#include <utility>

#include "backends/driver_variables.h"
#include "backends/vk/compiled_program_store.h"
#include "backends/vk/glsl_to_spirv.h"
#include "backends/vk/legacy_adapter.h"
#include "backends/vk/lru_cache.h"
#include "backends/vk/program_key.h"
#include "backends/vk/spirv_output_locations.h"
#include "backends/vk/uniform_block_layout.h"
#include "backends/vk/vertex_streams.h"
#include "backends/vk/vk_capture.h"
#include "backends/vk/vk_device.h"
#include "backends/vk/vk_instance.h"
#include "backends/vk/vk_prepared_capture.h"
#include "backends/vk/vk_prepared_render.h"
#include "backends/vk/vk_render.h"
#include "backends/vk/vk_shader_module.h"
#include "core/errors.h"
#include "core/phase_clock.h"

namespace snell {

namespace {

using namespace snell::vk;

// Enough for every listing and probe a suite run uses, small enough that a
// stream of distinct programs cannot pile up pipelines without bound.
constexpr std::size_t kCachedPrograms = 256;
// Keeps vertexCount * stride far inside 32-bit sizes and a minute's work on llvmpipe.
constexpr std::size_t kMaxVertices = std::size_t{1} << 24;
// Beyond this a single RGBA32F read-back passes 1 GiB.
constexpr int kMaxRenderSide = 8192;

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

// The program with its probe outputs at the locations the render reads.
VulkanProgram withProbeLocations(const VulkanProgram& compiled, const ProgramSource& source) {
  VulkanProgram placed = compiled;
  if (!placed.ok) return placed;
  OutputLocationResult result = assignProbeOutputLocations(placed.fragmentSpirv);
  if (!result.ok())
    throw SetupError(source.fragmentPath + ": placing the probe outputs: " + result.error);
  placed.fragmentSpirv = std::move(result.spirv);
  return placed;
}

class VkBackend final : public Backend {
 public:
  VkBackend(std::string name, bool lavapipeByDefault, const std::string& device,
            const BackendOptions& options)
      : name_(std::move(name)),
        instance_(options.validation, lavapipeByDefault),
        device_(instance_, device),
        captureRunner_(device_),
        renderRunner_(device_),
        programs_(kCachedPrograms),
        captures_(kCachedPrograms),
        renders_(kCachedPrograms),
        programStore_(options.cacheDir) {
    instance_.validationLog().throwIfAny("Vulkan start-up");
    // lavapipe at a width LP_NATIVE_VECTOR_WIDTH forces is another driver
    // than the one vk's goldens were blessed on, as llvmpipe's is for gl.
    const char* width = std::getenv("LP_NATIVE_VECTOR_WIDTH");
    const std::string renderer = device_.driverInfo().renderer;
    if (lavapipeByDefault && width && *width && renderer.find("llvmpipe") != std::string::npos)
      throw SetupError(whyNotAtNativeVectorWidth(
          name_, "lavapipe", renderer, width, driverVariableSetBy("LP_NATIVE_VECTOR_WIDTH"), ""));
  }

  std::string name() const override { return name_; }
  DriverInfo driverInfo() const override { return device_.driverInfo(); }

  CompileOutcome compile(const ProgramSource& program) override {
    return validated("compile", [&] {
      const VulkanProgram compiled = programStore_.compile(program);
      if (compiled.ok) {
        // The driver (and the validation layer) get to see both modules too.
        checkShaderModule(compiled.vertexSpirv);
        if (!compiled.fragmentSpirv.empty()) checkShaderModule(compiled.fragmentSpirv);
      }
      return CompileOutcome{compiled.ok, compiled.log, compiled.diagnostics};
    });
  }

  CaptureOutcome captureVertexOutputs(const CaptureJob& job) override {
    return validated("captureVertexOutputs", [&] { return capture(job); });
  }

  RenderOutcome render(const RenderJob& job) override {
    return validated("render", [&] { return draw(job); });
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
    const ShaderModule module(device_, spirv);
  }

  // Captures and renders of one program share its compile; the reference
  // is valid until the next call.
  const VulkanProgram& compiled(const ProgramSource& source) {
    return programs_.getOrMake(programKey(source), [&] {
      return std::make_unique<VulkanProgram>(programStore_.compile(source));
    });
  }

  CaptureOutcome capture(const CaptureJob& job) {
    PreparedCapture& prepared =
        captures_.getOrMake(preparedCaptureKey(job.program, job.varyings), [&] {
          const PhaseScope phase(Phase::Compile);
          return prepareCapture(device_, captureRunner_.renderPass(), compiled(job.program),
                                job.program, job.varyings);
        });
    CaptureOutcome outcome;
    outcome.compile = {prepared.program.ok, prepared.program.log, prepared.program.diagnostics};
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
      packUniforms(*layout, job.uniforms, captureRunner_.uniformBlock(uniformBytes));
    }
    if (job.vertexCount == 0) {
      outcome.varyings = splitRecords({}, prepared, 0);
      return outcome;
    }

    CaptureDraw draw;
    draw.pipeline = prepared.pipelines->pipeline(streams.formats);
    draw.descriptors = &prepared.pipelines->descriptors();
    if (const auto binding = prepared.pipelines->uniformBinding())
      draw.uniformBinding = binding->binding;
    draw.uniformBytes = uniformBytes;
    draw.streams = streams.streams;
    // The pipeline draws triangles; the padding vertices are dropped below.
    draw.vertexCount = static_cast<std::uint32_t>((job.vertexCount + 2) / 3 * 3);
    draw.stride = prepared.stride;
    const std::span<const float> records = [&] {
      const PhaseScope phase(Phase::Draw);
      return captureRunner_.run(draw);
    }();
    const PhaseScope reading(Phase::ReadBack);
    outcome.varyings = splitRecords(records, prepared, job.vertexCount);
    return outcome;
  }

  RenderOutcome draw(const RenderJob& job) {
    if (job.program.fragment.empty()) {
      throw UsageError(
          (job.program.vertexPath.empty() ? "<vertex shader>" : job.program.vertexPath) +
          ": a render needs a fragment shader");
    }
    const VkPhysicalDeviceLimits& limits = device_.limits();
    const int maxWidth = static_cast<int>(std::min<std::uint32_t>(
        {limits.maxFramebufferWidth, limits.maxImageDimension2D, kMaxRenderSide}));
    const int maxHeight = static_cast<int>(std::min<std::uint32_t>(
        {limits.maxFramebufferHeight, limits.maxImageDimension2D, kMaxRenderSide}));
    if (job.width < 1 || job.height < 1 || job.width > maxWidth || job.height > maxHeight) {
      throw UsageError("a " + std::to_string(job.width) + "x" + std::to_string(job.height) +
                       " render is outside 1x1 to " + std::to_string(maxWidth) + "x" +
                       std::to_string(maxHeight));
    }
    if (job.indices.size() % 3 != 0 || job.indices.size() > 3 * kMaxVertices) {
      throw UsageError("a render takes whole triangles, at most " + std::to_string(kMaxVertices) +
                       " of them; got " + std::to_string(job.indices.size()) + " indices");
    }

    // Probes are written into the fragment text before it is compiled
    // (core/fragment_probes.h), and their outputs placed in the SPIR-V.
    ProgramSource source = job.program;
    if (!job.probes.empty())
      source.fragment = insertFragmentProbes(source.fragment, source.fragmentPath, job.probes,
                                             ProbeOutputStyle::Outputs);
    const auto colourTargets = static_cast<std::uint32_t>(1 + job.probes.size());
    PreparedRender& prepared = renders_.getOrMake(programKey(source), [&] {
      const PhaseScope phase(Phase::Compile);
      if (job.probes.empty())
        return prepareRender(device_, renderRunner_.renderPass(1), 1, compiled(source), source);
      return prepareRender(device_, renderRunner_.renderPass(colourTargets), colourTargets,
                           withProbeLocations(compiled(source), source), source);
    });
    RenderOutcome outcome;
    outcome.compile = {prepared.program.ok, prepared.program.log, prepared.program.diagnostics};
    if (!prepared.program.ok) return outcome;

    RenderDraw draw;
    for (const SamplerBinding& sampler : prepared.samplers) {
      const auto found = job.cubeMaps.find(sampler.name);
      if (found == job.cubeMaps.end() || !found->second) {
        throw UsageError("the program samples cube map '" + sampler.name +
                         "' but the render job gives none by that name");
      }
      draw.cubeMaps.push_back({sampler.name, sampler.binding, found->second});
    }
    for (const SamplerBinding& sampler : prepared.textures2D) {
      const auto found = job.textures2D.find(sampler.name);
      if (found == job.textures2D.end() || !found->second) {
        throw UsageError("the program samples 2D texture '" + sampler.name +
                         "' but the render job gives none by that name");
      }
      draw.textures2D.push_back({sampler.name, sampler.binding, found->second});
    }
    const std::size_t vertexCount =
        job.indices.empty()
            ? 0
            : std::size_t{*std::max_element(job.indices.begin(), job.indices.end())} + 1;
    const VertexStreams streams =
        matchVertexStreams(prepared.program.vertexInputs, job.attributes, vertexCount);
    if (const auto& layout = prepared.program.uniformBlock) {
      draw.uniformBytes = layout->size;
      const std::span<std::byte> block = renderRunner_.uniformBlock(layout->size);
      if (layout->derivesLegacyState) {
        // An adapted legacy listing's gl_FragCoord needs the height to count
        // rows from the bottom, as OpenGL does (core/legacy_adapter.h).
        UniformMap uniforms = job.uniforms;
        uniforms[kFramebufferHeightUniform] =
            Value{ValueType::Float, {static_cast<float>(job.height)}};
        packUniforms(*layout, uniforms, block);
      } else {
        packUniforms(*layout, job.uniforms, block);
      }
    }
    draw.uniformBinding = prepared.uniformBinding;
    draw.pipeline = prepared.pipelines->pipeline(streams.formats, job.cullBackFaces);
    draw.descriptors = &prepared.pipelines->descriptors();
    draw.streams = streams.streams;
    draw.vertexCount = static_cast<std::uint32_t>(vertexCount);
    draw.indices = job.indices;
    draw.width = static_cast<std::uint32_t>(job.width);
    draw.height = static_cast<std::uint32_t>(job.height);
    draw.clearColor = job.clearColor;
    draw.colourTargets = colourTargets;
    std::vector<Image> images = renderRunner_.run(draw);
    outcome.image = std::move(images.front());
    outcome.probes.assign(std::make_move_iterator(images.begin() + 1),
                          std::make_move_iterator(images.end()));
    return outcome;
  }

  // Declared in the order they are built; destroyed in reverse.
  std::string name_;
  VulkanInstance instance_;
  VulkanDevice device_;
  CaptureRunner captureRunner_;
  RenderRunner renderRunner_;
  LruCache<VulkanProgram> programs_;
  LruCache<PreparedCapture> captures_;
  LruCache<PreparedRender> renders_;
  CompiledProgramStore programStore_;
};

}  // namespace

std::unique_ptr<Backend> makeVkBackend(const std::string& name, bool lavapipeByDefault,
                                       const std::string& device, const BackendOptions& options) {
  return std::make_unique<VkBackend>(name, lavapipeByDefault, device, options);
}

std::unique_ptr<Backend> makeVkBackend(const BackendOptions& options) {
  return makeVkBackend("vk", true, options.device, options);
}

}  // namespace snell
