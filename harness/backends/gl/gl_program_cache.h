#pragma once
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "backends/backend.h"
#include "backends/gl/gl_program_build.h"
#include "backends/gl/gl_uniform_table.h"
#include "backends/gl/gl_varying_layout.h"

namespace snell {

// A linked program, with what captures and renders need to know about it,
// queried once. Captures link with their varyings declared for transform
// feedback; renders link with none.
struct GlLinkedProgram {
  GlProgram program;
  CompileOutcome compile;  // a failed build is cached too, so it is not retried per call
  GlVaryingLayout varyings;
  GlUniformTable uniforms;
  std::vector<GlFragmentOutput> fragmentOutputs;
  std::map<std::string, GLint> attributeLocations;  // filled on first use, -1 when absent

  GLint attributeLocation(const std::string& name);
};

// Linked programs of one context. `snell eval` sends thousands of
// small jobs with the same listing; compiling once turns each into a draw.
// The profile is part of the key by construction: each context (core,
// compatibility) has its own cache, as GL objects are per context. Entries
// live as long as the context; suites hold few distinct listings.
class GlProgramCache {
 public:
  // The context must be current. Throws UsageError when the program links
  // but one of its captured outputs cannot be read back as floats.
  GlLinkedProgram& get(const ProgramSource& source, const std::vector<std::string>& varyings);

  std::size_t size() const { return programs_.size(); }

 private:
  // Paths are in the key because they appear in the cached compile log.
  using Key = std::tuple<std::string, std::string, std::string, std::string, std::vector<std::string>>;
  std::map<Key, std::unique_ptr<GlLinkedProgram>> programs_;
};

}  // namespace snell
