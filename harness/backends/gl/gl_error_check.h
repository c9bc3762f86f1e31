#pragma once
#include <string>

#include "backends/gl/gl_api.h"

namespace snell {

// Name of a GL error code, e.g. "GL_INVALID_OPERATION".
std::string glErrorName(GLenum error);

// Throws SetupError naming `call` when the GL error flag is set.
void throwOnGlError(const char* call);

// Remembers the first GL error of a sequence of calls that must all run (so
// that state is restored) before anything is thrown.
class GlErrorLog {
 public:
  void check(const char* call);
  void throwIfAny() const;

 private:
  std::string first_;
};

}  // namespace snell
