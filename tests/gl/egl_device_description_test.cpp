// What `snell devices` shows of an EGL device, from what the device told.
#include <gtest/gtest.h>

#include "backends/gl/egl_context.h"

namespace snell {
namespace {

TEST(EglDeviceDescription, NamesEachKindOfDevice) {
  EglDeviceInfo software;
  software.software = true;
  EXPECT_EQ(describeEglDevice(software).first, "software (Mesa llvmpipe/softpipe/zink)");

  EglDeviceInfo drm;
  drm.drmNode = "/dev/dri/renderD128";
  EXPECT_EQ(describeEglDevice(drm),
            (std::pair<std::string, std::string>{"/dev/dri/renderD128", "/dev/dri/renderD128"}));

  // NVIDIA's device in a container: EGL_EXT_device_drm with no node; the
  // name comes from EGL_EXT_device_query_name.
  EglDeviceInfo named;
  named.renderer = "NVIDIA H200/PCIe/SSE2";
  named.vendor = "NVIDIA";
  EXPECT_EQ(describeEglDevice(named),
            (std::pair<std::string, std::string>{"NVIDIA H200/PCIe/SSE2", "no DRM node, NVIDIA"}));

  EXPECT_EQ(describeEglDevice(EglDeviceInfo{}).first, "a device EGL names no further");
}

}  // namespace
}  // namespace snell
