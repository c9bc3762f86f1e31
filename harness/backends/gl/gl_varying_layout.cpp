#include "backends/gl/gl_varying_layout.h"

#include <cstdio>

#include "core/errors.h"

namespace snell {

namespace {
int floatsPerElement(GLenum type) {
  switch (type) {
    case GL_FLOAT: return 1;
    case GL_FLOAT_VEC2: return 2;
    case GL_FLOAT_VEC3: return 3;
    case GL_FLOAT_VEC4: return 4;
    case GL_FLOAT_MAT2: return 4;
    case GL_FLOAT_MAT3: return 9;
    case GL_FLOAT_MAT4: return 16;
    case GL_FLOAT_MAT2x3: return 6;
    case GL_FLOAT_MAT2x4: return 8;
    case GL_FLOAT_MAT3x2: return 6;
    case GL_FLOAT_MAT3x4: return 12;
    case GL_FLOAT_MAT4x2: return 8;
    case GL_FLOAT_MAT4x3: return 12;
    default: return 0;
  }
}
}  // namespace

GlVaryingLayout GlVaryingLayout::query(GLuint program) {
  GlVaryingLayout layout;
  GLint count = 0;
  GLint maxLength = 0;
  glGetProgramiv(program, GL_TRANSFORM_FEEDBACK_VARYINGS, &count);
  glGetProgramiv(program, GL_TRANSFORM_FEEDBACK_VARYING_MAX_LENGTH, &maxLength);
  std::vector<char> name(static_cast<std::size_t>(maxLength > 0 ? maxLength : 1));
  for (GLint index = 0; index < count; ++index) {
    GLsizei length = 0;
    GLsizei arraySize = 0;
    GLenum type = 0;
    glGetTransformFeedbackVarying(program, static_cast<GLuint>(index), maxLength, &length,
                                  &arraySize, &type, name.data());
    Field field;
    field.name.assign(name.data(), static_cast<std::size_t>(length));
    const int perElement = floatsPerElement(type);
    if (perElement == 0) {
      char hex[16];
      std::snprintf(hex, sizeof hex, "0x%04X", type);
      throw UsageError("vertex output '" + field.name + "' has GL type " + hex +
                       "; only float, vec and mat outputs can be captured");
    }
    field.components = perElement * arraySize;
    field.offset = layout.stride;
    layout.stride += field.components;
    layout.fields.push_back(std::move(field));
  }
  return layout;
}

std::vector<CapturedVarying> GlVaryingLayout::split(const std::vector<float>& records,
                                                    std::size_t vertexCount) const {
  std::vector<CapturedVarying> varyings;
  varyings.reserve(fields.size());
  for (const Field& field : fields) {
    CapturedVarying varying;
    varying.name = field.name;
    varying.components = field.components;
    varying.data.reserve(vertexCount * static_cast<std::size_t>(field.components));
    for (std::size_t vertex = 0; vertex < vertexCount; ++vertex) {
      const float* first = records.data() + vertex * static_cast<std::size_t>(stride) +
                           static_cast<std::size_t>(field.offset);
      varying.data.insert(varying.data.end(), first, first + field.components);
    }
    varyings.push_back(std::move(varying));
  }
  return varyings;
}

}  // namespace snell
