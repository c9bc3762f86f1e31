#include "backends/gl/gl_vertex_capture.h"

#include <numeric>
#include <string>
#include <vector>

#include "backends/gl/gl_error_check.h"
#include "core/errors.h"
#include "core/phase_clock.h"

namespace snell {

namespace {
// Undoes what a capture changed, whichever way it leaves.
class CaptureStateGuard {
 public:
  CaptureStateGuard(GLuint program, GLuint vertexArray, GLuint framebuffer) {
    glUseProgram(program);
    glBindVertexArray(vertexArray);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  }
  CaptureStateGuard(const CaptureStateGuard&) = delete;
  CaptureStateGuard& operator=(const CaptureStateGuard&) = delete;
  ~CaptureStateGuard() {
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
    glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glBindVertexArray(0);
    glUseProgram(0);
  }
};

// A draw is an INVALID_OPERATION when samplers of different types share a
// texture unit, and every sampler starts on unit 0, so a program with a
// sampler2D and a samplerCube could not even be captured, though no
// fragment runs: each sampler (each element of an array) gets a unit of
// its own. Nothing is sampled, so nothing need be bound there.
void separateSamplerUnits(const GlUniformTable& uniforms) {
  GLint next = 0;
  for (const GlUniformTable::Sampler& sampler : uniforms.samplers()) {
    std::vector<GLint> units(static_cast<std::size_t>(sampler.arraySize));
    std::iota(units.begin(), units.end(), next);
    next += sampler.arraySize;
    glUniform1iv(sampler.location, sampler.arraySize, units.data());
  }
  throwOnGlError("glUniform1iv (a texture unit for each sampler)");
}
}  // namespace

GlVertexCapture::GlVertexCapture(GlVertexInputs& inputs) : inputs_(inputs) {
  glGenBuffers(1, &feedbackBuffer_);
  glGenQueries(1, &primitivesQuery_);
  throwOnGlError("creating the capture feedback buffer and query");
}

GlVertexCapture::~GlVertexCapture() {
  glDeleteQueries(1, &primitivesQuery_);
  glDeleteBuffers(1, &feedbackBuffer_);
}

std::vector<CapturedVarying> GlVertexCapture::run(GlLinkedProgram& program, const CaptureJob& job) {
  GlVertexInputs::check(program, job.attributes, job.vertexCount);
  if (job.vertexCount == 0 || program.varyings.stride == 0) {
    // No draw: with zero outputs glBeginTransformFeedback itself is an error.
    return program.varyings.split({}, 0);
  }

  const PhaseScope phase(Phase::Draw);
  CaptureStateGuard guard(program.program.id(), inputs_.vertexArray(), target_.id());
  program.uniforms.apply(job.uniforms);
  throwOnGlError("glUniform*");
  separateSamplerUnits(program.uniforms);
  inputs_.bindAttributes(program, job.attributes, job.vertexCount);
  const std::vector<float> records = drawAndRead(program, job.vertexCount);
  const PhaseScope reading(Phase::ReadBack);
  return program.varyings.split(records, job.vertexCount);
}

std::vector<float> GlVertexCapture::drawAndRead(const GlLinkedProgram& program,
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
  glFinish();  // the draw's time is the draw's, not the read-back's

  const PhaseScope reading(Phase::ReadBack);
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
