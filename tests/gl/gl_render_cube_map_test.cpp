// Cube map lookups in a fragment shader land on the texels cube_map.h
// says: face order +X -X +Y -Y +Z -Z, row j of the data is t in
// [j/size, (j+1)/size], base level only.
#include <gtest/gtest.h>

#include <array>
#include <stdexcept>
#include <string>

#include "backends/gl/gl_backend.h"
#include "core/errors.h"
#include "gl_render_test_jobs.h"

namespace snell {
namespace {

using gltest::Rgba;

struct Lookup {
  std::array<float, 3> direction;
  int face, i, j;  // the texel NEAREST must return
};

Rgba lookup(Backend& backend, const CubeMap& map, std::array<float, 3> direction) {
  const RenderOutcome outcome = backend.render(gltest::lookupJob(map, direction));
  if (!outcome.compile.ok) throw std::runtime_error(outcome.compile.log);
  // The direction is uniform, so every pixel must agree.
  const Rgba first = gltest::pixel(outcome.image, 0, 0);
  EXPECT_EQ(gltest::pixelsOtherThan(outcome.image, first, 0, 0, 4, 4), 0);
  return first;
}

TEST(GlRenderCubeMap, NearestAtEachFaceCentreReturnsThatFacesCentreTexel) {
  auto backend = makeGlBackend({});
  const CubeMap map = gltest::distinctTexelCubeMap(3, CubeFilter::Nearest);
  const std::array<Lookup, 6> centres = {{{{1, 0, 0}, 0, 1, 1},
                                          {{-1, 0, 0}, 1, 1, 1},
                                          {{0, 1, 0}, 2, 1, 1},
                                          {{0, -1, 0}, 3, 1, 1},
                                          {{0, 0, 1}, 4, 1, 1},
                                          {{0, 0, -1}, 5, 1, 1}}};
  for (const Lookup& centre : centres)
    EXPECT_EQ(lookup(*backend, map, centre.direction),
              gltest::texelColour(centre.face, centre.i, centre.j))
        << "face " << centre.face;
}

TEST(GlRenderCubeMap, NearestOffCentreFollowsTheRowOrder) {
  auto backend = makeGlBackend({});
  const CubeMap map = gltest::distinctTexelCubeMap(3, CubeFilter::Nearest);
  // (s, t) = (0.2, 0.2) on +Z and (0.8, 0.2) on +Y, by the cube map rules.
  const std::array<Lookup, 2> corners = {{{{-0.6f, 0.6f, 1}, 4, 0, 0},
                                          {{0.6f, 1, -0.6f}, 2, 2, 0}}};
  for (const Lookup& corner : corners)
    EXPECT_EQ(lookup(*backend, map, corner.direction),
              gltest::texelColour(corner.face, corner.i, corner.j))
        << "face " << corner.face;
}

Rgba averageOf4(int face, int i, int j) {
  Rgba sum{};
  for (int dj = 0; dj < 2; ++dj)
    for (int di = 0; di < 2; ++di) {
      const Rgba texel = gltest::texelColour(face, i + di, j + dj);
      for (int c = 0; c < 4; ++c) sum[static_cast<std::size_t>(c)] += texel[static_cast<std::size_t>(c)] / 4;
    }
  return sum;
}

// A direction at a texel corner weighs its four texels by exactly 1/2 and
// 1/2 in each axis, which llvmpipe's 8-bit filter weights hold exactly.
TEST(GlRenderCubeMap, LinearAtATexelCornerAveragesItsFourTexels) {
  auto backend = makeGlBackend({});
  const CubeMap map = gltest::distinctTexelCubeMap(4, CubeFilter::Linear);
  // (s, t) = (0.25, 0.25) on +Z; (0.75, 0.25) on -X.
  const std::array<Lookup, 2> corners = {{{{-0.5f, 0.5f, 1}, 4, 0, 0},
                                          {{-1, 0.5f, 0.5f}, 1, 2, 0}}};
  for (const Lookup& corner : corners) {
    const Rgba got = lookup(*backend, map, corner.direction);
    const Rgba expected = averageOf4(corner.face, corner.i, corner.j);
    for (std::size_t c = 0; c < 4; ++c)
      EXPECT_NEAR(got[c], expected[c], 1e-6) << "face " << corner.face << " channel " << c;
  }
}

TEST(GlRenderCubeMap, SeamlessFilteringReachesTheNeighbouringFace) {
  auto backend = makeGlBackend({});
  const Rgba positiveZ = {0.1f, 0.2f, 0.3f, 0.4f};
  const Rgba positiveX = {0.9f, 0.8f, 0.7f, 0.6f};
  CubeMap map;
  map.size = 2;
  map.filter = CubeFilter::Linear;
  for (int face = 0; face < 6; ++face) {
    const Rgba colour = face == 4 ? positiveZ : face == 0 ? positiveX : Rgba{0, 0, 0, 0};
    for (int texel = 0; texel < 4; ++texel)
      map.faces[static_cast<std::size_t>(face)].insert(
          map.faces[static_cast<std::size_t>(face)].end(), colour.begin(), colour.end());
  }
  // On +Z, half a texel from its edge with +X: the filter footprint
  // straddles the edge.
  const std::array<float, 3> nearEdge = {0.999f, 0, 1};

  map.seamless = false;
  const Rgba clamped = lookup(*backend, map, nearEdge);
  for (std::size_t c = 0; c < 4; ++c) EXPECT_NEAR(clamped[c], positiveZ[c], 1e-6) << c;

  map.seamless = true;
  const Rgba seamless = lookup(*backend, map, nearEdge);
  EXPECT_GT(seamless[0], positiveZ[0] + 0.3f) << "no +X texel was blended in";
  EXPECT_LT(seamless[0], positiveX[0]);
}

TEST(GlRenderCubeMap, SamplerWithoutACubeMapIsAUsageErrorNamingIt) {
  auto backend = makeGlBackend({});
  const CubeMap map = gltest::distinctTexelCubeMap(2, CubeFilter::Nearest);
  RenderJob job = gltest::lookupJob(map, {0, 0, 1});
  job.cubeMaps.clear();
  job.cubeMaps["Other"] = &map;
  try {
    backend->render(job);
    FAIL() << "expected UsageError";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("'Env'"), std::string::npos) << error.what();
  }
}

TEST(GlRenderCubeMap, FaceOfTheWrongSizeIsAUsageError) {
  auto backend = makeGlBackend({});
  CubeMap map = gltest::distinctTexelCubeMap(2, CubeFilter::Nearest);
  map.faces[3].resize(12);
  try {
    backend->render(gltest::lookupJob(map, {0, 0, 1}));
    FAIL() << "expected UsageError";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("face 3"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace snell
