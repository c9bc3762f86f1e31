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

// Renders read colour attachment 0. A lone output with no layout goes
// wherever the linker puts it, which the spec leaves open; when that is not
// location 0, the output is bound there and the program relinked (a layout
// qualifier still wins). Returns false when that relink fails.
bool bindLoneOutputToZero(GLuint program);

}  // namespace snell
