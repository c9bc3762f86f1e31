// renderReferenceImage end to end: Listings 14.1/14.2 (and 14.3/14.4) on
// hand-built draws, against what the geometry and the optics say
// independently of the renderer.
#include "oracle/reference/reference_image.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/errors.h"
#include "oracle/reference/cube_sampling.h"
#include "reference_scenes.h"

namespace snell {
namespace {

using test::Draw;
using test::kFaceColors;

PixelMask maskAt(const ReferenceImage& image, int x, int y) {
  return image.mask[static_cast<std::size_t>(y) * image.color.width + x];
}

// Where a shaded pixel is: the fragment part writes alpha 1, the clear
// colour of these tests has alpha 0.
bool drawn(const ReferenceImage& image, int x, int y) { return image.color.at(x, y)[3] == 1.0f; }

// Clip space = eye space (both matrices identity): a quad at z = -0.5
// facing the camera, counter-clockwise.
void addQuad(Draw& draw, double x0, double y0, double x1, double y1) {
  const std::uint32_t a = draw.addVertex({x0, y0, -0.5, 1}, {0, 0, 1});
  const std::uint32_t b = draw.addVertex({x1, y0, -0.5, 1}, {0, 0, 1});
  const std::uint32_t c = draw.addVertex({x1, y1, -0.5, 1}, {0, 0, 1});
  const std::uint32_t d = draw.addVertex({x0, y1, -0.5, 1}, {0, 0, 1});
  draw.addTriangle(a, b, c);
  draw.addTriangle(a, c, d);
}

double ndcOfColumn(int x, int width) { return -1 + 2.0 * (x + 0.5) / width; }
double ndcOfRow(int y, int height) { return 1 - 2.0 * (y + 0.5) / height; }

TEST(OracleReferenceImage, ConstantCubeMapGivesItsColourInsideAndTheClearColourOutside) {
  Draw draw;
  draw.environment = test::constantCubeMap({0.25f, 0.5f, 0.75f});
  addQuad(draw, -0.5, -0.5, 0.5, 0.5);
  ReferenceInput input = draw.input(32, 32);
  input.clearColor = {0.1f, 0.2f, 0.3f, 0.0f};
  const ReferenceImage image = renderReferenceImage(input);
  ASSERT_EQ(image.color.width, 32);
  ASSERT_EQ(image.mask.size(), 32u * 32u);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      const bool inside = std::fabs(ndcOfColumn(x, 32)) < 0.5 && std::fabs(ndcOfRow(y, 32)) < 0.5;
      const std::array<float, 4> expected =
          inside ? std::array<float, 4>{0.25f, 0.5f, 0.75f, 1.0f} : input.clearColor;
      for (int c = 0; c < 4; ++c) EXPECT_EQ(image.color.at(x, y)[c], expected[c]) << x << "," << y;
    }
  EXPECT_EQ(image.count(PixelMask::Undefined), 0u);
  EXPECT_EQ(image.count(PixelMask::FaceEdge), 0u);
}

TEST(OracleReferenceImage, TopHalfOfClipSpaceLandsInTheTopRows) {
  Draw draw;
  draw.environment = test::constantCubeMap({1, 1, 1});
  const std::uint32_t a = draw.addVertex({0.1, 0.2, -0.5, 1}, {0, 0, 1});
  const std::uint32_t b = draw.addVertex({0.9, 0.2, -0.5, 1}, {0, 0, 1});
  const std::uint32_t c = draw.addVertex({0.5, 0.9, -0.5, 1}, {0, 0, 1});
  draw.addTriangle(a, b, c);
  const ReferenceImage image = renderReferenceImage(draw.input(40, 40));
  std::size_t covered = 0;
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 40; ++x)
      if (drawn(image, x, y)) {
        ++covered;
        EXPECT_LT(y, 20) << "row " << y;
        EXPECT_GE(x, 20) << "column " << x;
      }
  EXPECT_GT(covered, 50u);
  // Wound the other way it is a back face and is culled.
  draw.indices = {a, c, b};
  const ReferenceImage culled = renderReferenceImage(draw.input(40, 40));
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 40; ++x) EXPECT_FALSE(drawn(culled, x, y)) << x << "," << y;
}

