// Listings 14.2 and 14.4 through the FragmentOracle interface, one fragment
// at a time, on a cube map with one colour per face.
#include <gtest/gtest.h>

#include <vector>

#include "core/errors.h"
#include "oracle/reference/cube_sampling.h"
#include "oracle/reference/fragment_oracle.h"
#include "oracle/reference/reference_image.h"
#include "reference_scenes.h"

namespace snell {
namespace {

using test::kFaceColors;

TEST(OracleFragmentListing, DrawingListingsHaveAFragmentPartUnderTheVertexPartsName) {
  EXPECT_TRUE(hasFragmentOracle("orange_book_fresnel"));
  EXPECT_TRUE(hasFragmentOracle("orange_book_chromatic"));
  EXPECT_FALSE(hasFragmentOracle("orange_book_fresnel_fragment"));
  EXPECT_THROW(makeFragmentOracle("cg_refraction"), UsageError);
}

TEST(OracleFragmentListing, FresnelReadsItsInputsInDeclarationOrder) {
  const auto fragment = makeFragmentOracle("orange_book_fresnel");
  const std::vector<FragmentInput> inputs = fragment->inputs();
  ASSERT_EQ(inputs.size(), 3u);
  EXPECT_EQ(inputs[0].name, "Reflect");
  EXPECT_EQ(inputs[0].components, 3);
  EXPECT_EQ(inputs[1].name, "Refract");
  EXPECT_EQ(inputs[1].components, 3);
  EXPECT_EQ(inputs[2].name, "Ratio");
  EXPECT_EQ(inputs[2].components, 1);
  EXPECT_EQ(fragment->samplers(), std::vector<std::string>{"Cubemap"});
}

TEST(OracleFragmentListing, FresnelMixesRefractionTowardReflectionByRatio) {
  const CubeMap map = test::faceColoredCubeMap(4);
  const CubeMapBindings bindings = {{"Cubemap", &map}};
  const auto fragment = makeFragmentOracle("orange_book_fresnel");
  // Reflect toward +Z, Refract toward -Z, Ratio 0.25.
  const std::vector<double> in = {0, 0, 1, 0, 0, -1, 0.25};
  const FragmentResult out = fragment->shade(in, bindings);
  for (int c = 0; c < 3; ++c)
    EXPECT_DOUBLE_EQ(out.color[c],
                     0.75 * kFaceColors[kNegativeZ][c] + 0.25 * kFaceColors[kPositiveZ][c])
        << "channel " << c;
  EXPECT_EQ(out.color[3], 1.0);
  EXPECT_FALSE(out.undefined);
  EXPECT_FALSE(out.faceEdge);
}

TEST(OracleFragmentListing, ChromaticTakesEachChannelFromItsOwnRefraction) {
  const CubeMap map = test::faceColoredCubeMap(4);
  const CubeMapBindings bindings = {{"Cubemap", &map}};
  const auto fragment = makeFragmentOracle("orange_book_chromatic");
  ASSERT_EQ(fragment->inputs().size(), 5u);
  // Ratio 0: the colour is the refraction alone. RefractR looks at +X (red
  // 1), RefractG at +Y (green 1), RefractB at +Z (blue 1).
  std::vector<double> in = {-1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.0};
  FragmentResult out = fragment->shade(in, bindings);
  EXPECT_EQ(out.color[0], 1.0);
  EXPECT_EQ(out.color[1], 1.0);
  EXPECT_EQ(out.color[2], 1.0);
  // RefractR toward -X, whose red is 0: only red changes.
  in[3] = -1;
  out = fragment->shade(in, bindings);
  EXPECT_EQ(out.color[0], kFaceColors[kNegativeX][0]);
  EXPECT_EQ(out.color[1], 1.0);
  EXPECT_EQ(out.color[2], 1.0);
  // Ratio 1: the reflection (-X) alone.
  in.back() = 1.0;
  out = fragment->shade(in, bindings);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(out.color[c], kFaceColors[kNegativeX][c]);
}

TEST(OracleFragmentListing, ZeroRefractionLookupIsUndefined) {
  const CubeMap map = test::faceColoredCubeMap(4);
  const CubeMapBindings bindings = {{"Cubemap", &map}};
  const auto fragment = makeFragmentOracle("orange_book_fresnel");
  EXPECT_TRUE(fragment->shade(std::vector<double>{0, 0, 1, 0, 0, 0, 0.5}, bindings).undefined);
  EXPECT_FALSE(fragment->shade(std::vector<double>{0, 0, 1, 0, 0, 1e-30, 0.5}, bindings).undefined);
}

TEST(OracleFragmentListing, FaceEdgeLookupCountsOnlyWhereTheEdgeIsAStep) {
  const std::vector<double> onEdge = {0, 0, 1, 0.7, 0, -0.7, 0.5};  // Refract on the +X/-Z edge
  const std::vector<double> offEdge = {0, 0, 1, 0.5, 0, -0.7, 0.5};
  auto faceEdge = [&](const CubeMap& map, const std::vector<double>& in) {
    return makeFragmentOracle("orange_book_fresnel")->shade(in, {{"Cubemap", &map}}).faceEdge;
  };
  const CubeMap nearest = test::faceColoredCubeMap(4, CubeFilter::Nearest);
  const CubeMap clamped = test::faceColoredCubeMap(4, CubeFilter::Linear, false);
  const CubeMap seamless = test::faceColoredCubeMap(4, CubeFilter::Linear, true);
  EXPECT_TRUE(faceEdge(nearest, onEdge));
  EXPECT_TRUE(faceEdge(clamped, onEdge));
  EXPECT_FALSE(faceEdge(seamless, onEdge));
  EXPECT_FALSE(faceEdge(nearest, offEdge));
}

}  // namespace
}  // namespace snell
