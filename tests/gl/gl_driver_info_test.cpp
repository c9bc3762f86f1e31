#include "backends/gl/gl_driver_info.h"

#include <gtest/gtest.h>

#include "backends/gl/gl_backend.h"

namespace snell {
namespace {

TEST(GlDriverInfo, DescribesMesasSoftwareRasteriser) {
  auto backend = makeGlBackend({});
  const DriverInfo info = backend->driverInfo();
  EXPECT_EQ(backend->name(), "gl");
  EXPECT_EQ(info.api, "OpenGL");
  EXPECT_FALSE(info.apiVersion.empty());
  EXPECT_TRUE(info.renderer.find("llvmpipe") != std::string::npos ||
              info.renderer.find("softpipe") != std::string::npos)
      << info.renderer;
  EXPECT_EQ(info.driverVersion.rfind("Mesa ", 0), 0u) << info.driverVersion;
  EXPECT_NE(info.apiVersion.find(info.driverVersion), std::string::npos) << info.apiVersion;
  EXPECT_NE(info.apiVersion.find("Core Profile"), std::string::npos) << info.apiVersion;
  EXPECT_EQ(info.deviceType, "cpu");
}

TEST(GlDriverInfo, ParsesMesaReleaseVersion) {
  const DriverInfo info =
      parseGlDriverInfo("4.5 (Core Profile) Mesa 22.3.6", "llvmpipe (LLVM 15.0.6, 256 bits)");
  EXPECT_EQ(info.driverVersion, "Mesa 22.3.6");
  EXPECT_EQ(info.apiVersion, "4.5 (Core Profile) Mesa 22.3.6");
  EXPECT_EQ(info.renderer, "llvmpipe (LLVM 15.0.6, 256 bits)");
  EXPECT_EQ(info.deviceType, "cpu");
}

TEST(GlDriverInfo, ParsesMesaDevelopmentVersionWithoutGitSuffix) {
  const DriverInfo info =
      parseGlDriverInfo("3.3 (Core Profile) Mesa 23.1.0-devel (git-1a2b3c)", "softpipe");
  EXPECT_EQ(info.driverVersion, "Mesa 23.1.0-devel");
  EXPECT_EQ(info.deviceType, "cpu");
}

// As NVIDIA 580.159.04 answered on an H200 (gl:gpu).
TEST(GlDriverInfo, ReadsNvidiasDriverVersion) {
  const DriverInfo info = parseGlDriverInfo("4.6.0 NVIDIA 580.159.04", "NVIDIA H200/PCIe/SSE2");
  EXPECT_EQ(info.driverVersion, "NVIDIA 580.159.04");
  EXPECT_EQ(info.deviceType, "other");
}

TEST(GlDriverInfo, AnUnknownVendorHasNoDriverVersion) {
  const DriverInfo info =
      parseGlDriverInfo("4.6.14761 Compatibility Profile Context 21.40.2", "Radeon RX 6800");
  EXPECT_EQ(info.driverVersion, "");
  EXPECT_EQ(info.deviceType, "other");
}

}  // namespace
}  // namespace snell
