#pragma once
#include <memory>

#include "backends/backend.h"
#include "backends/gl/gl_program_cache.h"
#include "backends/gl/gl_renderer.h"
#include "backends/gl/gl_vertex_capture.h"
#include "backends/gl/gl_vertex_inputs.h"
#include "backends/gl/gl_context_provider.h"

namespace snell {

// A context and the GL objects that belong to it. Captures and renders
// share its programs and vertex inputs. Member order matters: the context
// is declared first so it is destroyed last, after the destructor has made
// it current for the objects' deletion.
class GlContextState {
 public:
  explicit GlContextState(std::unique_ptr<GlContext> context);
  GlContextState(const GlContextState&) = delete;
  GlContextState& operator=(const GlContextState&) = delete;
  ~GlContextState();

  void makeCurrent() { context_->makeCurrent(); }
  GlProgramCache& programs() { return *programs_; }
  GlVertexCapture& capture() { return *capture_; }
  GlRenderer& renderer() { return *renderer_; }

 private:
  std::unique_ptr<GlContext> context_;
  std::unique_ptr<GlProgramCache> programs_;
  std::unique_ptr<GlVertexInputs> inputs_;
  std::unique_ptr<GlVertexCapture> capture_;
  std::unique_ptr<GlRenderer> renderer_;
};

}  // namespace snell
