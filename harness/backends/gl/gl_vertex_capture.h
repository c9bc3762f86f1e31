#pragma once
#include <vector>

#include "backends/backend.h"
#include "backends/gl/gl_api.h"
#include "backends/gl/gl_program_cache.h"

namespace snell {

// The vertex array, buffers and query that captures draw with, kept for the
// life of a context so a capture allocates no GL objects. Must be destroyed
// while its context is current.
class GlVertexCapture {
 public:
  GlVertexCapture();  // the context must be current
  GlVertexCapture(const GlVertexCapture&) = delete;
  GlVertexCapture& operator=(const GlVertexCapture&) = delete;
  ~GlVertexCapture();

  // Draws job.vertexCount points with rasterisation discarded and returns
  // the program's transform feedback outputs. The program must have linked.
  // Throws UsageError for attributes that do not fit the job and SetupError
  // for GL errors; either way GL state is left as it was found.
  std::vector<CapturedVarying> run(GlCaptureProgram& program, const CaptureJob& job);

 private:
  void bindAttributes(GlCaptureProgram& program, const CaptureJob& job);
  void unbindAttributes();
  std::vector<float> drawAndRead(const GlCaptureProgram& program, std::size_t vertexCount);

  GLuint vertexArray_ = 0;
  GLuint feedbackBuffer_ = 0;
  GLuint primitivesQuery_ = 0;
  std::vector<GLuint> attributeBuffers_;  // grows to the most attributes a job used
  std::vector<GLuint> enabledLocations_;
};

}  // namespace snell