TEST(OracleReferenceImage, NearerQuadHidesTheFartherOne) {
  // Two quads whose normals send Reflect to different cube faces; the far
  // one is drawn last.
  Draw draw;
  auto quad = [&](double z, const std::array<double, 3>& normal) {
    const std::uint32_t a = draw.addVertex({-0.6, -0.6, z, 1}, normal);
    const std::uint32_t b = draw.addVertex({0.6, -0.6, z, 1}, normal);
    const std::uint32_t c = draw.addVertex({0.6, 0.6, z, 1}, normal);
    const std::uint32_t d = draw.addVertex({-0.6, 0.6, z, 1}, normal);
    draw.addTriangle(a, b, c);
    draw.addTriangle(a, c, d);
  };
  draw.constants["Eta"] = 1.0;  // F = 0
  quad(-0.2, {0, 0, 1});        // near (ndc z -0.2)
  quad(0.6, {0.6, 0, 0.8});     // far (ndc z 0.6)
  const ReferenceImage image = renderReferenceImage(draw.input(32, 32));
  const float* centre = image.color.at(16, 16);
  // The centre shows what the near quad alone shows, not the far quad.
  Draw nearOnly = draw;
  nearOnly.indices.resize(6);
  const ReferenceImage alone = renderReferenceImage(nearOnly.input(32, 32));
  for (int c = 0; c < 4; ++c) EXPECT_EQ(centre[c], alone.color.at(16, 16)[c]) << "channel " << c;
  Draw farOnly = draw;
  farOnly.indices.erase(farOnly.indices.begin(), farOnly.indices.begin() + 6);
  const ReferenceImage behind = renderReferenceImage(farOnly.input(32, 32));
  EXPECT_NE(behind.color.at(16, 16)[2], centre[2]);
}

// What the optics give at a pixel of the sphere draw, independently of the
// renderer: the pixel-centre ray hits the sphere, reflects and refracts as
// Listing 14.1's formulas say, and Schlick's ratio mixes the two.
struct Optics {
  bool hit = false;
  double cosine = 0;  // dot(-i, n)
  Direction reflect{}, refract{};
  double k = 0;  // refract's 1 - eta^2 (1 - cos^2): negative for total internal reflection
  double ratio = 0;
};

Optics opticsAt(int x, int y, int size, const std::array<double, 3>& centre, double eta,
                double fresnelPower = 5.0) {
  const double f = 1 / std::tan(test::kSphereFovy / 2);
  const Direction d = {ndcOfColumn(x, size) / f, ndcOfRow(y, size) / f, -1};
  const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  const double dc = d[0] * centre[0] + d[1] * centre[1] + d[2] * centre[2];
  const double cc = centre[0] * centre[0] + centre[1] * centre[1] + centre[2] * centre[2];
  const double disc = dc * dc - dd * (cc - 1);
  Optics o;
  if (disc < 0) return o;
  o.hit = true;
  const double t = (dc - std::sqrt(disc)) / dd;
  const double length = std::sqrt(dd);
  Direction i{}, n{};
  for (int k = 0; k < 3; ++k) {
    i[k] = d[k] / length;
    n[k] = t * d[k] - centre[k];
  }
  o.cosine = -(i[0] * n[0] + i[1] * n[1] + i[2] * n[2]);
  o.k = 1 - eta * eta * (1 - o.cosine * o.cosine);
  for (int k = 0; k < 3; ++k) {
    o.reflect[k] = i[k] + 2 * o.cosine * n[k];
    o.refract[k] = o.k < 0 ? 0.0 : eta * i[k] + (eta * o.cosine - std::sqrt(o.k)) * n[k];
  }
  const double F = ((1 - eta) * (1 - eta)) / ((1 + eta) * (1 + eta));
  o.ratio = F + (1 - F) * std::pow(1 - o.cosine, fresnelPower);
  return o;
}

// How far a direction is from every face edge, relative to |ma|.
double faceGap(const Direction& d) {
  std::array<double, 3> m = {std::fabs(d[0]), std::fabs(d[1]), std::fabs(d[2])};
  std::sort(m.begin(), m.end());
  return (m[2] - m[1]) / m[2];
}

