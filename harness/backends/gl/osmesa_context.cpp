#include "backends/gl/osmesa_context.h"

#include <cstdlib>
#include <utility>

#include "core/errors.h"

namespace snell {

namespace {
constexpr int kBufferSide = 4;

const char* const kInstallHint =
    " Install Mesa's off-screen GL (Debian: apt-get install libosmesa6 libosmesa6-dev),"
    " check that GALLIUM_DRIVER is unset, llvmpipe or softpipe, and that the program"
    " links libOSMesa only (not libGL as well).";

std::string galliumDriver() {
  const char* driver = std::getenv("GALLIUM_DRIVER");
  return driver ? driver : "";
}

// libOSMesa 22.3 dereferences a null screen inside OSMesaCreateContextAttribs
// when GALLIUM_DRIVER names a driver it was not built with (zink, swr, a
// typo): the process dies with SIGSEGV. Refusing up front gives a message.
void checkGalliumDriver() {
  const std::string driver = galliumDriver();
  if (driver.empty() || driver == "llvmpipe" || driver == "softpipe") return;
  throw SetupError("GALLIUM_DRIVER=" + driver +
                   " is not a driver OSMesa offers: unset it, or set llvmpipe or softpipe.");
}

OSMesaContext createCore(int major, int minor) {
  const int attributes[] = {OSMESA_FORMAT,  OSMESA_RGBA,
                            OSMESA_DEPTH_BITS, 0,
                            OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION, major,
                            OSMESA_CONTEXT_MINOR_VERSION, minor,
                            0};
  return OSMesaCreateContextAttribs(attributes, nullptr);
}

OSMesaContext createCompatibility() {
  const int attributes[] = {OSMESA_FORMAT,  OSMESA_RGBA,
                            OSMESA_DEPTH_BITS, 0,
                            OSMESA_PROFILE, OSMESA_COMPAT_PROFILE,
                            0};
  return OSMesaCreateContextAttribs(attributes, nullptr);
}
}  // namespace

OsmesaContext OsmesaContext::create(Profile profile) {
  checkGalliumDriver();
  if (profile == Profile::Compatibility) {
    OSMesaContext handle = createCompatibility();
    if (!handle)
      throw SetupError(std::string("OSMesa could not create an OpenGL compatibility context.") +
                       kInstallHint);
    return OsmesaContext(handle, "OpenGL compatibility");
  }
  // softpipe stops at 3.3 core; asking it for 4.5 just fails.
  if (galliumDriver() != "softpipe") {
    if (OSMesaContext handle = createCore(4, 5)) return OsmesaContext(handle, "OpenGL 4.5 core");
  }
  if (OSMesaContext handle = createCore(3, 3)) return OsmesaContext(handle, "OpenGL 3.3 core");
  throw SetupError(
      std::string("OSMesa could not create an OpenGL core context (asked for 4.5, then 3.3).") +
      kInstallHint);
}

OsmesaContext::OsmesaContext(OSMesaContext handle, std::string what)
    : handle_(handle), what_(std::move(what)), colour_(kBufferSide * kBufferSide * 4) {}

OsmesaContext::OsmesaContext(OsmesaContext&& other) noexcept
    : handle_(std::exchange(other.handle_, nullptr)),
      what_(std::move(other.what_)),
      colour_(std::move(other.colour_)) {}

OsmesaContext::~OsmesaContext() {
  if (!handle_) return;
  if (OSMesaGetCurrentContext() == handle_) OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(handle_);
}

void OsmesaContext::makeCurrent() {
  if (OSMesaGetCurrentContext() == handle_) return;
  if (!OSMesaMakeCurrent(handle_, colour_.data(), GL_UNSIGNED_BYTE, kBufferSide, kBufferSide))
    throw SetupError("OSMesaMakeCurrent failed for the " + what_ + " context." + kInstallHint);
  // With libGL linked next to libOSMesa, GL calls go to libGL's dispatch,
  // which has no context: every query returns NULL instead of failing.
  if (!glGetString(GL_VERSION))
    throw SetupError("glGetString(GL_VERSION) returned NULL on a current " + what_ +
                     " context: link libOSMesa only, never libGL as well.");
}

}  // namespace snell
