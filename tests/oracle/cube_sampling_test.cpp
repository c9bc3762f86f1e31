// Cube map sampling against the spec tables, with maps whose texels encode
// where they are: red = face, green = i, blue = j.
#include "oracle/reference/cube_sampling.h"

#include <gtest/gtest.h>

#include <string>

#include "reference_scenes.h"

namespace snell {
namespace {

constexpr int kSize = 8;

CubeMap addressCubeMap(CubeFilter filter, bool seamless = true) {
  CubeMap map;
  map.size = kSize;
  map.filter = filter;
  map.seamless = seamless;
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < kSize; ++j)
      for (int i = 0; i < kSize; ++i)
        map.faces[face].insert(
            map.faces[face].end(),
            {static_cast<float>(face), static_cast<float>(i), static_cast<float>(j), 1.0f});
  return map;
}

TEST(OracleCubeSampling, EachFaceCentreSelectsItsFace) {
  const std::array<Direction, 6> centres = {
      {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};
  const CubeMap colored = test::faceColoredCubeMap(4);
  for (int face = 0; face < 6; ++face) {
    const FaceCoordinates at = selectCubeFace(centres[face]);
    EXPECT_EQ(at.face, face);
    EXPECT_EQ(at.s, 0.5) << "face " << face;
    EXPECT_EQ(at.t, 0.5) << "face " << face;
    const Rgba value = sampleCube(colored, centres[face]);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(value[c], test::kFaceColors[face][c]) << "face " << face;
  }
}

// OpenGL 4.6 table 8.19, read as: which direction, off the face's major
// axis, reaches the texels at small s (i = 0) and at small t (j = 0).
struct Orientation {
  const char* face;
  int index;
  Direction towardSmallS, towardLargeS, towardSmallT, towardLargeT;
};
constexpr Orientation kOrientations[] = {
    // sc = -rz, tc = -ry
    {"+X", kPositiveX, {1, 0, 0.9}, {1, 0, -0.9}, {1, 0.9, 0}, {1, -0.9, 0}},
    // sc = +rz, tc = -ry
    {"-X", kNegativeX, {-1, 0, -0.9}, {-1, 0, 0.9}, {-1, 0.9, 0}, {-1, -0.9, 0}},
    // sc = +rx, tc = +rz
    {"+Y", kPositiveY, {-0.9, 1, 0}, {0.9, 1, 0}, {0, 1, -0.9}, {0, 1, 0.9}},
    // sc = +rx, tc = -rz
    {"-Y", kNegativeY, {-0.9, -1, 0}, {0.9, -1, 0}, {0, -1, 0.9}, {0, -1, -0.9}},
    // sc = +rx, tc = -ry
    {"+Z", kPositiveZ, {-0.9, 0, 1}, {0.9, 0, 1}, {0, 0.9, 1}, {0, -0.9, 1}},
    // sc = -rx, tc = -ry
    {"-Z", kNegativeZ, {0.9, 0, -1}, {-0.9, 0, -1}, {0, 0.9, -1}, {0, -0.9, -1}},
};

TEST(OracleCubeSampling, FaceOrientationFollowsTheSpecTable) {
  const CubeMap map = addressCubeMap(CubeFilter::Nearest);
  auto expectTexel = [&](const Orientation& o, const Direction& d, int i, int j,
                         const char* where) {
    const Rgba texel = sampleCube(map, d);
    EXPECT_EQ(texel[0], o.index) << o.face << " " << where;
    EXPECT_EQ(texel[1], i) << o.face << " " << where;
    EXPECT_EQ(texel[2], j) << o.face << " " << where;
  };
  // 0.9 off the axis is s or t = 0.05 or 0.95: the first or last texel; on
  // the axis, 0.5: texel size / 2.
  for (const Orientation& o : kOrientations) {
    expectTexel(o, o.towardSmallS, 0, kSize / 2, "small s");
    expectTexel(o, o.towardLargeS, kSize - 1, kSize / 2, "large s");
    expectTexel(o, o.towardSmallT, kSize / 2, 0, "small t");
    expectTexel(o, o.towardLargeT, kSize / 2, kSize - 1, "large t");
  }
}

TEST(OracleCubeSampling, TiesGoToZThenY) {
  EXPECT_EQ(selectCubeFace({1, 1, 1}).face, kPositiveZ);
  EXPECT_EQ(selectCubeFace({-1, 1, -1}).face, kNegativeZ);
  EXPECT_EQ(selectCubeFace({1, -1, 0.5}).face, kNegativeY);
  EXPECT_EQ(selectCubeFace({-1, 1, 0}).face, kPositiveY);
  EXPECT_EQ(selectCubeFace({-1, 0.5, 0.5}).face, kNegativeX);
}

// A direction on `face` at (s, t) = ((i + 0.5) / size, (j + 0.5) / size),
// built from the same table.
Direction onFace(int face, double s, double t) {
  const double sc = 2 * s - 1, tc = 2 * t - 1;
  switch (face) {
    case kPositiveX:
      return {1, -tc, -sc};
    case kNegativeX:
      return {-1, -tc, sc};
    case kPositiveY:
      return {sc, 1, tc};
    case kNegativeY:
      return {sc, -1, -tc};
    case kPositiveZ:
      return {sc, -tc, 1};
    default:
      return {-sc, -tc, -1};
  }
}

TEST(OracleCubeSampling, SeamlessFootprintTakesTheNeighbouringFacesTexel) {
  const CubeMap map = addressCubeMap(CubeFilter::Linear);
  const int j = 3;
  // +X at s = 1 - 1/(4 size): the footprint is texel size-1 with weight 3/4
  // and, past the edge s = 1 (toward -z), -Z's texel i = 0 in the same row
  // (both faces have tc = -ry) with weight 1/4.
  const Rgba acrossS = sampleCube(map, onFace(kPositiveX, 1 - 0.25 / kSize, (j + 0.5) / kSize));
  EXPECT_DOUBLE_EQ(acrossS[0], 0.75 * kPositiveX + 0.25 * kNegativeZ);
  EXPECT_DOUBLE_EQ(acrossS[1], 0.75 * (kSize - 1) + 0.25 * 0);
  EXPECT_DOUBLE_EQ(acrossS[2], j);
  // +Y at t = 1/(4 size): past t = 0 (toward -z) lies -Z's top row j = 0,
  // running the other way along the edge (+Y has sc = rx, -Z has sc = -rx).
  const int i = 2;
  const Rgba acrossT = sampleCube(map, onFace(kPositiveY, (i + 0.5) / kSize, 0.25 / kSize));
  EXPECT_DOUBLE_EQ(acrossT[0], 0.75 * kPositiveY + 0.25 * kNegativeZ);
  EXPECT_DOUBLE_EQ(acrossT[1], 0.75 * i + 0.25 * (kSize - 1 - i));
  EXPECT_DOUBLE_EQ(acrossT[2], 0);
}

TEST(OracleCubeSampling, NonSeamlessFootprintClampsToTheFaceEdge) {
  const CubeMap map = addressCubeMap(CubeFilter::Linear, /*seamless=*/false);
  const int j = 3;
  const Rgba value = sampleCube(map, onFace(kPositiveX, 1 - 0.25 / kSize, (j + 0.5) / kSize));
  EXPECT_EQ(value[0], kPositiveX);
  EXPECT_DOUBLE_EQ(value[1], kSize - 1);
  EXPECT_DOUBLE_EQ(value[2], j);
}

TEST(OracleCubeSampling, SeamlessEdgeAveragesTheTwoFaces) {
  const CubeMap seamless = test::faceColoredCubeMap(4);
  const CubeMap clamped = test::faceColoredCubeMap(4, CubeFilter::Linear, false);
  // On the +X/-Z edge (the tie goes to -Z) the footprint is half on each face.
  const Direction edge = {1, 0.2, -1};
  const Rgba mixed = sampleCube(seamless, edge);
  const Rgba own = sampleCube(clamped, edge);
  for (int c = 0; c < 3; ++c) {
    EXPECT_DOUBLE_EQ(
        mixed[c], 0.5 * test::kFaceColors[kPositiveX][c] + 0.5 * test::kFaceColors[kNegativeZ][c]);
    EXPECT_EQ(own[c], test::kFaceColors[kNegativeZ][c]);
  }
}

TEST(OracleCubeSampling, SeamlessCornerAveragesTheThreeFaces) {
  const CubeMap seamless = test::faceColoredCubeMap(4);
  // (1, 1, 1) is +Z at its corner with +X and +Y: the footprint's corner
  // texel is the average of the three, and so is the whole filtered value.
  const Rgba corner = sampleCube(seamless, {1, 1, 1});
  for (int c = 0; c < 3; ++c) {
    const double expected = (test::kFaceColors[kPositiveX][c] + test::kFaceColors[kPositiveY][c] +
                             test::kFaceColors[kPositiveZ][c]) /
                            3.0;
    EXPECT_NEAR(corner[c], expected, 1e-15) << "channel " << c;
  }
}

TEST(OracleCubeSampling, NearestAndLinearDifferAtATexelCorner) {
  // s = t = 2 / size: the corner shared by texels 1 and 2 in both directions.
  const Direction at = onFace(kPositiveZ, 2.0 / kSize, 2.0 / kSize);
  const Rgba linear = sampleCube(addressCubeMap(CubeFilter::Linear), at);
  EXPECT_DOUBLE_EQ(linear[1], 1.5);
  EXPECT_DOUBLE_EQ(linear[2], 1.5);
  const Rgba nearest = sampleCube(addressCubeMap(CubeFilter::Nearest), at);
  EXPECT_EQ(nearest[1], 2);  // floor(s * size)
  EXPECT_EQ(nearest[2], 2);
  // Just inside texel 1 the nearest texel changes; the linear value barely moves.
  const Direction before = onFace(kPositiveZ, 2.0 / kSize - 1e-9, 2.0 / kSize - 1e-9);
  EXPECT_EQ(sampleCube(addressCubeMap(CubeFilter::Nearest), before)[1], 1);
  EXPECT_NEAR(sampleCube(addressCubeMap(CubeFilter::Linear), before)[1], 1.5, 1e-6);
}

TEST(OracleCubeSampling, FaceEdgeProximityIsRelativeToTheMajorAxis) {
  const double eps = kFaceEdgeRelativeEpsilon;
  EXPECT_TRUE(nearCubeFaceEdge({1, 1, 0.3}));
  EXPECT_TRUE(nearCubeFaceEdge({1, 1, 1}));
  EXPECT_TRUE(nearCubeFaceEdge({-4, 0.1, 4 * (1 - 0.5 * eps)}));
  EXPECT_FALSE(nearCubeFaceEdge({-4, 0.1, 4 * (1 - 2 * eps)}));
  EXPECT_TRUE(nearCubeFaceEdge({1e-3, 1e-3 * (1 - 0.5 * eps), 0}));
  EXPECT_FALSE(nearCubeFaceEdge({1, 0.5, 0.5}));
  EXPECT_FALSE(nearCubeFaceEdge({0, 0, 0}));
}

}  // namespace
}  // namespace snell
