#include "backends/gl/gl_context_state.h"

namespace snell {

GlContextState::GlContextState(std::unique_ptr<GlContext> context) : context_(std::move(context)) {
  context_->makeCurrent();
  programs_ = std::make_unique<GlProgramCache>();
  inputs_ = std::make_unique<GlVertexInputs>();
  capture_ = std::make_unique<GlVertexCapture>(*inputs_);
  renderer_ = std::make_unique<GlRenderer>(*inputs_);
}

GlContextState::~GlContextState() {
  // Another backend may have made its own context current since.
  try {
    context_->makeCurrent();
  } catch (...) {
    return;  // objects die with the context anyway
  }
  renderer_.reset();
  capture_.reset();
  inputs_.reset();
  programs_.reset();
}

}  // namespace snell
