// Listing 14.1 (Orange Book, Fresnel reflection/refraction vertex shader),
// run as published on the Vulkan backend with validation on.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "backends/vk/vk_backend.h"
#include "reference_math.h"
#include "vk_test_support.h"

namespace snell {
namespace {

using vktest::Vec3d;

const char* kVertexPath = "shaders/orange-book/14.1-fresnel/fresnel.vert";
const char* kFragmentPath = "shaders/orange-book/14.1-fresnel/fresnel.frag";

ProgramSource listing() {
  ProgramSource program;
  program.vertex = vktest::readSourceFile(kVertexPath);
  program.fragment = vktest::readSourceFile(kFragmentPath);
  program.vertexPath = kVertexPath;
  program.fragmentPath = kFragmentPath;
  return program;
}

std::vector<float> identity(int size) {
  std::vector<float> m(static_cast<std::size_t>(size * size), 0.0f);
  for (int i = 0; i < size; ++i) m[static_cast<std::size_t>(i * size + i)] = 1.0f;
  return m;
}

TEST(VkListing14_1, CompilesOnTheBackend) {
  auto backend = makeVkBackend(BackendOptions{.validation = true});
  const CompileOutcome outcome = backend->compile(listing());
  EXPECT_TRUE(outcome.ok) << outcome.log;
  EXPECT_EQ(outcome.log, "");
}

TEST(VkListing14_1, CapturesReflectRefractAndRatio) {
  auto backend = makeVkBackend(BackendOptions{.validation = true});
  CaptureJob job;
  job.program = listing();
  job.varyings = {"Reflect", "Refract", "Ratio"};
  // Identity matrices: eye space is model space, so the listing reduces to
  // reflect/refract of the normalised position against the normal.
  job.uniforms["MVMatrix"] = {ValueType::Mat4, identity(4)};
  job.uniforms["MVPMatrix"] = {ValueType::Mat4, identity(4)};
  job.uniforms["NormalMatrix"] = {ValueType::Mat3, identity(3)};
  job.uniforms["TextureMatrix"] = {ValueType::Mat4, identity(4)};
  // Points on a sphere of radius 2 around (0, 0, -5), seen from the origin.
  AttributeStream& vertex = job.attributes["MCvertex"] = {"MCvertex", 4, {}};
  AttributeStream& normal = job.attributes["MCnormal"] = {"MCnormal", 3, {}};
  for (int ring = 0; ring < 12; ++ring) {
    for (int step = 0; step < 16; ++step) {
      const double theta = 0.1 + 2.9 * ring / 11.0, phi = 6.2831853 * step / 16.0;
      const Vec3d n = {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                       std::cos(theta)};
      for (int c = 0; c < 3; ++c) {
        vertex.data.push_back(static_cast<float>(2 * n[c] + (c == 2 ? -5.0 : 0.0)));
        normal.data.push_back(static_cast<float>(n[c]));
      }
      vertex.data.push_back(1.0f);
    }
  }
  job.vertexCount = vertex.vertexCount();

  const CaptureOutcome outcome = backend->captureVertexOutputs(job);
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  ASSERT_EQ(outcome.varyings.size(), 3u);
  const CapturedVarying& reflected = outcome.varyings[0];
  const CapturedVarying& refracted = outcome.varyings[1];
  const CapturedVarying& ratio = outcome.varyings[2];
  ASSERT_EQ(reflected.name, "Reflect");
  ASSERT_EQ(ratio.components, 1);
  ASSERT_EQ(ratio.data.size(), job.vertexCount);

  // A plumbing check with loose bounds (the listing oracle owns the real
  // ones): normalize() adds a few ULPs over the reflect/refract probe, so
  // 16 * FLT_EPSILON. pow(x, 5) is exp2(5 * log2(x)): an absolute log2 error
  // of 2^-21 becomes a relative error of 5 * 2^-21 * ln 2 ~ 1.7e-6, and
  // exp2 adds up to 13 ULPs (~1.5e-6); Ratio reaches ~30 on the far side of
  // the sphere, where 1 - dot(-i, n) approaches 2. Hence 1e-5 relative.
  const double eta = static_cast<double>(0.66f);
  const double f = ((1 - eta) * (1 - eta)) / ((1 + eta) * (1 + eta));
  for (std::size_t v = 0; v < job.vertexCount; ++v) {
    const Vec3d i =
        vktest::normalizeRef({vertex.data[4 * v], vertex.data[4 * v + 1], vertex.data[4 * v + 2]});
    const Vec3d n =
        vktest::normalizeRef({normal.data[3 * v], normal.data[3 * v + 1], normal.data[3 * v + 2]});
    const Vec3d expectReflect = vktest::reflectRef(i, n);
    const Vec3d expectRefract = vktest::refractRef(i, n, eta);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(reflected.data[3 * v + c], expectReflect[c], 16 * FLT_EPSILON) << "vertex " << v;
      EXPECT_NEAR(refracted.data[3 * v + c], expectRefract[c], 16 * FLT_EPSILON) << "vertex " << v;
    }
    const double expectRatio =
        f + (1 - f) * std::pow(1 - vktest::dot({-i[0], -i[1], -i[2]}, n), 5.0);
    EXPECT_NEAR(ratio.data[v], expectRatio, 1e-5 * std::max(1.0, expectRatio)) << "vertex " << v;
  }
}

}  // namespace
}  // namespace snell
