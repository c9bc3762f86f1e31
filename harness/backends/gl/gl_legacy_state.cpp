#include "backends/gl/gl_legacy_state.h"

#include <algorithm>

#include "core/errors.h"
#include "core/legacy_builtins.h"

namespace snell {

namespace {

// The texture units whose matrices and coordinate arrays snell sets.
int textureUnits() {
  GLint coords = 0;
  glGetIntegerv(GL_MAX_TEXTURE_COORDS, &coords);
  return std::min<int>(coords, kLegacyTextureUnits);
}

bool readsMatrixState(const std::string& name) {
  for (const char* prefix :
       {"gl_ModelView", "gl_Projection", "gl_NormalMatrix", "gl_TextureMatrix"})
    if (name.rfind(prefix, 0) == 0) return true;
  return false;
}

// An array uniform is listed as "name[0]".
std::string withoutArraySuffix(std::string name) {
  const std::size_t bracket = name.find('[');
  if (bracket != std::string::npos) name.resize(bracket);
  return name;
}

template <class GetActive>
std::vector<std::string> activeNames(GLuint program, GLenum count, GLenum maxLength,
                                     GetActive getActive) {
  GLint entries = 0, longest = 0;
  glGetProgramiv(program, count, &entries);
  glGetProgramiv(program, maxLength, &longest);
  std::vector<char> buffer(static_cast<std::size_t>(std::max(longest, 1)));
  std::vector<std::string> names;
  for (GLint index = 0; index < entries; ++index) {
    GLsizei length = 0;
    GLint size = 0;
    GLenum type = 0;
    getActive(program, static_cast<GLuint>(index), longest, &length, &size, &type, buffer.data());
    names.emplace_back(buffer.data(), static_cast<std::size_t>(length));
  }
  return names;
}

const Value* given(const UniformMap& uniforms, const std::string& name) {
  const auto found = uniforms.find(name);
  return found == uniforms.end() ? nullptr : &found->second;
}

void loadOrIdentity(const Value* value) {
  if (value)
    glLoadMatrixf(value->data.data());  // column-major, as glLoadMatrixf expects
  else
    glLoadIdentity();
}

}  // namespace

bool GlLegacyReads::reads(const std::string& attribute) const {
  return std::find(attributes.begin(), attributes.end(), attribute) != attributes.end();
}

GlLegacyReads queryLegacyReads(GLuint program) {
  GlLegacyReads reads;
  for (const std::string& name :
       activeNames(program, GL_ACTIVE_UNIFORMS, GL_ACTIVE_UNIFORM_MAX_LENGTH, glGetActiveUniform))
    reads.matrices |= readsMatrixState(withoutArraySuffix(name));
  for (const std::string& name : activeNames(program, GL_ACTIVE_ATTRIBUTES,
                                             GL_ACTIVE_ATTRIBUTE_MAX_LENGTH, glGetActiveAttrib)) {
    const auto builtin = findLegacyBuiltin(name);
    if (builtin && builtin->kind == LegacyBuiltinKind::Attribute) reads.attributes.push_back(name);
  }
  return reads;
}

bool compatibilityContext() {
  GLint mask = 0;
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
  return (mask & GL_CONTEXT_COMPATIBILITY_PROFILE_BIT) != 0;
}

void checkLegacyMatrices(const UniformMap& uniforms) {
  const int units = textureUnits();
  for (const auto& [name, value] : uniforms) {
    const auto builtin = findLegacyBuiltin(name);
    if (!builtin || builtin->kind != LegacyBuiltinKind::Matrix) continue;
    if (value.type != ValueType::Mat4 || value.data.size() != 16)
      throw UsageError("uniform '" + name + "' is a mat4 but the value given is a " +
                       glslTypeName(value.type) + " of " + std::to_string(value.data.size()) +
                       " floats");
    if (builtin->unit >= units)
      throw UsageError("uniform '" + name + "': this context has " + std::to_string(units) +
                       " texture units with matrices");
  }
}

void loadLegacyMatrices(const UniformMap& uniforms) {
  glMatrixMode(GL_PROJECTION);
  loadOrIdentity(given(uniforms, "gl_ProjectionMatrix"));
  glMatrixMode(GL_TEXTURE);
  for (int unit = textureUnits() - 1; unit >= 0; --unit) {
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    loadOrIdentity(given(uniforms, "gl_TextureMatrix[" + std::to_string(unit) + "]"));
  }
  glMatrixMode(GL_MODELVIEW);
  loadOrIdentity(given(uniforms, "gl_ModelViewMatrix"));
}

void checkLegacyAttribute(const AttributeStream& stream) {
  const bool fits = stream.name == "gl_Normal"   ? stream.components == 3
                    : stream.name == "gl_Vertex" ? stream.components >= 2
                                                 : true;
  if (!fits)
    throw UsageError(
        "attribute '" + stream.name + "' has " + std::to_string(stream.components) +
        " components per vertex; " +
        (stream.name == "gl_Normal" ? "glNormalPointer takes 3" : "glVertexPointer takes 2 to 4"));
}

void disableLegacyArrays() {
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
  for (int unit = textureUnits() - 1; unit >= 0; --unit) {
    glClientActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  }
}

void enableLegacyArray(const std::string& name, int components) {
  if (name == "gl_Vertex") {
    glVertexPointer(components, GL_FLOAT, 0, nullptr);
    glEnableClientState(GL_VERTEX_ARRAY);
  } else if (name == "gl_Normal") {
    glNormalPointer(GL_FLOAT, 0, nullptr);
    glEnableClientState(GL_NORMAL_ARRAY);
  } else if (const auto builtin = findLegacyBuiltin(name); builtin && builtin->unit >= 0) {
    glClientActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + builtin->unit));
    glTexCoordPointer(components, GL_FLOAT, 0, nullptr);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glClientActiveTexture(GL_TEXTURE0);
  }
}

void resetLegacyCurrentValues(const GlLegacyReads& reads, const AttributeMap& given) {
  for (const std::string& name : reads.attributes) {
    if (given.contains(name)) continue;
    if (name == "gl_Normal") {
      glNormal3f(0.0f, 0.0f, 1.0f);
    } else if (const auto builtin = findLegacyBuiltin(name); builtin && builtin->unit >= 0) {
      glMultiTexCoord4f(static_cast<GLenum>(GL_TEXTURE0 + builtin->unit), 0.0f, 0.0f, 0.0f, 1.0f);
    }
  }
}

}  // namespace snell
