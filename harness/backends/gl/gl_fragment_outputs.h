#pragma once
#include <string>
#include <vector>

#include "backends/gl/gl_api.h"

namespace snell {

// A fragment shader output the listing declares (`out vec4 FragColor;`);
// legacy gl_FragColor and gl_FragData are not listed.
struct GlFragmentOutput {
  std::string name;
  GLint location = -1;
};

// The declared outputs of a linked program whose last stage is a fragment
// shader.
std::vector<GlFragmentOutput> queryFragmentOutputs(GLuint program);

// Renders read colour attachment 0, and probe k's output (snell_probe_k,
// core/fragment_probes.h) from attachment k. An output with no layout goes
// wherever the linker puts it, which the spec leaves open; so each probe is
// bound to its location by name, the listing's lone output to 0, and the
// program relinked when anything moved (a layout qualifier still wins).
// Returns false when that relink fails.
bool bindOutputLocations(GLuint program);

}  // namespace snell
