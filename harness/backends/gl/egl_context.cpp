#include "backends/gl/egl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdlib>
#include <map>
#include <utility>

#include "backends/gl/gl_api.h"
#include "core/errors.h"
#include "core/shared_library.h"

namespace snell {

namespace {
const char* const kInstallHint =
    "Install Mesa's EGL and DRI drivers (Debian: apt-get install libegl1 libegl-mesa0 "
    "libgl1-mesa-dri).";

struct EglLibrary {
  SharedLibrary library;
  decltype(&::eglGetProcAddress) getProcAddress;
  decltype(&::eglGetPlatformDisplay) getPlatformDisplay;
  decltype(&::eglInitialize) initialize;
  decltype(&::eglQueryString) queryString;
  decltype(&::eglBindAPI) bindAPI;
  decltype(&::eglChooseConfig) chooseConfig;
  decltype(&::eglCreateContext) createContext;
  decltype(&::eglDestroyContext) destroyContext;
  decltype(&::eglMakeCurrent) makeCurrent;
  decltype(&::eglGetCurrentContext) getCurrentContext;
  decltype(&::eglGetError) getError;
  PFNEGLQUERYDEVICESEXTPROC queryDevices = nullptr;
  PFNEGLQUERYDEVICESTRINGEXTPROC queryDeviceString = nullptr;
  GlFunctions gl;
  bool glLoaded = false;

  template <typename F>
  F load(const char* name) const {
    void* address = library.symbol(name);
    if (!address) throw SetupError(library.fileName() + " has no " + name + ". " + kInstallHint);
    return reinterpret_cast<F>(address);
  }

