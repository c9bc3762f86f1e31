#pragma once
#include <string>
#include <vector>

#include "backends/backend.h"
#include "backends/gl/gl_api.h"
#include "backends/gl/gl_fragment_outputs.h"

namespace snell {

// Owns a GL program object. Must be destroyed while its context is current.
class GlProgram {
 public:
  GlProgram() = default;
  explicit GlProgram(GLuint id) : id_(id) {}
  GlProgram(GlProgram&& other) noexcept;
  GlProgram& operator=(GlProgram&& other) noexcept;
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;
  ~GlProgram();

  GLuint id() const { return id_; }

 private:
  GLuint id_ = 0;
};

struct BuiltProgram {
  GlProgram program;       // id 0 unless outcome.ok
  CompileOutcome outcome;  // logs prefixed by stage and file
  std::vector<GlFragmentOutput> fragmentOutputs;  // empty without a fragment stage
};

// Compiles the vertex stage and, when present, the fragment stage, then links.
// feedbackVaryings are declared before linking (transform feedback needs
// that); pass none for a plain compile check or a render. A lone fragment
// output ends up at location 0. Never throws for bad GLSL.
BuiltProgram buildGlProgram(const ProgramSource& source,
                            const std::vector<std::string>& feedbackVaryings);

}  // namespace snell
