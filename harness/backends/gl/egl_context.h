#pragma once
// OpenGL through EGL with no window system: EGL_MESA_platform_surfaceless
// (Mesa's drivers, software ones with LIBGL_ALWAYS_SOFTWARE=1) or
// EGL_EXT_platform_device (one device by index, for machines with GPUs).
// The context is made current with no surface at all
// (EGL_KHR_surfaceless_context), so it has no default framebuffer.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "backends/gl/gl_context_provider.h"

namespace snell {

// Throws SetupError naming the missing extension or what to install.
std::unique_ptr<GlContext> createEglContext(bool onDevice, const GlContextRequest& request);

struct EglDeviceInfo {
  int index = 0;
  std::string drmNode;  // "/dev/dri/renderD128"; empty for a software device
  // EGL_EXT_device_query_name's renderer and vendor, where the device offers
  // it: NVIDIA's device names no DRM node inside a container.
  std::string renderer;
  std::string vendor;
  bool software = false;
  std::string extensions;
};

// What `snell devices` shows of a device: its name and its detail.
std::pair<std::string, std::string> describeEglDevice(const EglDeviceInfo& device);

// The devices EGL_EXT_device_enumeration lists; throws SetupError when
// libEGL or the extension is missing.
std::vector<EglDeviceInfo> listEglDevices();

}  // namespace snell
