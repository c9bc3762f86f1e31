#include "backends/gl/gl_error_check.h"

#include <cstdio>

#include "core/errors.h"

namespace snell {

std::string glErrorName(GLenum error) {
  switch (error) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: {
      char hex[16];
      std::snprintf(hex, sizeof hex, "0x%04X", error);
      return hex;
    }
  }
}

namespace {
// glGetError may hold several flags; all are drained so that the next check
// does not blame its own call for an older error.
std::string drainGlErrors() {
  std::string names;
  for (GLenum error = glGetError(); error != GL_NO_ERROR; error = glGetError()) {
    if (!names.empty()) names += ", ";
    names += glErrorName(error);
  }
  return names;
}

std::string describe(const char* call, const std::string& errors) {
  return std::string("OpenGL error ") + errors + " after " + call;
}
}  // namespace

void throwOnGlError(const char* call) {
  const std::string errors = drainGlErrors();
  if (!errors.empty()) throw SetupError(describe(call, errors));
}

void GlErrorLog::check(const char* call) {
  const std::string errors = drainGlErrors();
  if (!errors.empty() && first_.empty()) first_ = describe(call, errors);
}

void GlErrorLog::throwIfAny() const {
  if (!first_.empty()) throw SetupError(first_);
}

}  // namespace snell