const std::array<double, 3> kCentre = {0.05, 0.03, -4};
const double kEta = static_cast<float>(0.66);  // `const float Eta = 0.66;`

Draw sphereDraw(double eta = 0.66) {
  Draw draw;
  draw.constants["Eta"] = eta;
  draw.setCamera(identity4(), test::sphereProjection());
  draw.addSphere(kCentre, 48, 96);
  return draw;
}

TEST(OracleReferenceImage, SphereShowsRefractionInTheMiddleAndReflectionTowardTheRim) {
  constexpr int kSize = 96;
  // FresnelPower 1 widens the band where reflection dominates from a
  // sliver at the silhouette to a ring many pixels wide.
  Draw draw = sphereDraw();
  draw.constants["FresnelPower"] = 1.0;
  const ReferenceImage image = renderReferenceImage(draw.input(kSize, kSize));
  std::size_t refractionSide = 0, reflectionSide = 0, compared = 0;
  double largestError = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const Optics o = opticsAt(x, y, kSize, kCentre, kEta, 1.0);
      if (!o.hit || maskAt(image, x, y) != PixelMask::None) continue;
      // The mesh's per-vertex optics differ from the sphere's near grazing
      // and where a lookup sits on a face edge.
      if (o.cosine < 0.3 || faceGap(o.reflect) < 0.15 || faceGap(o.refract) < 0.15) continue;
      const auto& refractColor = kFaceColors[test::majorFace(o.refract)];
      const auto& reflectColor = kFaceColors[test::majorFace(o.reflect)];
      for (int c = 0; c < 3; ++c) {
        const double expected = refractColor[c] * (1 - o.ratio) + reflectColor[c] * o.ratio;
        largestError = std::max(largestError, std::fabs(image.color.at(x, y)[c] - expected));
      }
      ++compared;
      if (o.ratio < 0.1) ++refractionSide;
      if (o.ratio > 0.5) ++reflectionSide;
    }
  EXPECT_LT(largestError, 0.01);
  EXPECT_GT(compared, 1500u);
  EXPECT_GT(refractionSide, 50u);
  EXPECT_GT(reflectionSide, 300u);
  // Head on, the refraction goes through to -Z (yellow) and the weak
  // reflection comes back from +Z (blue).
  const float* middle = image.color.at(kSize / 2, kSize / 2);
  EXPECT_GT(middle[0], 0.9f);
  EXPECT_GT(middle[1], 0.9f);
  EXPECT_GT(middle[2], 0.02f);
  EXPECT_LT(middle[2], 0.1f);
}

TEST(OracleReferenceImage, SilhouetteMaskRingsTheCoverage) {
  constexpr int kSize = 64;
  const ReferenceImage image = renderReferenceImage(sphereDraw().input(kSize, kSize));
  std::size_t ring = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      bool someDrawn = false, someClear = false, analyticHit = false, analyticMiss = false;
      for (int ny = std::max(0, y - 1); ny <= std::min(kSize - 1, y + 1); ++ny)
        for (int nx = std::max(0, x - 1); nx <= std::min(kSize - 1, x + 1); ++nx)
          (drawn(image, nx, ny) ? someDrawn : someClear) = true;
      for (int ny = y - 2; ny <= y + 2; ++ny)
        for (int nx = x - 2; nx <= x + 2; ++nx)
          (opticsAt(nx, ny, kSize, kCentre, kEta).hit ? analyticHit : analyticMiss) = true;
      const bool expected = someDrawn && someClear;
      EXPECT_EQ(maskAt(image, x, y) == PixelMask::Silhouette, expected) << x << "," << y;
      if (expected) {
        ++ring;
        EXPECT_TRUE(analyticHit && analyticMiss)
            << "silhouette away from the sphere's outline at " << x << "," << y;
      }
    }
  EXPECT_GT(ring, 100u);
}

