// The reference renderer's fixed-function part on hand-placed clip-space
// triangles.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/errors.h"
#include "oracle/reference/rasterizer.h"

namespace snell {
namespace {

constexpr int kSize = 32;

std::size_t coveredCount(const Visibility& v) {
  std::size_t n = 0;
  for (std::uint32_t t : v.triangle) n += t != Visibility::kNoTriangle;
  return n;
}

std::uint32_t triangleAt(const Visibility& v, int x, int y) {
  return v.triangle[static_cast<std::size_t>(y) * v.width + x];
}

TEST(OracleRasterizer, TopOfClipSpaceIsTheTopRowsAndRightIsRight) {
  // Counter-clockwise in clip space (y up): a front face.
  const std::vector<ClipPosition> p = {{0.2, 0.2, 0, 1}, {0.8, 0.2, 0, 1}, {0.5, 0.8, 0, 1}};
  const std::vector<std::uint32_t> indices = {0, 1, 2};
  const Visibility v = rasterize(p, indices, {kSize, kSize, true});
  ASSERT_GT(coveredCount(v), 20u);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      if (v.covered(x, y)) {
        EXPECT_LT(y, kSize / 2) << "row " << y;
        EXPECT_GE(x, kSize / 2) << "column " << x;
      }
  // The apex (y = 0.8) is the narrow end, near the top of the image.
  int topRow = kSize, bottomRow = -1;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      if (v.covered(x, y)) {
        topRow = std::min(topRow, y);
        bottomRow = std::max(bottomRow, y);
      }
  int topWidth = 0, bottomWidth = 0;
  for (int x = 0; x < kSize; ++x) {
    topWidth += v.covered(x, topRow);
    bottomWidth += v.covered(x, bottomRow);
  }
  EXPECT_LT(topWidth, bottomWidth);
}

TEST(OracleRasterizer, PixelCentresAndTheViewportMapExactly) {
  // x_ndc in [-1, 0] is columns 0 .. size/2 - 1 exactly; the shared
  // diagonal passes through pixel corners only.
  const std::vector<ClipPosition> p = {{-1, -1, 0, 1}, {0, -1, 0, 1}, {0, 1, 0, 1}, {-1, 1, 0, 1}};
  const std::vector<std::uint32_t> indices = {0, 1, 2, 0, 2, 3};
  const Visibility v = rasterize(p, indices, {kSize, kSize, true});
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) EXPECT_EQ(v.covered(x, y), x < kSize / 2) << x << "," << y;
}

TEST(OracleRasterizer, SharedEdgeThroughPixelCentresIsCoveredExactlyOnce) {
  // Two triangles of a quad; the diagonal runs through pixel centres
  // (x + 0.5 = y + 0.5 in window coordinates). Drawn one at a time, every
  // quad pixel belongs to exactly one of them.
  const double a = -1 + 2 * 4.5 / kSize, b = -1 + 2 * 27.5 / kSize;
  const std::vector<ClipPosition> p = {{a, a, 0, 1}, {b, a, 0, 1}, {b, b, 0, 1}, {a, b, 0, 1}};
  const std::vector<std::uint32_t> first = {0, 1, 2}, second = {0, 2, 3}, both = {0, 1, 2, 0, 2, 3};
  const Visibility one = rasterize(p, first, {kSize, kSize, true});
  const Visibility two = rasterize(p, second, {kSize, kSize, true});
  const Visibility quad = rasterize(p, both, {kSize, kSize, true});
  std::size_t diagonal = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      EXPECT_FALSE(one.covered(x, y) && two.covered(x, y)) << x << "," << y;
      EXPECT_EQ(one.covered(x, y) || two.covered(x, y), quad.covered(x, y)) << x << "," << y;
      // Window y (up) = kSize - 1 - row: the diagonal's pixels.
      if (x == kSize - 1 - y && quad.covered(x, y)) ++diagonal;
    }
  EXPECT_GT(diagonal, 15u);
  EXPECT_EQ(coveredCount(quad), 23u * 23u);
  // The quad's own edges also run through pixel centres (4.5 and 27.5):
  // top-left rule, so its left column and top row are in, its right column
  // and bottom row out (window y 27.5 is row 4, 4.5 is row 27).
  EXPECT_TRUE(quad.covered(4, 10));
  EXPECT_FALSE(quad.covered(27, 10));
  EXPECT_TRUE(quad.covered(10, 4));
  EXPECT_FALSE(quad.covered(10, 27));
}

TEST(OracleRasterizer, BackFacesAreCulledOnlyWhenAsked) {
  // Clockwise in clip space: a back face.
  const std::vector<ClipPosition> p = {{-0.5, -0.5, 0, 1}, {0.5, 0.5, 0, 1}, {0.5, -0.5, 0, 1}};
  const std::vector<std::uint32_t> indices = {0, 1, 2};
  EXPECT_EQ(coveredCount(rasterize(p, indices, {kSize, kSize, true})), 0u);
  EXPECT_GT(coveredCount(rasterize(p, indices, {kSize, kSize, false})), 50u);
}

