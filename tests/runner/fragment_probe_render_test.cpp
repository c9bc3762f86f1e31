// Fragment probes through both backends: each probe's value lands in its
// own float target, written pixels have alpha 1, pixels the probe's
// statement never ran for (outside the triangles, or a branch not taken)
// keep alpha 0, and the listing's own output still lands in target 0.
#include <gtest/gtest.h>

#include <string>

#include "backends/backend.h"

namespace snell {
namespace {

constexpr int kWidth = 6;
constexpr int kHeight = 8;

const char* kVertex = R"(#version 140
in vec3 position;
void main() { gl_Position = vec4(position, 1.0); }
)";

// Line numbers matter: the probes name lines 4, 5 and 7.
const char* kFragment = R"(#version 140
out vec4 FragColor;
void main() {
  vec2 p = gl_FragCoord.xy;
  float s = p.x * 0.5 + p.y;
  if (p.x < 3.0) {
    vec3 d = vec3(p, 7.0);
  }
  FragColor = vec4(0.25, 0.5, 0.75, 1.0);
}
)";

// The same in legacy GLSL: gl_FragColor cannot sit beside user outputs.
const char* kLegacyVertex = R"(attribute vec3 position;
void main() { gl_Position = vec4(position, 1.0); }
)";
const char* kLegacyFragment = R"(// Line numbers as in kFragment:
// no #version, so GLSL 1.10.
void main() {
  vec2 p = gl_FragCoord.xy;
  float s = p.x * 0.5 + p.y;
  if (p.x < 3.0) {
    vec3 d = vec3(p, 7.0);
  }
  gl_FragColor = vec4(0.25, 0.5, 0.75, 1.0);
}
)";

// A triangle covering the top half of clip space (image rows 0 to 3).
RenderJob topHalfJob(const char* vertex, const char* fragment, Profile profile) {
  RenderJob job;
  job.program.vertex = vertex;
  job.program.fragment = fragment;
  job.program.vertexPath = "probe.vert";
  job.program.fragmentPath = "probe.frag";
  job.program.profile = profile;
  job.attributes["position"] = {"position", 3, {-1, 0, 0.5f, 3, 0, 0.5f, -1, 4, 0.5f}};
  job.indices = {0, 1, 2};
  job.width = kWidth;
  job.height = kHeight;
  job.probes = {{"p", ValueType::Vec2, 4}, {"s", ValueType::Float, 5}, {"d", ValueType::Vec3, 7}};
  return job;
}

// Which way gl_FragCoord counts rows in what a backend ran.
enum class RowOrigin { Bottom, Top };

void expectProbes(const std::string& backendName, const RenderOutcome& outcome,
                  RowOrigin origin) {
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  ASSERT_EQ(outcome.probes.size(), 3u);
  for (int row = 0; row < kHeight; ++row)
    for (int x = 0; x < kWidth; ++x) {
      SCOPED_TRACE(backendName + " pixel " + std::to_string(x) + "," + std::to_string(row));
      const float* p = outcome.probes[0].at(x, row);
      const float* s = outcome.probes[1].at(x, row);
      const float* d = outcome.probes[2].at(x, row);
      if (row >= kHeight / 2) {  // not covered: nothing written anywhere
        for (const float* probe : {p, s, d})
          for (int c = 0; c < 4; ++c) EXPECT_EQ(probe[c], 0.0f);
        continue;
      }
      const float fx = static_cast<float>(x) + 0.5f;
      const float fy =
          static_cast<float>(origin == RowOrigin::Bottom ? kHeight - 1 - row : row) + 0.5f;
      EXPECT_EQ(p[0], fx);
      EXPECT_EQ(p[1], fy);
      EXPECT_EQ(p[2], 0.0f);
      EXPECT_EQ(p[3], 1.0f);
      EXPECT_EQ(s[0], fx * 0.5f + fy);
      EXPECT_EQ(s[3], 1.0f);
      if (fx < 3.0f) {
        EXPECT_EQ(d[0], fx);
        EXPECT_EQ(d[1], fy);
        EXPECT_EQ(d[2], 7.0f);
        EXPECT_EQ(d[3], 1.0f);
      } else {
        EXPECT_EQ(d[3], 0.0f);  // the branch did not run
      }
      const float* colour = outcome.image.at(x, row);
      EXPECT_EQ(colour[0], 0.25f);
      EXPECT_EQ(colour[3], 1.0f);
    }
}

class FragmentProbeRender : public testing::TestWithParam<const char*> {};

// A core listing runs unmodified: gl_FragCoord's origin is the lower left
// in OpenGL and the upper left in Vulkan, and the probes show each.
TEST_P(FragmentProbeRender, CoreListing) {
  std::unique_ptr<Backend> backend = makeBackend(GetParam(), BackendOptions{.validation = true});
  expectProbes(GetParam(), backend->render(topHalfJob(kVertex, kFragment, Profile::Core)),
               std::string(GetParam()) == "gl" ? RowOrigin::Bottom : RowOrigin::Top);
}

// A legacy listing runs with OpenGL's meaning on both: gl_FragData on
// OpenGL, and on Vulkan the legacy adapter, which also mirrors gl_FragCoord
// to count rows from the bottom.
TEST_P(FragmentProbeRender, LegacyListingSeesOpenGLsRowOrder) {
  std::unique_ptr<Backend> backend = makeBackend(GetParam(), BackendOptions{.validation = true});
  expectProbes(GetParam(),
               backend->render(topHalfJob(kLegacyVertex, kLegacyFragment, Profile::Compatibility)),
               RowOrigin::Bottom);
}

TEST_P(FragmentProbeRender, WithoutProbesTheListingRendersAsBefore) {
  std::unique_ptr<Backend> backend = makeBackend(GetParam(), BackendOptions{.validation = true});
  RenderJob job = topHalfJob(kVertex, kFragment, Profile::Core);
  job.probes.clear();
  const RenderOutcome outcome = backend->render(job);
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  EXPECT_TRUE(outcome.probes.empty());
  EXPECT_EQ(outcome.image.at(0, 0)[2], 0.75f);
}

INSTANTIATE_TEST_SUITE_P(Backends, FragmentProbeRender, testing::Values("gl", "vk"));

}  // namespace
}  // namespace snell
