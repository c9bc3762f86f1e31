// The blog's legacy listings edited behind the manifest's back must fail on
// both APIs: OpenGL runs the edited shader on its fixed-function state,
// Vulkan through the legacy adapter, and the oracle reads the constants
// and the texture units as printed.
#include "edited_listing.h"

namespace snell {
namespace {

using edited::editedCopy;
using edited::expectEveryCaseFails;

TEST(BlogChangedConstant, FresnelEtaEditedFailsOnBothBackends) {
  expectEveryCaseFails(
      editedCopy("blog/fresnel", "fresnel.vert", "const float Eta=0.6;", "const float Eta=0.61;"));
}

// The refraction reads texture unit 0's matrix and the reflection unit 1's;
// the manifest binds them to different matrices, so a swap is seen.
TEST(BlogChangedConstant, FresnelTextureUnitSwappedFailsOnBothBackends) {
  expectEveryCaseFails(editedCopy("blog/fresnel", "fresnel.vert",
                                  "vec3(gl_TextureMatrix[1] * vec4(Reflect,1.0))",
                                  "vec3(gl_TextureMatrix[0] * vec4(Reflect,1.0))"));
}

TEST(BlogChangedConstant, ChromaticEtaREditedFailsOnBothBackends) {
  expectEveryCaseFails(editedCopy("blog/chromatic", "chromatic.vert", "const float EtaR=0.3;",
                                  "const float EtaR=0.31;"));
}

TEST(BlogChangedConstant, DiffractionWidthEditedFailsOnBothBackends) {
  expectEveryCaseFails(editedCopy("blog/diffraction", "diffraction.vert", "const float c = 10.0;",
                                  "const float c = 11.0;"));
}

}  // namespace
}  // namespace snell
