// A scene's [model] scale: the stretched scene's modelview is not a
// rotation, so NormalMatrix gives eye-space normals of many lengths (the
// listings' normalize() calls matter there), yet it is still the inverse
// transpose (normals stay perpendicular to the surface); a scale that
// mirrors or flattens the model is refused with file and line.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/errors.h"
#include "core/scene.h"

namespace snell {
namespace {

std::array<double, 3> times3(const Value& m, const float* v) {
  std::array<double, 3> out{};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out[r] += double(m.data[c * 3 + r]) * v[c];
  return out;
}

TEST(SceneScale, StretchedNormalsAreNotUnitButStayPerpendicular) {
  const Scene s = makeScene("stretched");
  const Value& normalMatrix = s.values.at("normal_matrix");
  const Value& modelview = s.values.at("modelview");
  const auto& n = s.attributes.at("normal").data;
  const auto& t = s.attributes.at("tangent").data;
  double shortest = 1e9, longest = 0;
  for (std::size_t k = 0; k < s.vertexCount; ++k) {
    const std::array<double, 3> eyeNormal = times3(normalMatrix, &n[k * 3]);
    double length = 0;
    for (double x : eyeNormal) length += x * x;
    length = std::sqrt(length);
    shortest = std::min(shortest, length);
    longest = std::max(longest, length);
    // A tangent maps by the modelview's upper 3x3: still perpendicular.
    std::array<double, 3> eyeTangent{};
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) eyeTangent[r] += double(modelview.data[c * 4 + r]) * t[k * 3 + c];
    double along = 0;
    for (int c = 0; c < 3; ++c) along += eyeNormal[c] * eyeTangent[c];
    EXPECT_NEAR(along, 0, 1e-5) << k;
  }
  EXPECT_LT(shortest, 0.7);
  EXPECT_GT(longest, 1.5);
}

TEST(SceneScale, UnscaledScenesKeepUnitNormals) {
  const Scene s = makeScene("sphere");
  const std::array<double, 3> n =
      times3(s.values.at("normal_matrix"), &s.attributes.at("normal").data[300]);
  EXPECT_NEAR(std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), 1.0, 1e-6);
}

TEST(SceneScale, AMirroringScaleIsRefusedWithFileAndLine) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "snell-scene-scale-test";
  fs::create_directories(dir);
  std::ofstream(dir / "flat.toml") << "[geometry]\nshape = \"sphere\"\nstacks = 4\nslices = 8\n"
                                      "[model]\nscale = [1.0, -1.0, 1.0]\n[camera]\n"
                                      "[image]\nwidth = 8\nheight = 8\n";
  try {
    makeScene("flat", {dir});
    FAIL();
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("flat.toml:6: `scale` must hold three numbers > 0"),
              std::string::npos)
        << error.what();
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace snell
