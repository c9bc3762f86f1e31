// The CPU reference image drawn from a listing's own text (the derived
// oracle) against the one its hand-written fragment part draws, for every
// catalog listing that has both: the same picture, pixel for pixel, within
// what rounding the interpolated inputs to fp32 (as a GPU's varyings are)
// can move a colour.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/case.h"
#include "core/errors.h"
#include "oracle/reference/reference_image.h"
#include "runner/case_runner.h"
#include "runner/listing_oracles.h"
#include "runner/reference_cache.h"

namespace snell {
namespace {

// A colour channel's largest difference: the derived fragment stage reads
// its inputs rounded to fp32 (2^-24 relative), the hand-written one in
// double; through a normalize() and a refract() on a unit vector that
// moves a cube map lookup by a few 2^-24, and the bilinear filter turns it
// into at most (texel gradient) x (texels moved): the environment's largest
// neighbour step is below 1 and the lookup moves far less than a texel, so
// 1e-5 leaves a factor of 100 over the 2^-24 * 16 texels seen.
constexpr double kColourTolerance = 1e-5;

TEST(DerivedReference, DrawsWhatEveryHandWrittenFragmentPartDraws) {
  const std::vector<Manifest> manifests = loadManifests(SNELL_SOURCE_ROOT "/shaders");
  SceneCache scenes;
  int compared = 0;
  for (const Case& c : expandCases(manifests, "")) {
    const Manifest& m = *c.manifest;
    if (!c.spec.has("image") || m.oracle.empty() || m.expect != Expectation::Pass) continue;
    Manifest derivedOnly = m;
    derivedOnly.oracle.clear();
    derivedOnly.derivedOracle = true;
    Case derivedCase = c;
    derivedCase.manifest = &derivedOnly;
    const Scene& scene = scenes.get(c.spec.scene);
    const ResolvedBindings bindings = resolveBindings(m, scene);
    ReferenceCache handCache, derivedCache;
    const ReferenceImage& hand = handCache.get(c, scene, bindings);
    const ReferenceImage* derived = nullptr;
    try {
      derived = &derivedCache.get(derivedCase, scene, bindings);
    } catch (const UsageError& error) {
      ADD_FAILURE() << c.id << ": " << error.what();
      continue;
    }
    ++compared;
    ASSERT_EQ(hand.color.pixels.size(), derived->color.pixels.size()) << c.id;
    double worst = 0;
    std::size_t maskDiffers = 0;
    for (std::size_t p = 0; p < hand.mask.size(); ++p) {
      if (hand.mask[p] != derived->mask[p]) ++maskDiffers;
      if (hand.mask[p] != PixelMask::None || derived->mask[p] != PixelMask::None) continue;
      for (std::size_t k = 0; k < 4; ++k)
        worst = std::max(worst, std::fabs(static_cast<double>(hand.color.pixels[4 * p + k]) -
                                          derived->color.pixels[4 * p + k]));
    }
    std::printf("%-45s worst colour difference %.2e, %zu of %zu pixels masked differently\n",
                c.id.c_str(), worst, maskDiffers, hand.mask.size());
    EXPECT_LE(worst, kColourTolerance) << c.id;
    // A face edge or an undefined lookup decided by an fp32 input instead
    // of a double one: a handful of pixels at most.
    EXPECT_LE(maskDiffers, hand.mask.size() / 1000) << c.id;
  }
  EXPECT_GE(compared, 5);
}

TEST(DerivedReference, AManifestNamingBothOraclesGatesWithBothInOrder) {
  const std::vector<Manifest> manifests =
      loadManifests(SNELL_SOURCE_ROOT "/shaders/orange-book/14.1-fresnel");
  Manifest both = manifests.at(0);
  both.derivedOracle = true;
  const std::vector<NamedOracle> oracles = vectorOracles(both, CaptureStage::Vertex);
  ASSERT_EQ(oracles.size(), 2u);
  EXPECT_EQ(oracles[0].label, "orange_book_fresnel");
  EXPECT_EQ(oracles[1].label, "derived");
  EXPECT_EQ(oracles[1].oracle->outputs(), both.captureVertex);  // what is captured, no more
  EXPECT_EQ(oracleLabel(both), "orange_book_fresnel + derived");
  // The picture comes from the hand-written fragment part when there is one.
  EXPECT_EQ(drawingOracles(both).label, "orange_book_fresnel");
  both.oracle.clear();
  EXPECT_EQ(drawingOracles(both).label, "derived");
  EXPECT_EQ(oracleLabel(both), "derived");
}

}  // namespace
}  // namespace snell
