#pragma once
#include <vector>

#include "backends/backend.h"
#include "backends/gl/gl_api.h"
#include "backends/gl/gl_framebuffer.h"
#include "backends/gl/gl_program_cache.h"
#include "backends/gl/gl_vertex_inputs.h"

namespace snell {

// The feedback buffer and query that captures draw with, kept for the life
// of a context so a capture allocates no GL objects. Vertex inputs are the
// context's, shared with renders. Must be destroyed while its context is
// current.
class GlVertexCapture {
 public:
  explicit GlVertexCapture(GlVertexInputs& inputs);  // the context must be current
  GlVertexCapture(const GlVertexCapture&) = delete;
  GlVertexCapture& operator=(const GlVertexCapture&) = delete;
  ~GlVertexCapture();

  // Draws job.vertexCount points with rasterisation discarded and returns
  // the program's transform feedback outputs. The program must have linked.
  // Throws UsageError for attributes that do not fit the job and SetupError
  // for GL errors; either way GL state is left as it was found.
  std::vector<CapturedVarying> run(GlLinkedProgram& program, const CaptureJob& job);

 private:
  std::vector<float> drawAndRead(const GlLinkedProgram& program, std::size_t vertexCount);

  GlVertexInputs& inputs_;
  // Bound while capturing: an EGL surfaceless context has no default
  // framebuffer, and a draw needs a complete one even with rasterisation
  // discarded. Used under OSMesa too, so both take the same path.
  GlFramebuffer target_{1, 1, 1};
  GLuint feedbackBuffer_ = 0;
  GLuint primitivesQuery_ = 0;
};

}  // namespace snell
