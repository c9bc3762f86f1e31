#pragma once
#include <memory>
#include <string>

#include "backends/backend.h"
#include "backends/backend_registry.h"
#include "backends/gl/gl_context_provider.h"

namespace snell {

// OpenGL on whichever driver the provider and the environment select.
struct GlBackendConfig {
  std::string name = "gl";  // the registered name
  GlProviderKind provider = GlProviderKind::Osmesa;
  // coreVersion is the core version asked for (3.3 is the fallback).
  BackendCapabilities capabilities{
      "OpenGL", 45, 450, true, {"vertex", "fragment"}, {"transform-feedback", "fragment-probes"}};
  std::string device;  // EglDevice: the device index
  // What GL_RENDERER starts with on the driver the name stands for
  // (gl_named_driver.h); empty: any driver (gl:gpu).
  std::string rendererPrefix;
  // Whether the backend's own environment sets GALLIUM_DRIVER: then a
  // value there is snell's, not one the user left to unset.
  bool setsGalliumDriver = false;
  // Whether it sets LP_NATIVE_VECTOR_WIDTH: llvmpipe at another width is
  // another driver (gl:llvmpipe-128), with goldens of its own.
  bool setsVectorWidth = false;
};

std::unique_ptr<Backend> makeGlBackend(const GlBackendConfig& config);

}  // namespace snell
