#include "backends/gl/gl_driver_info.h"

#include "backends/gl/gl_api.h"

namespace snell {

namespace {
// Mesa appends "Mesa x.y.z" (sometimes with a suffix such as "-devel" or
// " (git-abc)") to GL_VERSION; the driver version is that word pair.
std::string mesaVersion(const std::string& version) {
  const auto start = version.find("Mesa ");
  if (start == std::string::npos) return "";
  const auto end = version.find(' ', start + 5);
  return version.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

bool contains(const std::string& text, const char* word) {
  return text.find(word) != std::string::npos;
}

// Mesa's software rasterisers; OSMesa never drives anything else today, but
// the renderer string is what says so.
std::string deviceTypeOf(const std::string& renderer) {
  if (contains(renderer, "llvmpipe") || contains(renderer, "softpipe") ||
      contains(renderer, "swrast"))
    return "cpu";
  return "other";
}

std::string glString(GLenum name) {
  const GLubyte* text = glGetString(name);
  return text ? reinterpret_cast<const char*>(text) : "";
}
}  // namespace

DriverInfo parseGlDriverInfo(const std::string& version, const std::string& renderer) {
  DriverInfo info;
  info.api = "OpenGL";
  info.apiVersion = version;
  info.renderer = renderer;
  info.driverVersion = mesaVersion(version);
  info.deviceType = deviceTypeOf(renderer);
  return info;
}

DriverInfo queryGlDriverInfo() {
  return parseGlDriverInfo(glString(GL_VERSION), glString(GL_RENDERER));
}

}  // namespace snell
