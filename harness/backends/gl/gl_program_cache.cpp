#include "backends/gl/gl_program_cache.h"

#include "backends/gl/gl_error_check.h"

namespace snell {

GLint GlLinkedProgram::attributeLocation(const std::string& name) {
  const auto found = attributeLocations.find(name);
  if (found != attributeLocations.end()) return found->second;
  const GLint location = glGetAttribLocation(program.id(), name.c_str());
  attributeLocations.emplace(name, location);
  return location;
}

GlLinkedProgram& GlProgramCache::get(const ProgramSource& source,
                                      const std::vector<std::string>& varyings) {
  Key key{source.vertex, source.fragment, source.vertexPath, source.fragmentPath, varyings};
  const auto found = programs_.find(key);
  if (found != programs_.end()) return *found->second;

  BuiltProgram built = buildGlProgram(source, varyings);
  auto entry = std::make_unique<GlLinkedProgram>();
  if (built.outcome.ok) {
    entry->varyings = GlVaryingLayout::query(built.program.id());
    entry->uniforms = GlUniformTable(built.program.id());
    throwOnGlError("querying the linked program's uniforms and outputs");
  }
  entry->fragmentOutputs = std::move(built.fragmentOutputs);
  entry->program = std::move(built.program);
  entry->compile = std::move(built.outcome);
  return *programs_.emplace(std::move(key), std::move(entry)).first->second;
}

}  // namespace snell
