#include "backends/gl/gl_vertex_inputs.h"

#include <string>

#include "backends/gl/gl_error_check.h"
#include "backends/gl/gl_legacy_state.h"
#include "core/errors.h"

namespace snell {

namespace {
void checkAttribute(const AttributeStream& stream, std::size_t vertexCount) {
  if (stream.components < 1 || stream.components > 4)
    throw UsageError("attribute '" + stream.name + "' has " + std::to_string(stream.components) +
                     " components per vertex; 1 to 4 are possible");
  if (stream.data.size() % static_cast<std::size_t>(stream.components) != 0)
    throw UsageError("attribute '" + stream.name + "' has " + std::to_string(stream.data.size()) +
                     " floats, not a multiple of its " + std::to_string(stream.components) +
                     " components");
  if (stream.vertexCount() < vertexCount)
    throw UsageError("attribute '" + stream.name + "' has " +
                     std::to_string(stream.vertexCount()) + " vertices; the job draws " +
                     std::to_string(vertexCount));
}
}  // namespace

GlVertexInputs::GlVertexInputs() {
  glGenVertexArrays(1, &vertexArray_);
  glGenBuffers(1, &elementBuffer_);
  throwOnGlError("creating the vertex array and element buffer");
}

GlVertexInputs::~GlVertexInputs() {
  if (!attributeBuffers_.empty())
    glDeleteBuffers(static_cast<GLsizei>(attributeBuffers_.size()), attributeBuffers_.data());
  glDeleteBuffers(1, &elementBuffer_);
  glDeleteVertexArrays(1, &vertexArray_);
}

void GlVertexInputs::check(GlLinkedProgram& program, const AttributeMap& attributes,
                           std::size_t vertexCount) {
  const GlLegacyReads legacy = queryLegacyReads(program.program.id());
  for (const auto& [name, stream] : attributes) {
    if (legacy.reads(name)) {
      checkAttribute(stream, vertexCount);
      checkLegacyAttribute(stream);
    } else if (program.attributeLocation(name) >= 0) {
      checkAttribute(stream, vertexCount);
    }
  }
}

void GlVertexInputs::bindAttributes(GlLinkedProgram& program, const AttributeMap& attributes,
                                    std::size_t vertexCount) {
  // Arrays a previous job enabled would otherwise feed this program.
  disableAttributes();
  // A legacy program reads gl_Vertex, gl_Normal, gl_MultiTexCoordk from
  // the fixed-function arrays (gl_legacy_state.h), which only a
  // compatibility context has.
  const bool compatibility = compatibilityContext();
  if (compatibility) disableLegacyArrays();
  const GlLegacyReads legacy =
      compatibility ? queryLegacyReads(program.program.id()) : GlLegacyReads{};
  std::size_t used = 0;
  for (const auto& [name, stream] : attributes) {
    const bool builtin = legacy.reads(name);
    const GLint location = builtin ? -1 : program.attributeLocation(name);
    if (!builtin && location < 0) continue;
    if (used == attributeBuffers_.size()) {
      attributeBuffers_.push_back(0);
      glGenBuffers(1, &attributeBuffers_.back());
    }
    const std::size_t floats = vertexCount * static_cast<std::size_t>(stream.components);
    glBindBuffer(GL_ARRAY_BUFFER, attributeBuffers_[used++]);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(floats * sizeof(float)),
                 stream.data.data(), GL_STREAM_DRAW);
    if (builtin) {
      enableLegacyArray(name, stream.components);
      continue;
    }
    glVertexAttribPointer(static_cast<GLuint>(location), stream.components, GL_FLOAT, GL_FALSE, 0,
                          nullptr);
    glEnableVertexAttribArray(static_cast<GLuint>(location));
    enabledLocations_.push_back(static_cast<GLuint>(location));
  }
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  resetLegacyCurrentValues(legacy, attributes);
  throwOnGlError("binding vertex attributes (glBufferData, glVertexAttribPointer)");
}

void GlVertexInputs::bindIndices(const std::vector<std::uint32_t>& indices) {
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, elementBuffer_);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER,
               static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)), indices.data(),
               GL_STREAM_DRAW);
  throwOnGlError("glBufferData(GL_ELEMENT_ARRAY_BUFFER)");
}

void GlVertexInputs::disableAttributes() {
  for (GLuint location : enabledLocations_) glDisableVertexAttribArray(location);
  enabledLocations_.clear();
}

}  // namespace snell
