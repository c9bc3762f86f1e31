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

GlFramebuffer::GlFramebuffer(int width, int height) {
  glGenFramebuffers(1, &framebuffer_);
  glGenRenderbuffers(1, &colour_);
  glGenRenderbuffers(1, &depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, colour_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA32F, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  // Draw and read buffers are framebuffer state: set once, here.
  glDrawBuffer(GL_COLOR_ATTACHMENT0);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
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
  glDeleteRenderbuffers(1, &colour_);
  framebuffer_ = depth_ = colour_ = 0;
}

GlFramebuffer& GlFramebufferCache::get(int width, int height) {
  const std::pair<int, int> size{width, height};
  auto found = entries_.find(size);
  if (found == entries_.end()) {
    if (entries_.size() >= kCapacity) {
      auto oldest = entries_.begin();
      for (auto entry = entries_.begin(); entry != entries_.end(); ++entry)
        if (entry->second.lastUse < oldest->second.lastUse) oldest = entry;
      entries_.erase(oldest);
    }
    found = entries_.emplace(size, Entry{std::make_unique<GlFramebuffer>(width, height), 0}).first;
  }
  found->second.lastUse = ++uses_;
  return *found->second.framebuffer;
}

}  // namespace snell
