#include "backends/gl/gl_driver_info.h"

#include "backends/gl/gl_api.h"

namespace snell {

namespace {
// The driver's version is the word pair GL_VERSION ends in: Mesa appends
// "Mesa x.y.z" (sometimes with a suffix such as "-devel" or " (git-abc)"),
// NVIDIA "NVIDIA x.y.z" ("4.6.0 NVIDIA 580.159.04").
std::string driverVersionOf(const std::string& version) {
  for (const char* vendor : {"Mesa ", "NVIDIA "}) {
    const auto start = version.find(vendor);
    if (start == std::string::npos) continue;
    const auto end = version.find(' ', start + std::string(vendor).size());
    return version.substr(start, end == std::string::npos ? std::string::npos : end - start);
  }
  return "";
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
  info.driverVersion = driverVersionOf(version);
  info.deviceType = deviceTypeOf(renderer);
  return info;
}

DriverInfo queryGlDriverInfo() {
  return parseGlDriverInfo(glString(GL_VERSION), glString(GL_RENDERER));
}

}  // namespace snell
