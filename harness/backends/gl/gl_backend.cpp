#include "backends/gl/gl_backend.h"

#include <fmt/format.h>

#include <cstdlib>
#include <iterator>
#include <memory>
#include <utility>

#include "backends/driver_variables.h"
#include "backends/gl/gl_context_state.h"
#include "backends/gl/gl_driver_info.h"
#include "backends/gl/gl_named_driver.h"
#include "core/errors.h"
#include "core/phase_clock.h"

namespace snell {

namespace {

// Contexts are made once per backend and reused across calls: bringing up a
// context costs far more than a capture. The compatibility context only
// serves legacy listings, so it is made on first use.
class GlBackend final : public Backend {
 public:
  explicit GlBackend(GlBackendConfig config)
      : config_(std::move(config)),
        core_(createGlContext(config_.provider, request(Profile::Core))) {
    core_.makeCurrent();
    info_ = queryGlDriverInfo();
    const auto user = [](bool ownVariable, const char* name) {
      const char* value = ownVariable ? nullptr : std::getenv(name);
      return std::string(value ? value : "");
    };
    if (std::string why = whyNotTheNamedDriver(
            config_.name, config_.rendererPrefix, info_,
            {user(config_.setsGalliumDriver, "GALLIUM_DRIVER"),
             user(config_.setsVectorWidth, "LP_NATIVE_VECTOR_WIDTH"),
             driverVariableSetBy("GALLIUM_DRIVER"), driverVariableSetBy("LP_NATIVE_VECTOR_WIDTH")});
        !why.empty())
      throw SetupError(why);
    // Mesa reads LP_NATIVE_VECTOR_WIDTH once per process: where llvmpipe
    // was already up at another width (`snell bench` with gl before
    // gl:llvmpipe-128), the backend's own setting did not take.
    if (const char* width = std::getenv("LP_NATIVE_VECTOR_WIDTH");
        config_.setsVectorWidth && width &&
        info_.renderer.find(fmt::format("{} bits", width)) == std::string::npos)
      throw SetupError(fmt::format(
          "{} is llvmpipe {} bits wide, but its context came up on {}: llvmpipe was already up "
          "in this process at another width; run {} in a command of its own",
          config_.name, width, info_.renderer, config_.name));
  }

  std::string name() const override { return config_.name; }
  DriverInfo driverInfo() const override { return info_; }

  std::string whyCannotRun(const ProgramSource& program) const override {
    return whyBackendCannotRun(config_.capabilities, glslVersionOf(program.vertex),
                               program.profile == Profile::Compatibility);
  }

  CompileOutcome compile(const ProgramSource& program) override {
    stateFor(program.profile);
    const PhaseScope phase(Phase::Compile);
    return buildGlProgram(program, {}).outcome;
  }

  CaptureOutcome captureVertexOutputs(const CaptureJob& job) override {
    GlContextState& state = stateFor(job.program.profile);
    GlLinkedProgram& program = [&]() -> GlLinkedProgram& {
      const PhaseScope phase(Phase::Compile);
      return state.programs().get(job.program, job.varyings);
    }();
    CaptureOutcome outcome;
    outcome.compile = program.compile;
    if (!outcome.compile.ok) return outcome;
    outcome.varyings = state.capture().run(program, job);
    return outcome;
  }

  // Renders link with no feedback varyings, so a listing that is both
  // captured and rendered is linked twice; each link is cached.
  // Probes are written into the fragment text before it is compiled
  // (core/fragment_probes.h); the style follows the listing's own output.
  RenderOutcome render(const RenderJob& job) override {
    GlContextState& state = stateFor(job.program.profile);
    ProgramSource source = job.program;
    if (!job.probes.empty())
      source.fragment = insertFragmentProbes(source.fragment, source.fragmentPath, job.probes,
                                             probeOutputStyleFor(source.fragment));
    GlLinkedProgram& program = [&]() -> GlLinkedProgram& {
      const PhaseScope phase(Phase::Compile);
      return state.programs().get(source, {});
    }();
    RenderOutcome outcome;
    outcome.compile = program.compile;
    if (!outcome.compile.ok) return outcome;
    std::vector<Image> images = state.renderer().run(program, job);
    outcome.image = std::move(images.front());
    outcome.probes.assign(std::make_move_iterator(images.begin() + 1),
                          std::make_move_iterator(images.end()));
    return outcome;
  }

 private:
  GlContextState& stateFor(Profile profile) {
    if (profile == Profile::Core) {
      core_.makeCurrent();
      return core_;
    }
    if (!compatibility_)
      compatibility_ = std::make_unique<GlContextState>(
          createGlContext(config_.provider, request(Profile::Compatibility)));
    compatibility_->makeCurrent();
    return *compatibility_;
  }

  GlContextRequest request(Profile profile) const {
    return {profile, config_.capabilities.coreVersion / 10, config_.capabilities.coreVersion % 10,
            config_.device};
  }

  GlBackendConfig config_;
  GlContextState core_;
  std::unique_ptr<GlContextState> compatibility_;
  DriverInfo info_;
};

}  // namespace

std::unique_ptr<Backend> makeGlBackend(const GlBackendConfig& config) {
  return std::make_unique<GlBackend>(config);
}

}  // namespace snell
