#pragma once
// OpenGL through EGL with no window system: EGL_MESA_platform_surfaceless
// (Mesa's drivers, software ones with LIBGL_ALWAYS_SOFTWARE=1) or
// EGL_EXT_platform_device (one device by index, for machines with GPUs).
// The context is made current with no surface at all
// (EGL_KHR_surfaceless_context), so it has no default framebuffer.
#include <memory>
#include <string>
#include <vector>

#include "backends/gl/gl_context_provider.h"

namespace snell {

// Throws SetupError naming the missing extension or what to install.
std::unique_ptr<GlContext> createEglContext(bool onDevice, const GlContextRequest& request);

struct EglDeviceInfo {
  int index = 0;
  std::string drmNode;  // "/dev/dri/renderD128"; empty for a software device
  bool software = false;
  std::string extensions;
};

// The devices EGL_EXT_device_enumeration lists; throws SetupError when
// libEGL or the extension is missing.
std::vector<EglDeviceInfo> listEglDevices();

}  // namespace snell
