// The physics references of the ladders, against each other and against
// the manifests that choose them.
#include "bench/ladder_reference.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "bench/dispersion_reference_image.h"
#include "bench/fresnel_reference_image.h"
#include "core/errors.h"
#include "core/manifest.h"
#include "core/scene.h"
#include "oracle/physics/sellmeier.h"

namespace snell::bench {
namespace {

double largestDifference(const ReferenceImage& a, const ReferenceImage& b) {
  double worst = 0;
  for (int y = 0; y < a.color.height; ++y)
    for (int x = 0; x < a.color.width; ++x)
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst,
                         static_cast<double>(std::abs(a.color.at(x, y)[c] - b.color.at(x, y)[c])));
  return worst;
}

// A glass with no dispersion: n^2 - 1 = 1.25 at every wavelength, n = 1.5.
const physics::SellmeierGlass& constantIndexGlass() {
  static const physics::SellmeierGlass glass{"n = 1.5", "test", {{1.25, 0.0}}, 300.0, 2500.0};
  return glass;
}

TEST(DispersionReference, WithNoDispersionItIsTheFresnelReference) {
  const Scene scene = makeScene("sphere");
  const ReferenceImage spectral = dispersionReferenceImage(scene, constantIndexGlass(), 16, 40, 40);
  const ReferenceImage fresnel = fresnelReferenceImage(scene, 1.0 / 1.5, 40, 40);
  EXPECT_EQ(spectral.covered, fresnel.covered);
  // The weights are normalised per channel: only float rounding is left.
  EXPECT_LT(largestDifference(spectral, fresnel), 1e-5);
}

TEST(DispersionReference, NBk7DispersesTheRefractedPictureMeasurably) {
  const Scene scene = makeScene("sphere");
  const ReferenceImage bk7 = dispersionReferenceImage(scene, physics::nBk7(), 32, 40, 40);
  const ReferenceImage fresnel = fresnelReferenceImage(
      scene, 1.0 / physics::refractiveIndex(physics::nBk7(), 587.5618), 40, 40);
  EXPECT_GT(largestDifference(bk7, fresnel), 1e-3);
}

std::vector<Manifest> dispersionLadder() {
  return loadManifests(SNELL_SOURCE_ROOT "/shaders/methods/dispersion");
}

TEST(DispersionLadder, SpectralRungsNameNBk7AndTheRgbRungMatchesItsFit) {
  int named = 0;
  for (const Manifest& m : dispersionLadder()) {
    if (const physics::SellmeierGlass* glass = manifestGlass(m)) {
      EXPECT_EQ(glass, &physics::nBk7()) << m.id;
      ++named;
    }
    if (m.constants.count("LambdaR")) {
      // EtaR, EtaG, EtaB are 1 / n of N-BK7 at the stated wavelengths, to
      // the 7 digits the listing prints.
      for (const char* channel : {"R", "G", "B"}) {
        const double lambda = m.constants.at(std::string("Lambda") + channel);
        const double eta = m.constants.at(std::string("Eta") + channel);
        EXPECT_NEAR(eta, 1.0 / physics::refractiveIndex(physics::nBk7(), lambda), 1e-7)
            << m.id << " " << channel;
      }
    }
  }
  EXPECT_EQ(named, 4);
}

TEST(DispersionLadder, UnknownSellmeierTermsAndTwoGlassesAreRefused) {
  std::vector<Manifest> ladder = dispersionLadder();
  ASSERT_FALSE(ladder.empty());
  Manifest unknown = ladder.back();
  unknown.constants["B1"] = 1.0;
  EXPECT_THROW(manifestGlass(unknown), UsageError);

  Manifest water = ladder.back();
  const auto& terms = physics::water20C().terms;
  for (std::size_t k = 0; k < 4; ++k) {
    water.constants[fmt::format("B{}", k + 1)] = terms[k].b;
    water.constants[fmt::format("C{}", k + 1)] = terms[k].c;
  }
  EXPECT_EQ(manifestGlass(water), &physics::water20C());
  ladder.push_back(water);
  try {
    LadderReference(ladder, makeScene("sphere"), 8, 4);
    ADD_FAILURE() << "two glasses in one ladder were accepted";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("one glass"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace snell::bench
