#pragma once
#include <string>

#include "backends/backend.h"

namespace snell {

// Builds DriverInfo from the GL_VERSION and GL_RENDERER strings, e.g.
// "4.5 (Core Profile) Mesa 22.3.6" and "llvmpipe (LLVM 15.0.6, 256 bits)".
// Kept free of GL calls so the parsing can be tested on its own.
DriverInfo parseGlDriverInfo(const std::string& version, const std::string& renderer);

// Queries the current context.
DriverInfo queryGlDriverInfo();

}  // namespace snell
