#pragma once
// The vertex shader `snell eval` runs on a driver to probe one built-in:
// every input is a vertex attribute, so one draw answers many lines.
#include <string>

#include "core/program_source.h"

namespace snell {

// fn is "reflect" or "refract"; width 1 to 4 (float, vec2, vec3, vec4).
// Inputs: I, N (and eta for refract); output: R.
ProgramSource builtinProbeProgram(const std::string& fn, int width);

}  // namespace snell
