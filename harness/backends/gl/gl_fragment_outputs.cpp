#include "backends/gl/gl_fragment_outputs.h"

#include <optional>

#include "core/fragment_probes.h"

namespace snell {

namespace {
bool isBuiltIn(const std::string& name) { return name.rfind("gl_", 0) == 0; }
}  // namespace

std::vector<GlFragmentOutput> queryFragmentOutputs(GLuint program) {
  GLint count = 0;
  GLint maxLength = 0;
  glGetProgramInterfaceiv(program, GL_PROGRAM_OUTPUT, GL_ACTIVE_RESOURCES, &count);
  glGetProgramInterfaceiv(program, GL_PROGRAM_OUTPUT, GL_MAX_NAME_LENGTH, &maxLength);
  std::vector<char> name(static_cast<std::size_t>(maxLength > 0 ? maxLength : 1));
  std::vector<GlFragmentOutput> outputs;
  for (GLint index = 0; index < count; ++index) {
    GLsizei length = 0;
    glGetProgramResourceName(program, GL_PROGRAM_OUTPUT, static_cast<GLuint>(index), maxLength,
                             &length, name.data());
    GlFragmentOutput output;
    output.name.assign(name.data(), static_cast<std::size_t>(length));
    if (isBuiltIn(output.name)) continue;
    const GLenum property = GL_LOCATION;
    glGetProgramResourceiv(program, GL_PROGRAM_OUTPUT, static_cast<GLuint>(index), 1, &property, 1,
                           nullptr, &output.location);
    outputs.push_back(std::move(output));
  }
  return outputs;
}

bool bindOutputLocations(GLuint program) {
  const std::vector<GlFragmentOutput> outputs = queryFragmentOutputs(program);
  std::vector<const GlFragmentOutput*> listingOutputs;
  bool moved = false;
  for (const GlFragmentOutput& output : outputs) {
    const std::optional<int> location = probeOutputLocation(output.name);
    if (!location) {
      listingOutputs.push_back(&output);
      continue;
    }
    if (output.location == *location) continue;
    glBindFragDataLocation(program, static_cast<GLuint>(*location), output.name.c_str());
    moved = true;
  }
  if (listingOutputs.size() == 1 && listingOutputs.front()->location != 0) {
    glBindFragDataLocation(program, 0, listingOutputs.front()->name.c_str());
    moved = true;
  }
  if (!moved) return true;
  glLinkProgram(program);
  GLint linked = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &linked);
  return linked == GL_TRUE;
}

}  // namespace snell
