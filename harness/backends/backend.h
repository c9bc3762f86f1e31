#pragma once
// The one interface every graphics API hides behind. The harness hands a
// backend a program as published plus the values to bind, and gets floats
// back; what the API needs to do that (transform feedback, SPIR-V
// post-passes, descriptor layouts) stays inside the backend.
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/cube_map.h"
#include "core/fragment_probes.h"
#include "core/image.h"
#include "core/program_source.h"
#include "core/values.h"

namespace snell {

// What the driver says about itself; goes into every result and golden.
struct DriverInfo {
  std::string api;            // "OpenGL" / "Vulkan"
  std::string apiVersion;     // "4.5 (Core Profile) Mesa 22.3.6" / "1.3.230"
  std::string renderer;       // "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string driverVersion;  // "Mesa 22.3.6"
  std::string deviceType;     // "cpu", "integrated-gpu", ...
};

// One message of the compiler, placed: the stage's own file and line, so
// that an expected compile error can be pinned to where it must be.
struct CompileDiagnostic {
  std::string stage;  // "vertex", "fragment" or "link"
  int line = 0;       // in that stage's file; 0 when the message names no line
  bool error = true;  // false: a warning
  std::string message;
};

struct CompileOutcome {
  bool ok = false;
  std::string log;                             // compiler/linker diagnostics, empty when clean
  std::vector<CompileDiagnostic> diagnostics;  // the log's placed messages, parsed by the backend
};

struct CaptureJob {
  ProgramSource program;
  UniformMap uniforms;                // by GLSL name; names the program lacks are ignored
  AttributeMap attributes;            // by GLSL name
  std::vector<std::string> varyings;  // vertex outputs to read back, in order
  std::size_t vertexCount = 0;
};

struct CaptureOutcome {
  CompileOutcome compile;                 // !compile.ok => varyings is empty
  std::vector<CapturedVarying> varyings;  // same order as CaptureJob::varyings
};

// Draws the listing's triangles into an RGBA32F colour target (with a 32-bit
// float depth buffer, depth test LESS, cleared to 1) and reads the pixels
// back. Clip space follows OpenGL: +y up in the image; scenes keep every
// visible point at NDC z in [0, 1], so both APIs' depth ranges agree.
struct RenderJob {
  ProgramSource program;
  UniformMap uniforms;                 // by GLSL name; names the program lacks are ignored
  AttributeMap attributes;             // by GLSL name
  std::vector<std::uint32_t> indices;  // triangle list, counter-clockwise front faces
  std::map<std::string, const CubeMap*> cubeMaps;  // samplerCube uniforms by GLSL name
  // sampler2D uniforms by GLSL name. Base level only, LINEAR filtering and
  // REPEAT wrapping in s and t (the CPU reference, oracle/reference/
  // texture_2d_sampling.h, samples the same way); texel (i, j) is
  // image.at(i, j), covering s in [i/width, (i+1)/width] and t in
  // [j/height, (j+1)/height]: row j is uploaded as the texture's row j.
  std::map<std::string, const Image*> textures2D;
  int width = 256;
  int height = 256;
  std::array<float, 4> clearColor{0, 0, 0, 0};
  bool cullBackFaces = true;
  // Values read back from the fragment stage, each into an RGBA32F target of
  // its own (core/fragment_probes.h inserts the writes into the listing).
  std::vector<FragmentProbe> probes;
};

struct RenderOutcome {
  CompileOutcome compile;     // !compile.ok => image is empty
  Image image;                // width x height, row 0 at the top; the fragment shader's output 0
  std::vector<Image> probes;  // one per RenderJob::probes, same layout; alpha 1 where written
};

class Backend {
 public:
  virtual ~Backend() = default;
  virtual std::string name() const = 0;  // its registered name: "gl", "gl:softpipe", "vk"
  virtual DriverInfo driverInfo() const = 0;

  // "" when this backend can run the program; otherwise the reason it cannot
  // (a GLSL version or profile its driver lacks), reported as NotSupported.
  virtual std::string whyCannotRun(const ProgramSource& /*program*/) const { return ""; }

  // Compiles (and links) the program without running it.
  virtual CompileOutcome compile(const ProgramSource& program) = 0;

  // Runs the vertex stage once per vertex and reads back the named outputs
  // as fp32, one value per vertex, in vertex order. Throws SetupError when
  // the API itself fails (not for a compile error).
  virtual CaptureOutcome captureVertexOutputs(const CaptureJob& job) = 0;

  // Renders the job; throws SetupError when the API itself fails.
  virtual RenderOutcome render(const RenderJob& job) = 0;
};

struct BackendOptions {
  bool validation = false;  // Vulkan: enable VK_LAYER_KHRONOS_validation, any message is an error
  // Vulkan: a physical device by name, index or vendor:device id (hex);
  // EGL device backends: a device index. Empty: the backend's own choice.
  std::string device = "";  // NOLINT(readability-redundant-string-init): keeps {.validation} quiet
  // OpenGL: "osmesa" or "egl" in place of the backend's own context provider.
  std::string glProvider = "";  // NOLINT(readability-redundant-string-init)
  // A folder the backend may keep compiled programs in between runs (the
  // run's oracle cache); empty: it keeps nothing.
  std::string cacheDir = "";  // NOLINT(readability-redundant-string-init)
};

// A registered backend by name (backend_registry.h), with its environment
// set first; throws UsageError for an unknown name, SetupError when the
// driver cannot be brought up on this machine.
std::unique_ptr<Backend> makeBackend(const std::string& name, const BackendOptions& options);

}  // namespace snell
