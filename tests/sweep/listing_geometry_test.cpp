// The listing sweep's vertices: each grid normal makes its angle with the
// view ray; in the stretched frame the listing's own transforms (modelview
// on the position, NormalMatrix on the normal) give back the point's
// eye-space geometry, with a normal that is no longer unit length, so a
// missing normalize() shows.
#include "sweep/listing_geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/scene.h"

namespace snell::sweep {
namespace {

SweepGrid smallGrid() {
  SweepGrid grid;
  grid.angles = {0, 30, 60, 90};
  grid.criticalOffsets = {1e-6};
  return grid;
}

TEST(ListingGeometry, GridNormalsMakeTheirAngleWithTheViewRay) {
  for (const ListingPoint& p : listingPoints(smallGrid(), {1.5}, false)) {
    const double cosine = p.trueNormal[2];  // the view ray is -z: cos = dot(-I, N)
    EXPECT_NEAR(std::acos(std::clamp(cosine, -1.0, 1.0)) * 180 / std::numbers::pi, p.angleDegrees,
                1e-9);
  }
}

TEST(ListingGeometry, DenseAroundTheCriticalAngleAndPastNinetyForBackFaces) {
  const std::vector<ListingPoint> points = listingPoints(smallGrid(), {1.5}, true);
  const double critical = std::asin(1 / 1.5) * 180 / std::numbers::pi;
  int near = 0, back = 0, bad = 0;
  for (const ListingPoint& p : points) {
    near += std::abs(p.angleDegrees - critical) < 1e-4 && p.input == "grid";
    back += p.input == "back-face" && p.angleDegrees > 90;
    bad += p.input != "grid" && p.input != "back-face";
  }
  EXPECT_EQ(near, 3);  // the critical angle and 1e-6 rad either side
  EXPECT_GE(back, 5);
  EXPECT_GE(bad, 15);
}

TEST(ListingGeometry, StretchedFrameKeepsTheEyeSpaceGeometryButNotTheLength) {
  const Scene base = makeScene("sweep");
  const std::vector<ListingPoint> points = listingPoints(smallGrid(), {}, false);
  const Scene scene = listingScene(base, points, true);
  const Value& modelview = scene.values.at("modelview");
  const Value& normalMatrix = scene.values.at("normal_matrix");
  const AttributeStream& position = scene.attributes.at("position");
  const AttributeStream& normal = scene.attributes.at("normal");
  bool someNotUnit = false;
  for (std::size_t k = 0; k < points.size(); ++k) {
    for (int r = 0; r < 3; ++r) {
      double eye = 0;
      for (int c = 0; c < 4; ++c) eye += modelview.data[c * 4 + r] * position.data[k * 4 + c];
      EXPECT_NEAR(eye, points[k].position[r], 1e-6);
    }
    std::array<double, 3> n{};
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) n[r] += normalMatrix.data[c * 3 + r] * normal.data[k * 3 + c];
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    someNotUnit = someNotUnit || std::abs(length - 1) > 0.1;
    for (int r = 0; r < 3; ++r) EXPECT_NEAR(n[r] / length, points[k].trueNormal[r], 1e-6);
  }
  EXPECT_TRUE(someNotUnit);
}

TEST(ListingGeometry, HalfVectorPointsCrossZeroInFrontOfTheEye) {
  // The Orange Book's diffraction set-up: eye at the origin, a light to
  // the right and below.
  const HalfVector half = halfVectorAt({0, 0, 0}, {3, -3, 0});
  int near = 0;
  for (const ListingPoint& p : listingPoints(smallGrid(), {}, false, &half)) {
    if (p.input != "dot(N,H)->0") continue;
    double dot = 0;
    for (int c = 0; c < 3; ++c) dot += p.trueNormal[c] * half.h[c];
    EXPECT_NEAR(dot, p.dotNH, 1e-12);
    EXPECT_GT(p.trueNormal[2], 0) << "faces the eye";
    near += std::abs(dot) < 1e-7;
  }
  EXPECT_GE(near, 3);  // the zero and 1e-6 degrees either side
}

TEST(ListingGeometry, UnitFrameIsTheIdentity) {
  const Scene scene =
      listingScene(makeScene("sweep"), listingPoints(smallGrid(), {}, false), false);
  const Value& modelview = scene.values.at("modelview");
  for (int k = 0; k < 16; ++k) EXPECT_EQ(modelview.data[k], k % 5 == 0 ? 1.0f : 0.0f);
}

}  // namespace
}  // namespace snell::sweep
