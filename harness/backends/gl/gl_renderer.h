#pragma once
#include "backends/backend.h"
#include "backends/gl/gl_cube_textures.h"
#include "backends/gl/gl_framebuffer.h"
#include "backends/gl/gl_program_cache.h"
#include "backends/gl/gl_textures_2d.h"
#include "backends/gl/gl_vertex_inputs.h"

namespace snell {

// Draws render jobs into float framebuffers of one context. Vertex inputs
// are the context's, shared with captures. Must be destroyed while its
// context is current.
class GlRenderer {
 public:
  explicit GlRenderer(GlVertexInputs& inputs) : inputs_(inputs) {}

  // Draws the job's triangles with the program (which must have linked) and
  // reads the colour targets back, row 0 at the top: the listing's output
  // first, then one per probe (the program must hold the probes' writes). Throws UsageError for a
  // job that does not fit the program and SetupError for GL errors; either
  // way the bindings and enables a capture relies on are put back.
  std::vector<Image> run(GlLinkedProgram& program, const RenderJob& job);

 private:
  GlVertexInputs& inputs_;
  GlFramebufferCache framebuffers_;
  GlCubeTextures cubeTextures_;
  GlTextures2D textures2D_;
};

}  // namespace snell
