#pragma once
// What a backend can run, and the one rule that turns a listing it cannot
// run into NotSupported with the reason (instead of a compile failure).
#include <string>
#include <vector>

namespace snell {

// What a backend can run; a case that needs more is NotSupported with the
// reason instead of failing.
struct BackendCapabilities {
  std::string api;                   // "OpenGL" / "Vulkan"
  int coreVersion = 0;               // highest core profile it offers: 45 is 4.5, 13 is Vulkan 1.3
  int glslVersion = 0;               // highest `#version` it compiles: 450
  bool compatibilityProfile = true;  // legacy listings (no #version, GL's fixed-function state)
  std::vector<std::string> stages{"vertex", "fragment"};
  std::vector<std::string> captures;  // "transform-feedback", "fragment-probes"
};

// The number of a shader's `#version` line; 110 (GLSL 1.10) when it has none.
int glslVersionOf(const std::string& shaderText);

// "" when the backend can run the program; otherwise why not ("needs GLSL
// 4.60; softpipe offers OpenGL 3.3 core"), for a NotSupported result.
std::string whyBackendCannotRun(const BackendCapabilities& can, int programGlslVersion,
                                bool compatibilityProfile);

}  // namespace snell
