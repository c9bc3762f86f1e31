// Section 14.2's diffraction listing: lambda2rgb against values worked out
// by hand, and the oracle's intervals on the real sphere scene, bound as the
// manifest binds it.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "core/case.h"
#include "core/manifest.h"
#include "core/scene.h"
#include "oracle/listings/orange_book_diffraction.h"
#include "oracle/vertex_oracle.h"

namespace snell {
namespace {

using Listing = listings::OrangeBookDiffraction<double>;

// a = (lambda - 400) / 300, b = a - (0.75, 0.5, 0.25), max(1 - 10 b^2, 0).
TEST(OracleOrangeBookDiffraction, Lambda2rgbAtHandComputedWavelengths) {
  const auto at = [](double lambda) { return Listing::lambda2rgb(lambda, 400.0, 700.0, 10.0); };
  // 400 nm: a = 0, b = (-0.75, -0.5, -0.25): 1 - (5.625, 2.5, 0.625).
  const auto violet = at(400.0);
  EXPECT_DOUBLE_EQ(violet[0], 0.0);
  EXPECT_DOUBLE_EQ(violet[1], 0.0);
  EXPECT_DOUBLE_EQ(violet[2], 0.375);
  // 550 nm: a = 0.5, b = (-0.25, 0, 0.25): 1 - (0.625, 0, 0.625).
  const auto green = at(550.0);
  EXPECT_DOUBLE_EQ(green[0], 0.375);
  EXPECT_DOUBLE_EQ(green[1], 1.0);
  EXPECT_DOUBLE_EQ(green[2], 0.375);
  // 700 nm: a = 1, b = (0.25, 0.5, 0.75): 1 - (0.625, 2.5, 5.625).
  const auto red = at(700.0);
  EXPECT_DOUBLE_EQ(red[0], 0.375);
  EXPECT_DOUBLE_EQ(red[1], 0.0);
  EXPECT_DOUBLE_EQ(red[2], 0.0);
}

TEST(OracleOrangeBookDiffraction, IntervalsHoldTheDoubleAndFloatResultsOnTheSphere) {
  const Manifest manifest = loadManifest(std::filesystem::path(SNELL_SOURCE_ROOT) /
                                         "shaders/orange-book/14.2-diffraction/manifest.toml");
  const Scene scene = makeScene("sphere");
  const ResolvedBindings bindings = resolveBindings(manifest, scene);
  const auto oracle = makeVertexOracle(manifest.oracle);
  const std::vector<OracleVarying> varyings = oracle->evaluate(
      {bindings.uniforms, manifest.constants, bindings.attributes, bindings.vertexCount});
  const OracleVarying* color = nullptr;
  for (const OracleVarying& v : varyings)
    if (v.name == "Color") color = &v;
  ASSERT_NE(color, nullptr);
  ASSERT_EQ(color->components, 4);
  std::size_t undefined = 0, checked = 0;
  for (std::size_t k = 0; k < color->reference.size(); ++k) {
    if (color->undefined[k]) {
      ++undefined;
      continue;
    }
    ++checked;
    EXPECT_LE(color->lo[k], color->reference[k]) << k;
    EXPECT_GE(color->hi[k], color->reference[k]) << k;
    EXPECT_LE(color->lo[k], static_cast<double>(color->strict[k])) << k;
    EXPECT_GE(color->hi[k], static_cast<double>(color->strict[k])) << k;
  }
  // Only `2.0 * u / w` with w = dot(Normal, HalfVec) near 0 leaves Color
  // undefined: a thin band of the sphere, a small share of the samples.
  std::printf("Color components: %zu checked, %zu undefined of %zu\n", checked, undefined,
              color->reference.size());
  EXPECT_LT(undefined * 50, color->reference.size());
  EXPECT_GT(checked, 0u);
}

}  // namespace
}  // namespace snell
