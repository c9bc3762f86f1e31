// The OpenGL backends: one driver each, told apart by the context provider
// and the environment their worker sets before the driver loads.
#include <fmt/format.h>

#include <algorithm>

#include "backends/backend_registry.h"
#include "backends/gl/egl_context.h"
#include "backends/gl/gl_backend.h"
#include "core/errors.h"

namespace snell {

namespace {

BackendCapabilities openGl(int coreVersion, int glslVersion, bool compatibility = true) {
  BackendCapabilities can;
  can.api = "OpenGL";
  can.coreVersion = coreVersion;
  can.glslVersion = glslVersion;
  can.compatibilityProfile = compatibility;
  can.captures = {"transform-feedback", "fragment-probes"};
  return can;
}

GlProviderKind providerFor(const BackendEntry& entry, GlProviderKind own,
                           const BackendOptions& options) {
  if (options.glProvider.empty() || own == GlProviderKind::EglDevice) return own;
  if (options.glProvider == "egl") return GlProviderKind::EglSurfaceless;
  if (options.glProvider == "osmesa") {
    // OSMesa 22.3 has no zink: it would crash on a null screen.
    for (const auto& [name, value] : entry.environment)
      if (name == "GALLIUM_DRIVER" && value == "zink")
        throw UsageError(
            fmt::format("{} runs through EGL only: drop --gl-provider osmesa", entry.name));
    return GlProviderKind::Osmesa;
  }
  throw UsageError(fmt::format("--gl-provider {}: use osmesa or egl", options.glProvider));
}

BackendEntry glEntry(std::string name, std::string description, GlProviderKind provider,
                     std::vector<std::pair<std::string, std::string>> environment,
                     BackendCapabilities can, std::string goldenKey, std::string rendererPrefix) {
  BackendEntry e;
  e.name = std::move(name);
  e.description = std::move(description);
  e.family = "gl";
  e.environment = std::move(environment);
  e.capabilities = std::move(can);
  e.goldenKey = std::move(goldenKey);
  // A device backend has its own display on the device it is given; the
  // others run on Mesa's software drivers, through either provider.
  e.takesDevice = provider == GlProviderKind::EglDevice;
  e.takesGlProvider = provider != GlProviderKind::EglDevice;
  e.make = [provider, rendererPrefix](const BackendEntry& entry, const BackendOptions& options) {
    const auto sets = [&](const char* name) {
      return std::any_of(entry.environment.begin(), entry.environment.end(),
                         [&](const auto& variable) { return variable.first == name; });
    };
    return makeGlBackend({entry.name, providerFor(entry, provider, options), entry.capabilities,
                          options.device, rendererPrefix, sets("GALLIUM_DRIVER"),
                          sets("LP_NATIVE_VECTOR_WIDTH")});
  };
  return e;
}

}  // namespace

std::vector<BackendEntry> glBackendEntries() {
  // LIBGL_ALWAYS_SOFTWARE keeps EGL's surfaceless platform on Mesa's
  // software drivers even where a GPU is present, so each name is one driver.
  std::vector<BackendEntry> out;
  out.push_back(glEntry("gl", "OpenGL 4.5 core on llvmpipe through OSMesa", GlProviderKind::Osmesa,
                        {}, openGl(45, 450), "gl", "llvmpipe"));
  out.push_back(glEntry("gl:egl", "OpenGL 4.5 core on llvmpipe through EGL (surfaceless)",
                        GlProviderKind::EglSurfaceless, {{"LIBGL_ALWAYS_SOFTWARE", "1"}},
                        openGl(45, 450), "gl", "llvmpipe"));
  out.push_back(glEntry("gl:llvmpipe-128", "llvmpipe generating 128-bit vector code (OSMesa)",
                        GlProviderKind::Osmesa, {{"LP_NATIVE_VECTOR_WIDTH", "128"}},
                        openGl(45, 450), "gl-llvmpipe-128", "llvmpipe"));
  out.push_back(glEntry("gl:softpipe", "OpenGL 3.3 core on softpipe (OSMesa)",
                        GlProviderKind::Osmesa, {{"GALLIUM_DRIVER", "softpipe"}}, openGl(33, 330),
                        "gl-softpipe", "softpipe"));
  out.push_back(glEntry("gl:zink", "OpenGL 4.6 core on zink over Vulkan (lavapipe) through EGL",
                        GlProviderKind::EglSurfaceless,
                        {{"LIBGL_ALWAYS_SOFTWARE", "1"}, {"GALLIUM_DRIVER", "zink"}},
                        openGl(46, 460), "gl-zink", "zink"));
  out.push_back(glEntry("gl:gpu",
                        "OpenGL on a GPU through EGL_EXT_platform_device (--device INDEX)",
                        GlProviderKind::EglDevice, {}, openGl(46, 460), "gl-gpu", ""));
  return out;
}

}  // namespace snell

namespace snell {

std::vector<DeviceListing> glDeviceListing() {
  std::vector<DeviceListing> out;
  try {
    for (const EglDeviceInfo& d : listEglDevices()) {
      auto [name, detail] = describeEglDevice(d);
      out.push_back({"EGL", d.index, std::move(name), std::move(detail)});
    }
  } catch (const std::exception& error) {
    out.push_back({"EGL", -1, "(none)", error.what()});
  }
  return out;
}

}  // namespace snell