TEST(OracleRasterizer, NearerTriangleWinsInEitherOrder) {
  // Two full-screen-ish triangles at depth ndc -0.5 and +0.5.
  auto at = [](double z) {
    return std::vector<ClipPosition>{{-0.9, -0.9, z, 1}, {0.9, -0.9, z, 1}, {0, 0.9, z, 1}};
  };
  std::vector<ClipPosition> p = at(0.5);
  const std::vector<ClipPosition> near = at(-0.5);
  p.insert(p.end(), near.begin(), near.end());
  const std::vector<std::uint32_t> farFirst = {0, 1, 2, 3, 4, 5}, nearFirst = {3, 4, 5, 0, 1, 2};
  const Visibility a = rasterize(p, farFirst, {kSize, kSize, true});
  const Visibility b = rasterize(p, nearFirst, {kSize, kSize, true});
  ASSERT_GT(coveredCount(a), 100u);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      if (a.covered(x, y)) {
        EXPECT_EQ(triangleAt(a, x, y), 1u);
        EXPECT_EQ(triangleAt(b, x, y), 0u);
      }
}

TEST(OracleRasterizer, FragmentsBeyondTheFarPlaneAreClipped) {
  // Depth runs from ndc -0.5 on the left to 1.5 on the right: the right
  // part lies beyond the far plane.
  const std::vector<ClipPosition> p = {
      {-1, -1, -0.5, 1}, {1, -1, 1.5, 1}, {1, 1, 1.5, 1}, {-1, 1, -0.5, 1}};
  const std::vector<std::uint32_t> indices = {0, 1, 2, 0, 2, 3};
  const Visibility v = rasterize(p, indices, {kSize, kSize, true});
  for (int x = 0; x < kSize; ++x) {
    const double zNdc = -0.5 + 2.0 * (x + 0.5) / kSize;
    EXPECT_EQ(v.covered(x, kSize / 2), zNdc <= 1.0) << "column " << x;
  }
}

// A quad in eye space slanting away to the right: x from -1 to 1 while
// depth goes from 2 to 4, seen through x_clip = x, w_clip = -z. A value
// that is 0 on the left edge and 1 on the right interpolates, perspective-
// correctly, to the u of the eye-space point that the pixel centre sees.
TEST(OracleRasterizer, InterpolationIsPerspectiveCorrect) {
  auto eye = [](double u, double v) {  // (x, y, z)
    return std::array<double, 3>{-1 + 2 * u, -1 + 2 * v, -2 - 2 * u};
  };
  std::vector<ClipPosition> p;
  const std::array<std::array<double, 2>, 4> corners = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  for (const auto& [u, v] : corners) {
    const auto e = eye(u, v);
    p.push_back({e[0], e[1], 0.0, -e[2]});
  }
  const std::vector<std::uint32_t> indices = {0, 1, 2, 0, 2, 3};
  const Visibility vis = rasterize(p, indices, {kSize, kSize, true});
  double largestScreenLinearError = 0;
  std::size_t checked = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      if (!vis.covered(x, y)) continue;
      const std::size_t pixel = static_cast<std::size_t>(y) * kSize + x;
      const std::uint32_t t = vis.triangle[pixel];
      double interpolated = 0;
      for (int k = 0; k < 3; ++k)
        interpolated += vis.weights[pixel][k] * corners[indices[3 * t + k]][0];
      // x_ndc = (-1 + 2u) / (2 + 2u)  =>  u = (1 + 2 x_ndc) / (2 - 2 x_ndc).
      const double xNdc = -1 + 2.0 * (x + 0.5) / kSize;
      const double analytic = (1 + 2 * xNdc) / (2 - 2 * xNdc);
      EXPECT_NEAR(interpolated, analytic, 1e-12) << x << "," << y;
      // Screen-linear interpolation would give the ndc fraction instead.
      const double leftNdc = -0.5, rightNdc = 0.25;
      largestScreenLinearError = std::max(
          largestScreenLinearError, std::fabs((xNdc - leftNdc) / (rightNdc - leftNdc) - analytic));
      ++checked;
    }
  EXPECT_GT(checked, 100u);
  EXPECT_GT(largestScreenLinearError, 0.05);
}

TEST(OracleRasterizer, TriangleAcrossTheEyePlaneIsAUsageError) {
  const std::vector<ClipPosition> p = {{-0.5, -0.5, 0, 1}, {0.5, -0.5, 0, 1}, {0, 0.5, -1, -1}};
  const std::vector<std::uint32_t> indices = {0, 1, 2};
  EXPECT_THROW(rasterize(p, indices, {kSize, kSize, true}), UsageError);
}

TEST(OracleRasterizer, TriangleWhollyBehindTheNearPlaneIsDropped) {
  // Behind the eye, as a GL perspective matrix puts it: w < 0 and z < -w.
  const std::vector<ClipPosition> p = {{-0.5, -0.5, -2, -1}, {0.5, -0.5, -2, -1}, {0, 0.5, -2, -1}};
  const std::vector<std::uint32_t> indices = {0, 1, 2};
  EXPECT_EQ(coveredCount(rasterize(p, indices, {kSize, kSize, false})), 0u);
}

TEST(OracleRasterizer, BadIndicesAreAUsageError) {
  const std::vector<ClipPosition> p = {{0, 0, 0, 1}, {1, 0, 0, 1}, {0, 1, 0, 1}};
  const std::vector<std::uint32_t> pastTheEnd = {0, 1, 3}, notTriangles = {0, 1};
  EXPECT_THROW(rasterize(p, pastTheEnd, {kSize, kSize, true}), UsageError);
  EXPECT_THROW(rasterize(p, notTriangles, {kSize, kSize, true}), UsageError);
}

}  // namespace
}  // namespace snell
