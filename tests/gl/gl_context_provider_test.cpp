// The context providers: EGL (surfaceless, on llvmpipe) gives the same
// capture and the same pixels as OSMesa through the same function table,
// the two interleave in one process, and a provider that lacks an entry
// point or a library is a SetupError naming it.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <string>

#include "backends/gl/egl_context.h"
#include "backends/gl/gl_api.h"
#include "backends/gl/gl_backend.h"
#include "core/errors.h"
#include "core/shared_library.h"
#include "gl_render_test_jobs.h"
#include "gl_test_jobs.h"

namespace snell {
namespace {

const char* const kReflect =
    "#version 140\nin vec3 I;\nout vec3 R;\n"
    "void main() { R = reflect(I, vec3(0.0, 1.0, 0.0)); gl_Position = vec4(0.0); }\n";

std::unique_ptr<Backend> eglBackend() {
  setenv("LIBGL_ALWAYS_SOFTWARE", "1", 1);  // llvmpipe, as the gl:egl backend asks
  GlBackendConfig config;
  config.name = "gl:egl";
  config.provider = GlProviderKind::EglSurfaceless;
  return makeGlBackend(config);
}

CaptureJob reflectJob() {
  CaptureJob job;
  job.program = gltest::vertexOnly(kReflect);
  gltest::addAttribute(job, gltest::attribute("I", 3, {0.6f, -0.8f, 0.0f, 0.1f, -0.2f, 0.3f}));
  job.varyings = {"R"};
  job.vertexCount = 2;
  return job;
}

TEST(GlContextProvider, EglSurfacelessRunsOnLlvmpipe) {
  auto backend = eglBackend();
  EXPECT_EQ(backend->name(), "gl:egl");
  EXPECT_NE(backend->driverInfo().renderer.find("llvmpipe"), std::string::npos)
      << backend->driverInfo().renderer;
  EXPECT_NE(backend->driverInfo().apiVersion.find("Core Profile"), std::string::npos);
}

// A capture draws with rasterisation discarded; a surfaceless context has
// no default framebuffer, so it draws into the capture's own one.
TEST(GlContextProvider, EglAndOsmesaCaptureTheSameFloatsInterleaved) {
  auto osmesa = makeGlBackend({});
  auto egl = eglBackend();
  for (int round = 0; round < 3; ++round) {
    const CaptureOutcome a = osmesa->captureVertexOutputs(reflectJob());
    const CaptureOutcome b = egl->captureVertexOutputs(reflectJob());
    ASSERT_TRUE(a.compile.ok && b.compile.ok) << a.compile.log << b.compile.log;
    EXPECT_EQ(a.varyings.at(0).data, b.varyings.at(0).data) << "round " << round;
    EXPECT_EQ(a.varyings.at(0).data.at(1), 0.8f);  // reflect flips y: exact in fp32
  }
}

TEST(GlContextProvider, EglAndOsmesaRenderTheSamePixels) {
  auto osmesa = makeGlBackend({});
  auto egl = eglBackend();
  gltest::Triangles triangles;
  triangles.fullScreen(0.5f, {0.25f, 0.5f, 0.75f, 1.0f});
  triangles.add({-1, -1, 0.25f}, {1, -1, 0.25f}, {0, 1, 0.25f}, {1.0f, 0.125f, 0.0f, 1.0f});
  const RenderJob job = gltest::flatColourJob(triangles, 16, 8);
  const RenderOutcome a = osmesa->render(job);
  const RenderOutcome b = egl->render(job);
  ASSERT_TRUE(a.compile.ok && b.compile.ok) << a.compile.log << b.compile.log;
  EXPECT_EQ(a.image.pixels, b.image.pixels);
  EXPECT_EQ(gltest::pixel(b.image, 0, 0)[2], 0.75f);   // a corner the nearer triangle misses
  EXPECT_EQ(gltest::pixel(b.image, 8, 6)[1], 0.125f);  // inside the nearer triangle
}

TEST(GlContextProvider, EglListsAtLeastTheSoftwareDevice) {
  const std::vector<EglDeviceInfo> devices = listEglDevices();
  ASSERT_FALSE(devices.empty());
  bool software = false;
  for (const EglDeviceInfo& d : devices) software |= d.software;
  EXPECT_TRUE(software);
}

TEST(GlContextProvider, AMissingEntryPointIsASetupErrorNamingIt) {
  const auto allButOne = [](const char* name, void*) -> void* {
    static int dummy = 0;
    return std::strcmp(name, "glDrawBuffers") == 0 ? nullptr : &dummy;
  };
  try {
    loadGlFunctions(allButOne, nullptr, "TestProvider");
    FAIL() << "expected SetupError";
  } catch (const SetupError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("glDrawBuffers"), std::string::npos) << message;
    EXPECT_NE(message.find("TestProvider"), std::string::npos) << message;
  }
}

TEST(GlContextProvider, AMissingLibraryIsASetupErrorWithTheHint) {
  try {
    SharedLibrary::open({"libsnell-no-such-gl.so.1"}, "Install it.");
    FAIL() << "expected SetupError";
  } catch (const SetupError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("libsnell-no-such-gl.so.1"), std::string::npos) << message;
    EXPECT_NE(message.find("Install it."), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace snell
