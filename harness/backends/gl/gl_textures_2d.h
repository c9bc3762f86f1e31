#pragma once
#include <cstddef>
#include <cstdint>
#include <map>

#include "backends/gl/gl_api.h"
#include "core/image.h"

namespace snell {

// 2D textures of one context, uploaded once per image, as GlCubeTextures
// keeps cube maps: an entry is found by the Image's address and trusted
// only if its size and a hash of its texels still match, so an Image freed
// and another allocated at the same address is uploaded afresh. Must be
// destroyed while its context is current.
class GlTextures2D {
 public:
  GlTextures2D() = default;
  GlTextures2D(const GlTextures2D&) = delete;
  GlTextures2D& operator=(const GlTextures2D&) = delete;
  ~GlTextures2D();

  // Starts a job: textures bound from here on are kept until it ends.
  void beginJob() { ++job_; }

  // Binds `image` to texture unit `unit` (uploading it when needed) as
  // RGBA32F, base level only, LINEAR filtering and REPEAT wrapping (what
  // RenderJob::textures2D promises). Row j of the image is row j of the
  // texture. The image must hold width * height * 4 floats. Leaves `unit`
  // active.
  void bind(const Image& image, int unit);

  std::size_t uploads() const { return uploads_; }  // for tests: how often texels went to GL

 private:
  struct Texture {
    GLuint id = 0;
    int width = 0;
    int height = 0;
    std::uint64_t hash = 0;
    std::uint64_t lastJob = 0;
  };
  // Kept across jobs; one job that samples more still gets them all.
  static constexpr std::size_t kCapacity = 8;

  Texture& entryFor(const Image& image);
  void evictOneUnusedThisJob();
  void upload(const Image& image);  // into the bound texture

  std::map<const Image*, Texture> textures_;
  std::uint64_t job_ = 0;
  std::size_t uploads_ = 0;
};

// A hash of the size and every texel's bits.
std::uint64_t imageHash(const Image& image);

}  // namespace snell
