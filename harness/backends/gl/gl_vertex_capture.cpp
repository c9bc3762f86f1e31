#include "backends/gl/gl_vertex_capture.h"

#include <string>

#include "backends/gl/gl_error_check.h"
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

// Undoes what a capture changed, whichever way it leaves.
class CaptureStateGuard {
 public:
  CaptureStateGuard(GLuint program, GLuint vertexArray) {
    glUseProgram(program);
    glBindVertexArray(vertexArray);
  }
  CaptureStateGuard(const CaptureStateGuard&) = delete;
  CaptureStateGuard& operator=(const CaptureStateGuard&) = delete;
  ~CaptureStateGuard() {
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
    glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, 0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindVertexArray(0);
    glUseProgram(0);
  }
};
}  // namespace

GlVertexCapture::GlVertexCapture() {
  glGenVertexArrays(1, &vertexArray_);
  glGenBuffers(1, &feedbackBuffer_);
  glGenQueries(1, &primitivesQuery_);
  throwOnGlError("creating the capture vertex array, buffer and query");
}

GlVertexCapture::~GlVertexCapture() {
  if (!attributeBuffers_.empty())
    glDeleteBuffers(static_cast<GLsizei>(attributeBuffers_.size()), attributeBuffers_.data());
  glDeleteQueries(1, &primitivesQuery_);
  glDeleteBuffers(1, &feedbackBuffer_);
  glDeleteVertexArrays(1, &vertexArray_);
}

std::vector<CapturedVarying> GlVertexCapture::run(GlCaptureProgram& program,
                                                  const CaptureJob& job) {
  for (const auto& [name, stream] : job.attributes) {
    if (program.attributeLocation(name) >= 0) checkAttribute(stream, job.vertexCount);
  }
  if (job.vertexCount == 0 || program.varyings.stride == 0) {
    // No draw: with zero outputs glBeginTransformFeedback itself is an error.
    return program.varyings.split({}, 0);
  }

  CaptureStateGuard guard(program.program.id(), vertexArray_);
  program.uniforms.apply(job.uniforms);
  throwOnGlError("glUniform*");
  bindAttributes(program, job);
  const std::vector<float> records = drawAndRead(program, job.vertexCount);
  return program.varyings.split(records, job.vertexCount);
}

// Attributes the program has but the job leaves out read the generic
// attribute value (0,0,0,1), so arrays from an earlier job are switched off.
void GlVertexCapture::bindAttributes(GlCaptureProgram& program, const CaptureJob& job) {
  unbindAttributes();
  std::size_t used = 0;
  for (const auto& [name, stream] : job.attributes) {
    const GLint location = program.attributeLocation(name);
    if (location < 0) continue;
    if (used == attributeBuffers_.size()) {
      attributeBuffers_.push_back(0);
      glGenBuffers(1, &attributeBuffers_.back());
    }
    const std::size_t floats = job.vertexCount * static_cast<std::size_t>(stream.components);
    glBindBuffer(GL_ARRAY_BUFFER, attributeBuffers_[used++]);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(floats * sizeof(float)),
                 stream.data.data(), GL_STREAM_DRAW);
    glVertexAttribPointer(static_cast<GLuint>(location), stream.components, GL_FLOAT, GL_FALSE, 0,
                          nullptr);
    glEnableVertexAttribArray(static_cast<GLuint>(location));
    enabledLocations_.push_back(static_cast<GLuint>(location));
  }
  throwOnGlError("binding vertex attributes (glBufferData, glVertexAttribPointer)");
}

void GlVertexCapture::unbindAttributes() {
  for (GLuint location : enabledLocations_) glDisableVertexAttribArray(location);
  enabledLocations_.clear();
}

std::vector<float> GlVertexCapture::drawAndRead(const GlCaptureProgram& program,
                                                std::size_t vertexCount) {
  const std::size_t floats = vertexCount * static_cast<std::size_t>(program.varyings.stride);
  const auto bytes = static_cast<GLsizeiptr>(floats * sizeof(float));
  glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, feedbackBuffer_);
  glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, bytes, nullptr, GL_STREAM_READ);
  glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, feedbackBuffer_);
  throwOnGlError("allocating the transform feedback buffer");

  // Straight-line from here to the restore: every call runs, errors are
  // remembered, and rasterizer discard is off again before anything throws.
  GlErrorLog errors;
  glEnable(GL_RASTERIZER_DISCARD);
  glBeginQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, primitivesQuery_);
  glBeginTransformFeedback(GL_POINTS);
  errors.check("glBeginTransformFeedback(GL_POINTS)");
  glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(vertexCount));
  errors.check("glDrawArrays(GL_POINTS)");
  glEndTransformFeedback();
  errors.check("glEndTransformFeedback");
  glEndQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN);
  glDisable(GL_RASTERIZER_DISCARD);
  errors.check("glEndQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN)");
  errors.throwIfAny();

  GLuint written = 0;
  glGetQueryObjectuiv(primitivesQuery_, GL_QUERY_RESULT, &written);
  std::vector<float> records(floats);
  glGetBufferSubData(GL_TRANSFORM_FEEDBACK_BUFFER, 0, bytes, records.data());
  throwOnGlError("glGetBufferSubData(GL_TRANSFORM_FEEDBACK_BUFFER)");
  // A short write would leave the tail of the buffer undefined.
  if (written != vertexCount)
    throw SetupError("transform feedback wrote " + std::to_string(written) + " of " +
                     std::to_string(vertexCount) + " vertices");
  return records;
}

}  // namespace snell
