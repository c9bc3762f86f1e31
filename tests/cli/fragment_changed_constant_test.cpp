// A fragment-stage listing edited behind the manifest's back must fail: the
// oracle reads the local constants as printed (the manifest's `constants`),
// the backend runs the edited shader, and the values read back from the
// fragment stage leave their intervals.
#include "edited_listing.h"

namespace snell {
namespace {

using edited::editedCopy;
using edited::expectEveryCaseFails;

TEST(FragmentChangedConstant, Cs381IndexEditedFailsOnBothBackends) {
  expectEveryCaseFails(editedCopy("cs381/refraction", "refraction.frag", "float index = 1.1;",
                                  "float index = 1.2;"));
}

TEST(FragmentChangedConstant, ShadertoyLensKoefEditedFailsOnBothBackends) {
  expectEveryCaseFails(editedCopy("shadertoy/lens", "lens.frag", "float refract_koef = 1.02;",
                                  "float refract_koef = 1.03;"));
}

}  // namespace
}  // namespace snell
