#pragma once
#include <map>
#include <string>
#include <vector>

#include "backends/gl/gl_api.h"
#include "core/values.h"

namespace snell {

// The active uniforms of one linked program, and what it takes to set them
// from Values. A cached program is reused across jobs, so a uniform that one
// job set and the next leaves out is put back to its link-time value: a
// job's results never depend on the jobs before it.
class GlUniformTable {
 public:
  GlUniformTable() = default;
  explicit GlUniformTable(GLuint program);  // queries; the program need not be bound

  // The program must be bound (glUseProgram). Throws UsageError for a Value
  // whose type or size does not match the declaration, naming the uniform.
  // Names the program lacks are ignored.
  void apply(const UniformMap& uniforms);

  // Sampler uniforms are bound to texture units, not set from Values.
  struct Sampler {
    std::string name;
    GLint location = -1;
    GLenum type = 0;
    GLint arraySize = 1;
  };
  const std::vector<Sampler>& samplers() const { return samplers_; }

  // "samplerCube", "vec3", ...: how the shader declares a GL type.
  static std::string glslName(GLenum type);

 private:
  struct Slot {
    GLint location = -1;
    GLenum type = 0;
    GLint arraySize = 1;
    std::vector<float> linkValue;  // empty for types a Value cannot set
    bool changed = false;
  };
  static void checkSettable(const std::string& name, const Slot& slot, const Value& value);

  std::map<std::string, Slot> slots_;
  std::vector<Sampler> samplers_;
};

}  // namespace snell