TEST(OracleReferenceImage, TotalInternalReflectionLookupsAreUndefined) {
  constexpr int kSize = 64;
  // Eta > 1 (leaving glass): refract() returns 0 beyond the critical angle,
  // and with an identity TextureMatrix the zero reaches the lookup.
  const double eta = 1.5;
  const ReferenceImage image = renderReferenceImage(sphereDraw(eta).input(kSize, kSize));
  std::size_t undefined = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const Optics o = opticsAt(x, y, kSize, kCentre, eta);
      if (maskAt(image, x, y) != PixelMask::Undefined) continue;
      ++undefined;
      // Only where all three vertices are past the critical angle.
      EXPECT_LT(o.k, 0.0) << x << "," << y;
    }
  EXPECT_GT(undefined, 50u);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      if (opticsAt(x, y, kSize, kCentre, eta).k > 0.3) {
        EXPECT_NE(maskAt(image, x, y), PixelMask::Undefined) << x << "," << y;
      }
  EXPECT_EQ(renderReferenceImage(sphereDraw().input(kSize, kSize)).count(PixelMask::Undefined), 0u);
}

// A flat quad at eye z = -1 seen with x_clip = x / 2, y_clip = y / 2: the
// quad's corners (+-1.5, +-1.5) are equally far from the eye, so Reflect
// interpolates to exactly (x, y, 1) / |(x, y, 1)| at the eye point (x, y),
// and with Eta = 1 Refract to (x, y, -1) / |...|. On a 254-pixel image,
// pixel centres land exactly on x = +-1 (the +-Z / +-X edges), y = +-1 and
// |x| = |y| (the X / Y edges).
Draw faceEdgeDraw(const CubeMap& environment) {
  Draw draw;
  draw.environment = environment;
  draw.constants["Eta"] = 1.0;
  Mat4d projection = perspective(std::numbers::pi / 2, 1.0, 0.5, 10.0);
  projection[0] = 0.5;
  projection[5] = 0.5;
  draw.setCamera(identity4(), projection);
  const std::uint32_t a = draw.addVertex({-1.5, -1.5, -1, 1}, {0, 0, 1});
  const std::uint32_t b = draw.addVertex({1.5, -1.5, -1, 1}, {0, 0, 1});
  const std::uint32_t c = draw.addVertex({1.5, 1.5, -1, 1}, {0, 0, 1});
  const std::uint32_t d = draw.addVertex({-1.5, 1.5, -1, 1}, {0, 0, 1});
  draw.addTriangle(a, b, c);
  draw.addTriangle(a, c, d);
  return draw;
}

TEST(OracleReferenceImage, FaceEdgeMaskFollowsTheCubeEdgesWhereTheyAreSteps) {
  constexpr int kSize = 254;
  const Draw nearestDraw = faceEdgeDraw(test::faceColoredCubeMap(16, CubeFilter::Nearest));
  const ReferenceImage nearest = renderReferenceImage(nearestDraw.input(kSize, kSize));
  std::size_t onEdge = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      if (!drawn(nearest, x, y) || maskAt(nearest, x, y) == PixelMask::Silhouette) continue;
      const double ex = 2 * ndcOfColumn(x, kSize), ey = 2 * ndcOfRow(y, kSize);
      const bool expected = nearCubeFaceEdge({ex, ey, 1});
      onEdge += expected;
      EXPECT_EQ(maskAt(nearest, x, y) == PixelMask::FaceEdge, expected) << x << "," << y;
    }
  // Two columns and two rows across the middle square, and the diagonals
  // outside it.
  EXPECT_GT(onEdge, 4u * 120u);
  EXPECT_EQ(nearest.count(PixelMask::FaceEdge), onEdge);
  const Draw clampedDraw =
      faceEdgeDraw(test::faceColoredCubeMap(16, CubeFilter::Linear, /*seamless=*/false));
  EXPECT_EQ(renderReferenceImage(clampedDraw.input(kSize, kSize)).count(PixelMask::FaceEdge),
            onEdge);
  const Draw seamlessDraw = faceEdgeDraw(test::faceColoredCubeMap(16, CubeFilter::Linear, true));
  EXPECT_EQ(renderReferenceImage(seamlessDraw.input(kSize, kSize)).count(PixelMask::FaceEdge), 0u);
}

std::size_t differingPixels(const Image& a, const Image& b, int channel, double threshold) {
  std::size_t n = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      n += std::fabs(a.at(x, y)[channel] - b.at(x, y)[channel]) > threshold;
  return n;
}

