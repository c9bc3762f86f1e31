// A listing edited behind the manifest's back must fail: the oracle reads
// the constants as printed, the backend runs the edited shader.
#include "edited_listing.h"

namespace snell {
namespace {

using edited::editedCopy;
using edited::expectEveryCaseFails;

TEST(ChangedConstant, FresnelEtaEditedFailsOnBothBackends) {
  expectEveryCaseFails(editedCopy("orange-book/14.1-fresnel", "fresnel.vert",
                                  "const float Eta = 0.66;", "const float Eta = 0.67;"));
}

TEST(ChangedConstant, FresnelPowerEditedFailsOnBothBackends) {
  expectEveryCaseFails(editedCopy("orange-book/14.1-fresnel", "fresnel.vert",
                                  "const float FresnelPower = 5.0;",
                                  "const float FresnelPower = 4.0;"));
}

TEST(ChangedConstant, SwappedReflectArgumentsFailOnBothBackends) {
  expectEveryCaseFails(
      editedCopy("orange-book/14.1-fresnel", "fresnel.vert", "reflect(i, n)", "reflect(n, i)"));
}

TEST(ChangedConstant, ChromaticEtaREditedFailsOnBothBackends) {
  expectEveryCaseFails(editedCopy("orange-book/14.3-chromatic", "chromatic.vert",
                                  "const float EtaR = 0.65;", "const float EtaR = 0.66;"));
}

TEST(ChangedConstant, CgRefractConstantEditedFailsOnBothBackends) {
  expectEveryCaseFails(editedCopy("cg-tutorial/c7e3v-refraction", "c7e3v_refraction.vert",
                                  "float cosT2 = 1.0f", "float cosT2 = 1.01f"));
}

TEST(ChangedConstant, DiffractionWidthEditedFailsOnBothBackends) {
  expectEveryCaseFails(editedCopy("orange-book/14.2-diffraction", "diffraction.vert",
                                  "const float c = 10.0;", "const float c = 11.0;"));
}

}  // namespace
}  // namespace snell
