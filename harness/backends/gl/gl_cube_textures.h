#pragma once
#include <cstddef>
#include <cstdint>
#include <map>

#include "backends/gl/gl_api.h"
#include "core/cube_map.h"

namespace snell {

// Cube map textures of one context, uploaded once per environment: a suite
// renders many cases against the same CubeMap. An entry is found by the
// CubeMap's address and trusted only if the size and a hash of the texels
// still match, so a CubeMap freed and another allocated at the same address
// is uploaded afresh. Must be destroyed while its context is current.
class GlCubeTextures {
 public:
  GlCubeTextures() = default;
  GlCubeTextures(const GlCubeTextures&) = delete;
  GlCubeTextures& operator=(const GlCubeTextures&) = delete;
  ~GlCubeTextures();

  // Starts a job: textures bound from here on are kept until it ends.
  void beginJob() { ++job_; }

  // Binds `map` to texture unit `unit` (uploading it when needed), with
  // base-level-only sampling, its filter and clamp-to-edge wrapping. The
  // faces must hold size * size * 4 floats each. Leaves `unit` active.
  void bind(const CubeMap& map, int unit);

  std::size_t uploads() const { return uploads_; }  // for tests: how often texels went to GL

 private:
  struct Texture {
    GLuint id = 0;
    int size = 0;
    std::uint64_t hash = 0;
    std::uint64_t lastJob = 0;
  };
  // Kept across jobs; one job that samples more still gets them all.
  static constexpr std::size_t kCapacity = 8;

  Texture& entryFor(const CubeMap& map);
  void evictOneUnusedThisJob();
  void upload(const CubeMap& map);  // into the bound texture

  std::map<const CubeMap*, Texture> textures_;
  std::uint64_t job_ = 0;
  std::size_t uploads_ = 0;
};

// A hash of the size and every texel's bits: cheap next to an upload, and it
// sees any change, not just a sample.
std::uint64_t cubeMapHash(const CubeMap& map);

}  // namespace snell
