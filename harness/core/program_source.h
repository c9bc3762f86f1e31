#pragma once
// A listing's shader program as published, ready for any backend.
#include <string>

namespace snell {

enum class Profile { Core, Compatibility };

struct ProgramSource {
  std::string vertex;        // GLSL text, exactly as in the file
  std::string fragment;      // may be empty for capture-only probes
  std::string vertexPath;    // for diagnostics only
  std::string fragmentPath;
  Profile profile = Profile::Core;
};

}  // namespace snell
