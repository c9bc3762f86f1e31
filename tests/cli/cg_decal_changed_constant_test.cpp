// The Cg Tutorial's C7E4f_refraction edited behind the manifest's back must
// fail on both backends. The edits are in the fragment program only, so the
// vertex stage's vectors still pass: the failure must come from the image
// check, against the CPU reference (which runs the listing as published)
// and against the golden.
#include "edited_listing.h"

namespace snell {
namespace {

constexpr const char* kListing = "cg-tutorial/c7e4f-refraction";
constexpr const char* kFragment = "c7e4f_refraction.frag";

std::filesystem::path editedCopy(const std::string& from, const std::string& to) {
  return edited::editedCopy(kListing, kFragment, from, to);
}

void expectEveryImageFails(const std::filesystem::path& dir) {
  const std::vector<edited::EditedResult> results = edited::runOnBothBackends(dir);
  std::size_t images = 0;
  for (const edited::EditedResult& r : results) {
    const std::string where = r.backend + " " + r.c.id + "\n" + r.result.message;
    if (!r.c.spec.has("image")) {
      // The stretched scene reads vectors only: the fragment edit is not seen.
      EXPECT_EQ(r.result.status, Status::Pass) << where;
      continue;
    }
    ++images;
    EXPECT_EQ(r.result.status, Status::Fail) << where;
    // The vertex stage was not edited: its vectors still pass.
    EXPECT_EQ(r.result.componentsFailed(), 0u) << where;
    ASSERT_EQ(r.result.images.size(), 2u) << where;
    EXPECT_EQ(r.result.images[0].against, "reference");
    EXPECT_EQ(r.result.images[0].verdict, ImageVerdict::Fail) << where;
    EXPECT_EQ(r.result.images[1].against, "golden");
    EXPECT_EQ(r.result.images[1].verdict, ImageVerdict::Fail) << where;
  }
  EXPECT_EQ(images, 4u);  // sphere and torus on gl and vk
}

TEST(CgDecalChangedConstant, SwappedMixArgumentsFailOnBothBackends) {
  expectEveryImageFails(editedCopy("mix(decalColor, refractedColor, transmittance)",
                                   "mix(refractedColor, decalColor, transmittance)"));
}

TEST(CgDecalChangedConstant, TransmittanceUsedOtherwiseFailsOnBothBackends) {
  expectEveryImageFails(
      editedCopy("mix(decalColor, refractedColor, transmittance)",
                 "mix(decalColor, refractedColor, transmittance * transmittance)"));
}

TEST(CgDecalChangedConstant, SwappedDecalCoordinatesFailOnBothBackends) {
  expectEveryImageFails(
      editedCopy("texture(decalMap, oTexCoord)", "texture(decalMap, oTexCoord.yx)"));
}

}  // namespace
}  // namespace snell
