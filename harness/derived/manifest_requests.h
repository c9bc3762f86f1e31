#pragma once
// What the derived oracle reads of a listing's manifest: a stage's GLSL
// text, and the values it is asked for there. The runner gates a listing's
// captures with these; the tests' adversarial machine runs the same.
#include <vector>

#include "core/manifest.h"
#include "derived/lower_glsl.h"

namespace snell::derived {

// The stage's text as the drivers compile it (core/manifest.h loadProgram).
ShaderSource stageSource(const Manifest& m, Stage stage);

// The vertex captures at the end of main(), or the fragment captures that
// are not the stage's inputs, each after its line (a fragment input is
// read back as it is: there is nothing to compute).
std::vector<OutputRequest> captureRequests(const Manifest& m, Stage stage);

}  // namespace snell::derived
