#include "backends/gl/osmesa_context.h"

// gl_api.h before GL/osmesa.h: it asks GL/glext.h (included once) for the
// prototypes that gl_functions.h takes the types of.
// clang-format off
#include "backends/gl/gl_api.h"
#include <GL/osmesa.h>
// clang-format on

#include <cstdlib>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "core/shared_library.h"

namespace snell {

namespace {
constexpr int kBufferSide = 4;

const char* const kInstallHint =
    " Install Mesa's off-screen GL (Debian: apt-get install libosmesa6), and check that"
    " GALLIUM_DRIVER is unset, llvmpipe or softpipe.";

// The OSMesa entry points, and the GL table loaded through it once.
struct OsmesaLibrary {
  SharedLibrary library;
  decltype(&::OSMesaCreateContextAttribs) createContextAttribs;
  decltype(&::OSMesaMakeCurrent) makeCurrent;
  decltype(&::OSMesaGetCurrentContext) getCurrentContext;
  decltype(&::OSMesaDestroyContext) destroyContext;
  decltype(&::OSMesaGetProcAddress) getProcAddress;
  GlFunctions gl;
  bool glLoaded = false;

  template <typename F>
  F load(const char* name) const {
    void* address = library.symbol(name);
    if (!address)
      throw SetupError(library.fileName() + " has no " + name + ": not an OSMesa library." +
                       kInstallHint);
    return reinterpret_cast<F>(address);
  }

  explicit OsmesaLibrary(SharedLibrary lib)
      : library(std::move(lib)),
        createContextAttribs(load<decltype(createContextAttribs)>("OSMesaCreateContextAttribs")),
        makeCurrent(load<decltype(makeCurrent)>("OSMesaMakeCurrent")),
        getCurrentContext(load<decltype(getCurrentContext)>("OSMesaGetCurrentContext")),
        destroyContext(load<decltype(destroyContext)>("OSMesaDestroyContext")),
        getProcAddress(load<decltype(getProcAddress)>("OSMesaGetProcAddress")) {}
};

OsmesaLibrary& osmesa() {
  static OsmesaLibrary library(
      SharedLibrary::open({"libOSMesa.so.8", "libOSMesa.so"}, kInstallHint));
  return library;
}

void* lookupGl(const char* name, void* userData) {
  auto& lib = *static_cast<OsmesaLibrary*>(userData);
  if (OSMESAproc address = lib.getProcAddress(name)) return reinterpret_cast<void*>(address);
  return lib.library.symbol(name);  // libOSMesa exports every gl* entry point too
}

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
                   " is not a driver OSMesa offers: unset it, set llvmpipe or softpipe, or use"
                   " --gl-provider egl.");
}

OSMesaContext createCore(int major, int minor) {
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            0,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            major,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            minor,
                            0};
  return osmesa().createContextAttribs(attributes, nullptr);
}

OSMesaContext createCompatibility() {
  const int attributes[] = {
      OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_PROFILE, OSMESA_COMPAT_PROFILE, 0};
  return osmesa().createContextAttribs(attributes, nullptr);
}

// The small colour buffer OSMesaMakeCurrent needs; pixels are read from
// framebuffer objects, never from it.
class OsmesaContext final : public GlContext {
 public:
  OsmesaContext(OSMesaContext handle, std::string what)
      : handle_(handle), what_(std::move(what)), colour_(kBufferSide * kBufferSide * 4) {}
  OsmesaContext(const OsmesaContext&) = delete;
  OsmesaContext& operator=(const OsmesaContext&) = delete;
  ~OsmesaContext() override {
    OsmesaLibrary& lib = osmesa();
    if (lib.getCurrentContext() == handle_) lib.makeCurrent(nullptr, nullptr, 0, 0, 0);
    lib.destroyContext(handle_);
  }

  void makeCurrent() override {
    OsmesaLibrary& lib = osmesa();
    if ((!wasMadeCurrentLast() || lib.getCurrentContext() != handle_) &&
        !lib.makeCurrent(handle_, colour_.data(), GL_UNSIGNED_BYTE, kBufferSide, kBufferSide))
      throw SetupError("OSMesaMakeCurrent failed for the " + what_ + " context." + kInstallHint);
    if (!lib.glLoaded) {
      lib.gl = loadGlFunctions(lookupGl, &lib, "OSMesa");
      lib.glLoaded = true;
    }
    currentGlFunctions = &lib.gl;
    madeCurrent();
  }

  std::string what() const override { return what_; }

 private:
  OSMesaContext handle_;
  std::string what_;
  std::vector<unsigned char> colour_;
};
}  // namespace

std::unique_ptr<GlContext> createOsmesaContext(const GlContextRequest& request) {
  checkGalliumDriver();
  if (request.profile == Profile::Compatibility) {
    OSMesaContext handle = createCompatibility();
    if (!handle)
      throw SetupError(std::string("OSMesa could not create an OpenGL compatibility context.") +
                       kInstallHint);
    return std::make_unique<OsmesaContext>(handle, "OpenGL compatibility (OSMesa)");
  }
  const bool above33 = request.coreMajor * 10 + request.coreMinor > 33;
  if (above33) {
    if (OSMesaContext handle = createCore(request.coreMajor, request.coreMinor))
      return std::make_unique<OsmesaContext>(handle, "OpenGL " + std::to_string(request.coreMajor) +
                                                         "." + std::to_string(request.coreMinor) +
                                                         " core (OSMesa)");
  }
  if (OSMesaContext handle = createCore(3, 3))
    return std::make_unique<OsmesaContext>(handle, "OpenGL 3.3 core (OSMesa)");
  throw SetupError(std::string("OSMesa could not create an OpenGL core context (asked for ") +
                   std::to_string(request.coreMajor) + "." + std::to_string(request.coreMinor) +
                   (above33 ? ", then 3.3)." : ").") + kInstallHint);
}

}  // namespace snell
