#include "backends/gl/gl_uniform_table.h"

#include <cstdio>

#include "backends/gl/gl_legacy_state.h"
#include "core/errors.h"

namespace snell {

namespace {

GLenum glTypeOf(ValueType type) {
  switch (type) {
    case ValueType::Float: return GL_FLOAT;
    case ValueType::Vec2: return GL_FLOAT_VEC2;
    case ValueType::Vec3: return GL_FLOAT_VEC3;
    case ValueType::Vec4: return GL_FLOAT_VEC4;
    case ValueType::Mat3: return GL_FLOAT_MAT3;
    case ValueType::Mat4: return GL_FLOAT_MAT4;
  }
  return 0;
}

// Only the types a Value can carry have an entry; others are named by GLSL
// type for messages.
int floatCount(GLenum type) {
  switch (type) {
    case GL_FLOAT: return 1;
    case GL_FLOAT_VEC2: return 2;
    case GL_FLOAT_VEC3: return 3;
    case GL_FLOAT_VEC4: return 4;
    case GL_FLOAT_MAT3: return 9;
    case GL_FLOAT_MAT4: return 16;
    default: return 0;
  }
}

std::string glslNameOf(GLenum type) {
  switch (type) {
    case GL_FLOAT: return "float";
    case GL_FLOAT_VEC2: return "vec2";
    case GL_FLOAT_VEC3: return "vec3";
    case GL_FLOAT_VEC4: return "vec4";
    case GL_FLOAT_MAT2: return "mat2";
    case GL_FLOAT_MAT3: return "mat3";
    case GL_FLOAT_MAT4: return "mat4";
    case GL_INT: return "int";
    case GL_INT_VEC2: return "ivec2";
    case GL_INT_VEC3: return "ivec3";
    case GL_INT_VEC4: return "ivec4";
    case GL_UNSIGNED_INT: return "uint";
    case GL_BOOL: return "bool";
    case GL_SAMPLER_1D: return "sampler1D";
    case GL_SAMPLER_2D: return "sampler2D";
    case GL_SAMPLER_3D: return "sampler3D";
    case GL_SAMPLER_CUBE: return "samplerCube";
    case GL_SAMPLER_2D_SHADOW: return "sampler2DShadow";
    case GL_SAMPLER_CUBE_SHADOW: return "samplerCubeShadow";
    case GL_SAMPLER_2D_ARRAY: return "sampler2DArray";
    case GL_SAMPLER_2D_RECT: return "sampler2DRect";
    default: {
      char hex[32];
      std::snprintf(hex, sizeof hex, "GL type 0x%04X", type);
      return hex;
    }
  }
}

// Every opaque type a shader can sample or load from; each needs a texture
// bound to its unit, which no Value provides.
bool isSampler(GLenum type) {
  switch (type) {
    case GL_SAMPLER_1D: case GL_SAMPLER_2D: case GL_SAMPLER_3D: case GL_SAMPLER_CUBE:
    case GL_SAMPLER_1D_SHADOW: case GL_SAMPLER_2D_SHADOW: case GL_SAMPLER_1D_ARRAY:
    case GL_SAMPLER_2D_ARRAY: case GL_SAMPLER_1D_ARRAY_SHADOW: case GL_SAMPLER_2D_ARRAY_SHADOW:
    case GL_SAMPLER_2D_MULTISAMPLE: case GL_SAMPLER_2D_MULTISAMPLE_ARRAY:
    case GL_SAMPLER_CUBE_SHADOW: case GL_SAMPLER_BUFFER: case GL_SAMPLER_2D_RECT:
    case GL_SAMPLER_2D_RECT_SHADOW: case GL_SAMPLER_CUBE_MAP_ARRAY:
    case GL_SAMPLER_CUBE_MAP_ARRAY_SHADOW:
    case GL_INT_SAMPLER_1D: case GL_INT_SAMPLER_2D: case GL_INT_SAMPLER_3D:
    case GL_INT_SAMPLER_CUBE: case GL_INT_SAMPLER_1D_ARRAY: case GL_INT_SAMPLER_2D_ARRAY:
    case GL_INT_SAMPLER_2D_MULTISAMPLE: case GL_INT_SAMPLER_2D_MULTISAMPLE_ARRAY:
    case GL_INT_SAMPLER_BUFFER: case GL_INT_SAMPLER_2D_RECT: case GL_INT_SAMPLER_CUBE_MAP_ARRAY:
    case GL_UNSIGNED_INT_SAMPLER_1D: case GL_UNSIGNED_INT_SAMPLER_2D:
    case GL_UNSIGNED_INT_SAMPLER_3D: case GL_UNSIGNED_INT_SAMPLER_CUBE:
    case GL_UNSIGNED_INT_SAMPLER_1D_ARRAY: case GL_UNSIGNED_INT_SAMPLER_2D_ARRAY:
    case GL_UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE:
    case GL_UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE_ARRAY: case GL_UNSIGNED_INT_SAMPLER_BUFFER:
    case GL_UNSIGNED_INT_SAMPLER_2D_RECT: case GL_UNSIGNED_INT_SAMPLER_CUBE_MAP_ARRAY:
      return true;
    default:
      return false;
  }
}

void upload(GLint location, GLenum type, const float* data) {
  switch (type) {
    case GL_FLOAT: glUniform1fv(location, 1, data); break;
    case GL_FLOAT_VEC2: glUniform2fv(location, 1, data); break;
    case GL_FLOAT_VEC3: glUniform3fv(location, 1, data); break;
    case GL_FLOAT_VEC4: glUniform4fv(location, 1, data); break;
    // Values are column-major, as GL expects without transposing.
    case GL_FLOAT_MAT3: glUniformMatrix3fv(location, 1, GL_FALSE, data); break;
    case GL_FLOAT_MAT4: glUniformMatrix4fv(location, 1, GL_FALSE, data); break;
    default: break;
  }
}

// An array uniform is reported as "name[0]"; it is listed under "name" so a
// job naming it gets a clear error instead of being silently ignored.
std::string baseName(const std::string& name) {
  const std::string suffix = "[0]";
  if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
    return name.substr(0, name.size() - suffix.size());
  return name;
}

}  // namespace

GlUniformTable::GlUniformTable(GLuint program) {
  GLint count = 0;
  GLint maxLength = 0;
  glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
  glGetProgramiv(program, GL_ACTIVE_UNIFORM_MAX_LENGTH, &maxLength);
  std::vector<char> name(static_cast<std::size_t>(maxLength > 0 ? maxLength : 1));
  for (GLint index = 0; index < count; ++index) {
    GLsizei length = 0;
    Slot slot;
    glGetActiveUniform(program, static_cast<GLuint>(index), maxLength, &length, &slot.arraySize,
                       &slot.type, name.data());
    const std::string fullName(name.data(), static_cast<std::size_t>(length));
    slot.location = glGetUniformLocation(program, fullName.c_str());
    if (slot.location < 0) continue;  // a member of a uniform block, not settable by name
    const int floats = floatCount(slot.type);
    if (floats > 0 && slot.arraySize == 1) {
      slot.linkValue.resize(static_cast<std::size_t>(floats));
      glGetUniformfv(program, slot.location, slot.linkValue.data());
    }
    if (isSampler(slot.type))
      samplers_.push_back(Sampler{baseName(fullName), slot.location, slot.type, slot.arraySize});
    slots_[baseName(fullName)] = std::move(slot);
  }
}

std::string GlUniformTable::glslName(GLenum type) { return glslNameOf(type); }

void GlUniformTable::apply(const UniformMap& uniforms) {
  // A legacy program's matrices are context state, not uniforms of the
  // program (gl_legacy_state.h); asked of the bound program on every job,
  // they cost a few queries and keep this table the program's own.
  GLint current = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &current);
  const bool legacyMatrices = queryLegacyReads(static_cast<GLuint>(current)).matrices;
  // Everything is checked before anything is set, so a rejected job leaves
  // the program as it was.
  if (legacyMatrices) checkLegacyMatrices(uniforms);
  for (const auto& [name, value] : uniforms) {
    const auto found = slots_.find(name);
    if (found != slots_.end()) checkSettable(name, found->second, value);
  }
  if (legacyMatrices) loadLegacyMatrices(uniforms);
  for (auto& [name, slot] : slots_) {
    const auto given = uniforms.find(name);
    if (given != uniforms.end()) {
      upload(slot.location, slot.type, given->second.data.data());
      slot.changed = true;
    } else if (slot.changed) {
      upload(slot.location, slot.type, slot.linkValue.data());
      slot.changed = false;
    }
  }
}

void GlUniformTable::checkSettable(const std::string& name, const Slot& slot, const Value& value) {
  const std::string declared =
      glslNameOf(slot.type) + (slot.arraySize > 1 ? "[" + std::to_string(slot.arraySize) + "]" : "");
  if (slot.arraySize > 1)
    throw UsageError("uniform '" + name + "' is declared " + declared +
                     " in the shader; array uniforms cannot be set from a value");
  if (glTypeOf(value.type) != slot.type)
    throw UsageError("uniform '" + name + "' is declared " + declared +
                     " in the shader but the value given is a " + glslTypeName(value.type));
  if (value.data.size() != static_cast<std::size_t>(componentCount(value.type)))
    throw UsageError("uniform '" + name + "': a " + glslTypeName(value.type) + " needs " +
                     std::to_string(componentCount(value.type)) + " floats, the value has " +
                     std::to_string(value.data.size()));
}

}  // namespace snell
