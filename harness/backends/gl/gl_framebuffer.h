#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <tuple>
#include <utility>
#include <vector>

#include "backends/gl/gl_api.h"

namespace snell {

// A framebuffer object with RGBA32F colour renderbuffers (the listing's
// output and one per fragment probe) and a 32-bit float depth renderbuffer:
// float so that results are compared before any 8-bit quantisation. Must be
// destroyed while its context is current.
class GlFramebuffer {
 public:
  // The context must be current; leaves framebuffer 0 bound. Throws
  // SetupError naming the status when the driver calls it incomplete.
  GlFramebuffer(int width, int height, int colourTargets);
  GlFramebuffer(const GlFramebuffer&) = delete;
  GlFramebuffer& operator=(const GlFramebuffer&) = delete;
  ~GlFramebuffer();

  GLuint id() const { return framebuffer_; }
  int colourTargets() const { return static_cast<int>(colour_.size()); }

 private:
  void release();

  GLuint framebuffer_ = 0;
  std::vector<GLuint> colour_;
  GLuint depth_ = 0;
};

// Framebuffers of one context by size. A suite renders at a few sizes, so
// each is made once; the least recently used goes when more are asked for,
// since a long `eval` run must not keep every size it ever saw.
class GlFramebufferCache {
 public:
  GlFramebuffer& get(int width, int height, int colourTargets);

 private:
  static constexpr std::size_t kCapacity = 4;
  struct Entry {
    std::unique_ptr<GlFramebuffer> framebuffer;
    std::uint64_t lastUse = 0;
  };
  std::map<std::tuple<int, int, int>, Entry> entries_;
  std::uint64_t uses_ = 0;
};

// "GL_FRAMEBUFFER_UNSUPPORTED", ... for glCheckFramebufferStatus results.
const char* glFramebufferStatusName(GLenum status);

}  // namespace snell