  explicit EglLibrary(SharedLibrary lib)
      : library(std::move(lib)),
        getProcAddress(load<decltype(getProcAddress)>("eglGetProcAddress")),
        getPlatformDisplay(load<decltype(getPlatformDisplay)>("eglGetPlatformDisplay")),
        initialize(load<decltype(initialize)>("eglInitialize")),
        queryString(load<decltype(queryString)>("eglQueryString")),
        bindAPI(load<decltype(bindAPI)>("eglBindAPI")),
        chooseConfig(load<decltype(chooseConfig)>("eglChooseConfig")),
        createContext(load<decltype(createContext)>("eglCreateContext")),
        destroyContext(load<decltype(destroyContext)>("eglDestroyContext")),
        makeCurrent(load<decltype(makeCurrent)>("eglMakeCurrent")),
        getCurrentContext(load<decltype(getCurrentContext)>("eglGetCurrentContext")),
        getError(load<decltype(getError)>("eglGetError")) {
    queryDevices =
        reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(getProcAddress("eglQueryDevicesEXT"));
    queryDeviceString =
        reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(getProcAddress("eglQueryDeviceStringEXT"));
  }
};

EglLibrary& egl() {
  static EglLibrary library(SharedLibrary::open({"libEGL.so.1", "libEGL.so"}, kInstallHint));
  return library;
}

std::string errorName(EGLint error) {
  switch (error) {
    case EGL_BAD_MATCH:
      return "EGL_BAD_MATCH";
    case EGL_BAD_ATTRIBUTE:
      return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
      return "EGL_BAD_CONFIG";
    case EGL_BAD_DISPLAY:
      return "EGL_BAD_DISPLAY";
    case EGL_NOT_INITIALIZED:
      return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ALLOC:
      return "EGL_BAD_ALLOC";
    case EGL_BAD_PARAMETER:
      return "EGL_BAD_PARAMETER";
    case EGL_BAD_ACCESS:
      return "EGL_BAD_ACCESS";
    default:
      return "EGL error " + std::to_string(error);
  }
}

bool hasExtension(const char* list, const std::string& name) {
  if (!list) return false;
  const std::string text = std::string(" ") + list + " ";
  return text.find(" " + name + " ") != std::string::npos;
}

std::vector<EGLDeviceEXT> devices() {
  EglLibrary& lib = egl();
  if (!lib.queryDevices || !lib.queryDeviceString)
    throw SetupError("libEGL has no EGL_EXT_device_enumeration. " + std::string(kInstallHint));
  EGLint count = 0;
  if (!lib.queryDevices(0, nullptr, &count))
    throw SetupError("eglQueryDevicesEXT failed: " + errorName(lib.getError()));
  std::vector<EGLDeviceEXT> list(static_cast<std::size_t>(count));
  lib.queryDevices(count, list.data(), &count);
  list.resize(static_cast<std::size_t>(count));
  return list;
}

// The device a --device index names, or the first one that is not software.
EGLDeviceEXT chooseDevice(const std::string& wanted) {
  const std::vector<EglDeviceInfo> infos = listEglDevices();
  const std::vector<EGLDeviceEXT> list = devices();
  if (!wanted.empty()) {
    char* end = nullptr;
    const long index = std::strtol(wanted.c_str(), &end, 10);
    if (*end != '\0' || index < 0 || index >= static_cast<long>(list.size()))
      throw UsageError("--device " + wanted + ": EGL devices are chosen by index, 0 to " +
                       std::to_string(static_cast<long>(list.size()) - 1) +
                       " here (`snell devices` lists them)");
    return list[static_cast<std::size_t>(index)];
  }
  for (const EglDeviceInfo& info : infos)
    if (!info.software) return list[static_cast<std::size_t>(info.index)];
  throw SetupError("no GPU among the " + std::to_string(list.size()) +
                   " EGL device(s) here (only software ones): pass --device INDEX to use one of "
                   "them, or install the GPU's Mesa or vendor driver");
}

// One display per platform and device for the process; never terminated,
// since drivers do not all survive eglTerminate with contexts alive elsewhere.
EGLDisplay display(bool onDevice, const std::string& wanted) {
  static std::map<std::string, EGLDisplay> displays;
  const std::string key = onDevice ? "device:" + wanted : "surfaceless";
  if (auto it = displays.find(key); it != displays.end()) return it->second;
  EglLibrary& lib = egl();
  const char* clientExtensions = lib.queryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  const char* platform = onDevice ? "EGL_EXT_platform_device" : "EGL_MESA_platform_surfaceless";
  if (!hasExtension(clientExtensions, platform))
    throw SetupError(std::string("libEGL does not offer ") + platform + ". " + kInstallHint);
  EGLDisplay dpy =
      onDevice
          ? lib.getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, chooseDevice(wanted), nullptr)
          : lib.getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  EGLint major = 0, minor = 0;
  if (dpy == EGL_NO_DISPLAY || !lib.initialize(dpy, &major, &minor))
    throw SetupError(std::string("eglInitialize failed on ") + platform + " (" +
                     errorName(lib.getError()) + "). " + kInstallHint);
  const char* extensions = lib.queryString(dpy, EGL_EXTENSIONS);
  if (!hasExtension(extensions, "EGL_KHR_surfaceless_context"))
    throw SetupError(
        "this EGL display lacks EGL_KHR_surfaceless_context: snell renders with no "
        "surface at all");
  if (!lib.bindAPI(EGL_OPENGL_API))
    throw SetupError("eglBindAPI(EGL_OPENGL_API) failed: this EGL offers no desktop OpenGL");
  return displays[key] = dpy;
}

EGLConfig config(EGLDisplay dpy) {
  EglLibrary& lib = egl();
  if (hasExtension(lib.queryString(dpy, EGL_EXTENSIONS), "EGL_KHR_no_config_context"))
    return EGL_NO_CONFIG_KHR;
  const EGLint attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig chosen = nullptr;
  EGLint count = 0;
  if (!lib.chooseConfig(dpy, attributes, &chosen, 1, &count) || count == 0)
    throw SetupError("eglChooseConfig found no OpenGL config");
  return chosen;
}

EGLContext create(EGLDisplay dpy, Profile profile, int major, int minor) {
  const EGLint mask = profile == Profile::Core ? EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT
                                               : EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT;
  std::vector<EGLint> attributes = {EGL_CONTEXT_OPENGL_PROFILE_MASK, mask};
  if (profile == Profile::Core)
    attributes.insert(attributes.end(),
                      {EGL_CONTEXT_MAJOR_VERSION, major, EGL_CONTEXT_MINOR_VERSION, minor});
  attributes.push_back(EGL_NONE);
  return egl().createContext(dpy, config(dpy), EGL_NO_CONTEXT, attributes.data());
}

void* lookupGl(const char* name, void* userData) {
  return reinterpret_cast<void*>(static_cast<EglLibrary*>(userData)->getProcAddress(name));
}

class EglContext final : public GlContext {
 public:
  EglContext(EGLDisplay dpy, EGLContext handle, std::string what)
      : display_(dpy), handle_(handle), what_(std::move(what)) {}
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;
  ~EglContext() override {
    EglLibrary& lib = egl();
    if (lib.getCurrentContext() == handle_)
      lib.makeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    lib.destroyContext(display_, handle_);
  }

