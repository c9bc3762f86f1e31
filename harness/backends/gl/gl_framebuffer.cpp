#include "backends/gl/gl_framebuffer.h"

#include <string>

#include "backends/gl/gl_error_check.h"
#include "core/errors.h"

namespace snell {

const char* glFramebufferStatusName(GLenum status) {
  switch (status) {
    case GL_FRAMEBUFFER_COMPLETE: return "GL_FRAMEBUFFER_COMPLETE";
    case GL_FRAMEBUFFER_UNDEFINED: return "GL_FRAMEBUFFER_UNDEFINED";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
      return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER";
    case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER";
    case GL_FRAMEBUFFER_UNSUPPORTED: return "GL_FRAMEBUFFER_UNSUPPORTED";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
    case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS:
      return "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS";
    default: return "an unknown status";
  }
}

GlFramebuffer::GlFramebuffer(int width, int height, int colourTargets)
    : colour_(static_cast<std::size_t>(colourTargets)) {
  glGenFramebuffers(1, &framebuffer_);
  glGenRenderbuffers(colourTargets, colour_.data());
  glGenRenderbuffers(1, &depth_);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  std::vector<GLenum> drawBuffers;
  for (int k = 0; k < colourTargets; ++k) {
    glBindRenderbuffer(GL_RENDERBUFFER, colour_[static_cast<std::size_t>(k)]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA32F, width, height);
    const GLenum attachment = static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + k);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, attachment, GL_RENDERBUFFER,
                              colour_[static_cast<std::size_t>(k)]);
    drawBuffers.push_back(attachment);
  }
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  // Draw and read buffers are framebuffer state: set once, here.
  glDrawBuffers(colourTargets, drawBuffers.data());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  const std::string size = std::to_string(width) + "x" + std::to_string(height) + " (" +
                           std::to_string(colourTargets) + " colour targets)";
  try {
    throwOnGlError(("creating a " + size + " RGBA32F + DEPTH_COMPONENT32F framebuffer").c_str());
  } catch (...) {
    release();
    throw;
  }
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    release();
    throw SetupError("the " + size + " RGBA32F + DEPTH_COMPONENT32F framebuffer is incomplete: " +
                     glFramebufferStatusName(status));
  }
}

GlFramebuffer::~GlFramebuffer() { release(); }

void GlFramebuffer::release() {
  glDeleteFramebuffers(1, &framebuffer_);
  glDeleteRenderbuffers(1, &depth_);
  if (!colour_.empty()) glDeleteRenderbuffers(static_cast<GLsizei>(colour_.size()), colour_.data());
  colour_.clear();
  framebuffer_ = depth_ = 0;
}

GlFramebuffer& GlFramebufferCache::get(int width, int height, int colourTargets) {
  const std::tuple<int, int, int> size{width, height, colourTargets};
  auto found = entries_.find(size);
  if (found == entries_.end()) {
    if (entries_.size() >= kCapacity) {
      auto oldest = entries_.begin();
      for (auto entry = entries_.begin(); entry != entries_.end(); ++entry)
        if (entry->second.lastUse < oldest->second.lastUse) oldest = entry;
      entries_.erase(oldest);
    }
    found = entries_.emplace(size, Entry{std::make_unique<GlFramebuffer>(width, height, colourTargets), 0}).first;
  }
  found->second.lastUse = ++uses_;
  return *found->second.framebuffer;
}

}  // namespace snell