TEST(OracleReferenceImage, ChangingEtaChangesTheImage) {
  constexpr int kSize = 64;
  const ReferenceImage glass = renderReferenceImage(sphereDraw(0.66).input(kSize, kSize));
  const ReferenceImage water = renderReferenceImage(sphereDraw(0.75).input(kSize, kSize));
  const ReferenceImage again = renderReferenceImage(sphereDraw(0.66).input(kSize, kSize));
  std::size_t covered = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) covered += drawn(glass, x, y);
  std::size_t changed = 0;
  for (int c = 0; c < 3; ++c)
    changed = std::max(changed, differingPixels(glass.color, water.color, c, 0.01));
  EXPECT_GT(changed, covered / 10);
  EXPECT_EQ(glass.color.pixels, again.color.pixels);
}

TEST(OracleReferenceImage, ChromaticWithOneEtaIsTheFresnelImage) {
  constexpr int kSize = 48;
  Draw chromatic = sphereDraw();
  chromatic.useChromatic(0.66, 0.66, 0.66);
  const ReferenceImage a = renderReferenceImage(chromatic.input(kSize, kSize));
  const ReferenceImage b = renderReferenceImage(sphereDraw(0.66).input(kSize, kSize));
  EXPECT_EQ(a.color.pixels, b.color.pixels);
  EXPECT_EQ(a.mask, b.mask);
}

TEST(OracleReferenceImage, ChromaticGreenIsFresnelWithEtaGAndRedDiffers) {
  constexpr int kSize = 48;
  Draw chromatic = sphereDraw();
  chromatic.environment = test::gradientCubeMap(16);
  chromatic.useChromatic(0.55, 0.66, 0.8);
  Draw fresnel = sphereDraw(0.66);
  fresnel.environment = chromatic.environment;
  const ReferenceImage dispersed = renderReferenceImage(chromatic.input(kSize, kSize));
  const ReferenceImage plain = renderReferenceImage(fresnel.input(kSize, kSize));
  EXPECT_EQ(differingPixels(dispersed.color, plain.color, 1, 0.0), 0u);
  EXPECT_GT(differingPixels(dispersed.color, plain.color, 0, 0.001), 100u);
  EXPECT_GT(differingPixels(dispersed.color, plain.color, 2, 0.001), 100u);
}

TEST(OracleReferenceImage, MissingCubeMapOrFragmentPartIsAUsageError) {
  const Draw draw = sphereDraw();
  ReferenceInput unbound = draw.input(16, 16);
  unbound.cubeMaps.clear();
  try {
    renderReferenceImage(unbound);
    FAIL() << "no UsageError";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("Cubemap"), std::string::npos) << e.what();
  }
  ReferenceInput unknown = draw.input(16, 16);
  unknown.oracle = "cg_refraction";
  EXPECT_THROW(renderReferenceImage(unknown), UsageError);
  CubeMap empty;
  ReferenceInput incomplete = draw.input(16, 16);
  incomplete.cubeMaps["Cubemap"] = &empty;
  EXPECT_THROW(renderReferenceImage(incomplete), UsageError);
}

// The size the suite renders: 256 x 256, a 48 x 96 sphere (9216
// triangles). The covered area matches the sphere's analytic outline.
TEST(OracleReferenceImage, Sphere256MatchesTheAnalyticOutline) {
  constexpr int kSize = 256;
  const Draw draw = sphereDraw();
  const auto start = std::chrono::steady_clock::now();
  const ReferenceImage image = renderReferenceImage(draw.input(kSize, kSize));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  RecordProperty("render_seconds", std::to_string(seconds));
  std::size_t covered = 0, analytic = 0, disagree = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const bool hit = opticsAt(x, y, kSize, kCentre, kEta).hit;
      covered += drawn(image, x, y);
      analytic += hit;
      disagree += hit != drawn(image, x, y);
    }
  EXPECT_GT(analytic, 10000u);
  // The 96-gon outline lies inside the circle by well under a pixel.
  EXPECT_LT(disagree, analytic / 100);
  EXPECT_LE(covered, analytic);
}

}  // namespace
}  // namespace snell