  void makeCurrent() override {
    EglLibrary& lib = egl();
    if ((!wasMadeCurrentLast() || lib.getCurrentContext() != handle_) &&
        !lib.makeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, handle_))
      throw SetupError("eglMakeCurrent failed for the " + what_ + " context (" +
                       errorName(lib.getError()) + ")");
    if (!lib.glLoaded) {
      lib.gl = loadGlFunctions(lookupGl, &lib, "EGL");
      lib.glLoaded = true;
    }
    currentGlFunctions = &lib.gl;
    madeCurrent();
  }

  std::string what() const override { return what_; }

 private:
  EGLDisplay display_;
  EGLContext handle_;
  std::string what_;
};
}  // namespace

std::vector<EglDeviceInfo> listEglDevices() {
  EglLibrary& lib = egl();
  std::vector<EglDeviceInfo> out;
  const std::vector<EGLDeviceEXT> list = devices();
  for (std::size_t k = 0; k < list.size(); ++k) {
    EglDeviceInfo info;
    info.index = static_cast<int>(k);
    const char* extensions = lib.queryDeviceString(list[k], EGL_EXTENSIONS);
    info.extensions = extensions ? extensions : "";
    info.software = hasExtension(extensions, "EGL_MESA_device_software");
    if (hasExtension(extensions, "EGL_EXT_device_drm")) {
      const char* node = lib.queryDeviceString(list[k], EGL_DRM_DEVICE_FILE_EXT);
      info.drmNode = node ? node : "";
    }
    if (hasExtension(extensions, "EGL_EXT_device_query_name")) {
      constexpr EGLint kRendererExt = 0x335F;  // EGL_RENDERER_EXT
      const char* renderer = lib.queryDeviceString(list[k], kRendererExt);
      const char* vendor = lib.queryDeviceString(list[k], EGL_VENDOR);
      info.renderer = renderer ? renderer : "";
      info.vendor = vendor ? vendor : "";
    }
    out.push_back(std::move(info));
  }
  return out;
}

std::pair<std::string, std::string> describeEglDevice(const EglDeviceInfo& device) {
  if (device.software)
    return {"software (Mesa llvmpipe/softpipe/zink)", "EGL_MESA_device_software"};
  std::string name = !device.renderer.empty()  ? device.renderer
                     : !device.drmNode.empty() ? device.drmNode
                                               : "a device EGL names no further";
  std::string detail = device.drmNode.empty() ? "no DRM node" : device.drmNode;
  if (!device.vendor.empty()) detail += ", " + device.vendor;
  return {name, detail};
}

std::unique_ptr<GlContext> createEglContext(bool onDevice, const GlContextRequest& request) {
  EGLDisplay dpy = display(onDevice, request.device);
  const std::string through = onDevice ? " (EGL device)" : " (EGL surfaceless)";
  if (request.profile == Profile::Compatibility) {
    if (EGLContext handle = create(dpy, Profile::Compatibility, 0, 0))
      return std::make_unique<EglContext>(dpy, handle, "OpenGL compatibility" + through);
    throw SetupError("EGL could not create an OpenGL compatibility context (" +
                     errorName(egl().getError()) + ")");
  }
  const int major = request.coreMajor, minor = request.coreMinor;
  if (EGLContext handle = create(dpy, Profile::Core, major, minor))
    return std::make_unique<EglContext>(
        dpy, handle,
        "OpenGL " + std::to_string(major) + "." + std::to_string(minor) + " core" + through);
  const std::string firstError = errorName(egl().getError());
  if (major * 10 + minor > 33)
    if (EGLContext handle = create(dpy, Profile::Core, 3, 3))
      return std::make_unique<EglContext>(dpy, handle, "OpenGL 3.3 core" + through);
  throw SetupError("EGL could not create an OpenGL " + std::to_string(major) + "." +
                   std::to_string(minor) + " core context (" + firstError +
                   "), nor 3.3: the driver offers no core profile");
}

}  // namespace snell
