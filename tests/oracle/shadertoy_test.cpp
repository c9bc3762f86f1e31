// The Shadertoy lens, Fresnel lens and bubble through the VertexOracle
// interface, fed as the fragment pipeline feeds them: one "vertex" per
// pixel, uv and point_normal as the completed shader computed them. Here
// the pixels are random uv in [-1, 1]^2 whose rays hit the completion's
// sphere (centre (0, 0, 2), radius 1, eye at the origin), with the exact
// normal at the hit. The expected values are the optics written out
// independently: the ray through the pixel, Snell's law for the refracted
// directions, the mirror law, the post's Fresnel term.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/errors.h"
#include "oracle/vertex_oracle.h"
#include "test_geometry.h"

namespace snell {
namespace {

using test::Dir;

const double kFresnelPower = static_cast<float>(1.97);  // `float fresnelPower = 1.97;`

struct Pixels {
  std::vector<Dir> rays, normals;  // the exact ray through uv; the normal as given
  AttributeMap attributes;
  UniformMap uniforms;
  ConstantMap constants{{"refract_koef", 1.02}, {"fresnelBias", 0.0},    {"fresnelScale", 0.25},
                        {"fresnelPower", 1.97}, {"etaRatioRGB.r", 1.03}, {"etaRatioRGB.g", 1.06},
                        {"etaRatioRGB.b", 1.09}};

  // Pixel 0 looks straight at the sphere's centre: normal incidence.
  Pixels() {
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<float> coordinate(-1.0f, 1.0f);
    AttributeStream uv{"uv", 2, {}}, normal{"point_normal", 3, {}};
    const Dir centre{0.0, 0.0, 2.0};
    while (rays.size() < 1024) {
      const float x = rays.empty() ? 0.0f : coordinate(rng);
      const float y = rays.empty() ? 0.0f : coordinate(rng);
      const Dir ray = test::unit({x, y, 1.0});
      const double b = test::dotOf(ray, centre);
      const double discriminant = b * b - (test::dotOf(centre, centre) - 1.0);
      if (discriminant < 0.0) continue;
      const Dir hit = test::scaled(ray, b - std::sqrt(discriminant));
      const auto n = test::toFloats(test::unit(test::plus(hit, test::scaled(centre, -1.0))));
      rays.push_back(ray);
      normals.push_back({n[0], n[1], n[2]});
      uv.data.insert(uv.data.end(), {x, y});
      normal.data.insert(normal.data.end(), n.begin(), n.end());
    }
    attributes["uv"] = uv;
    attributes["point_normal"] = normal;
  }

  std::vector<OracleVarying> evaluate(const char* oracle) const {
    return makeVertexOracle(oracle)->evaluate(
        OracleInput{uniforms, constants, attributes, rays.size()});
  }
  double cosine(std::size_t p) const { return -test::dotOf(rays[p], normals[p]); }
};

// A copy: the tests often look up an output of a temporary result.
OracleVarying varying(const std::vector<OracleVarying>& all, const std::string& name) {
  for (const OracleVarying& v : all)
    if (v.name == name) return v;
  throw std::runtime_error("no varying " + name);
}

// refract(ray, -n, eta) for the outward unit normal n: the normal refract
// gets points along the ray, so the result keeps the ray's tangential part
// scaled by eta (Snell: sin t = eta sin i) and leaves along +n with length
// 1; zero where eta sin i > 1.
struct Refracted {
  Dir direction;
  double k;  // 1 - eta^2 sin^2 i: negative means totally reflected
};

Refracted snell(const Dir& ray, const Dir& n, double eta) {
  const double cosI = -test::dotOf(ray, n);
  const Dir tangential = test::plus(ray, test::scaled(n, cosI));
  const double k = 1.0 - eta * eta * (1.0 - cosI * cosI);
  if (k < 0.0) return {{0.0, 0.0, 0.0}, k};
  return {test::plus(test::scaled(tangential, eta), test::scaled(n, std::sqrt(k))), k};
}

TEST(OracleShadertoy, OutputsTheCapturedLocals) {
  EXPECT_EQ(makeVertexOracle("shadertoy_lens")->outputs(),
            (std::vector<std::string>{"ray_dir", "refracted_ray"}));
  EXPECT_EQ(makeVertexOracle("shadertoy_lens_fresnel")->outputs(),
            (std::vector<std::string>{"ray_dir", "refracted_ray", "reflected_ray", "mix_coef"}));
  EXPECT_EQ(makeVertexOracle("shadertoy_bubble")->outputs(),
            (std::vector<std::string>{"ray_dir", "TRed", "TGreen", "TBlue", "reflected_ray",
                                      "mix_coef"}));
}

// up * uv.y + right * uv.x + forward with right = cross(up, forward) = +x.
TEST(OracleShadertoy, RayDirIsTheNormalizedPixelDirection) {
  const Pixels pixels;
  for (const char* oracle : {"shadertoy_lens", "shadertoy_lens_fresnel", "shadertoy_bubble"}) {
    const OracleVarying& rayDir = varying(pixels.evaluate(oracle), "ray_dir");
    for (std::size_t p = 0; p < pixels.rays.size(); ++p)
      for (int k = 0; k < 3; ++k) {
        ASSERT_NEAR(rayDir.reference[3 * p + k], pixels.rays[p][k], 1e-12) << oracle << " " << p;
        ASSERT_NEAR(rayDir.strict[3 * p + k], pixels.rays[p][k], 1e-6) << oracle << " " << p;
      }
  }
}

TEST(OracleShadertoy, LensAndConcaveLensRefractBySnellsLaw) {
  for (double koef : {1.02, 0.98}) {
    Pixels pixels;
    pixels.constants["refract_koef"] = koef;
    const double eta = static_cast<float>(koef);
    const OracleVarying& refracted = varying(pixels.evaluate("shadertoy_lens"), "refracted_ray");
    int totallyReflected = 0;
    for (std::size_t p = 0; p < pixels.rays.size(); ++p) {
      const Refracted e = snell(pixels.rays[p], pixels.normals[p], eta);
      if (std::fabs(e.k) < 1e-5) continue;  // rounding may take either branch
      totallyReflected += e.k < 0.0;
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(refracted.reference[3 * p + k], e.direction[k], 1e-6) << koef << " " << p;
        // Near k = 0 the square root magnifies fp32 rounding.
        if (e.k > 1e-2 || e.k < 0.0) {
          EXPECT_NEAR(refracted.strict[3 * p + k], e.direction[k], 1e-5) << koef << " " << p;
        }
      }
    }
    // The convex lens (eta > 1) totally reflects near the silhouette, where
    // sin i > 1 / 1.02; the concave one never does.
    if (koef > 1.0) {
      EXPECT_GT(totallyReflected, 0);
    } else {
      EXPECT_EQ(totallyReflected, 0);
    }
  }
}

TEST(OracleShadertoy, FresnelLensReflectsByTheMirrorLawAndMixesByThePostsTerm) {
  const Pixels pixels;
  const auto out = pixels.evaluate("shadertoy_lens_fresnel");
  const OracleVarying& reflected = varying(out, "reflected_ray");
  const OracleVarying& mixCoef = varying(out, "mix_coef");
  EXPECT_EQ(varying(out, "refracted_ray").reference,
            varying(pixels.evaluate("shadertoy_lens"), "refracted_ray").reference);
  for (std::size_t p = 0; p < pixels.rays.size(); ++p) {
    const Dir& ray = pixels.rays[p];
    const Dir& n = pixels.normals[p];
    const Dir mirror = test::plus(ray, test::scaled(n, 2.0 * pixels.cosine(p)));
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(reflected.reference[3 * p + k], mirror[k], 1e-12) << p;
      EXPECT_NEAR(reflected.strict[3 * p + k], mirror[k], 1e-5) << p;
    }
    // 0.25 (1 - cos i)^1.97: 0 head on, growing toward the silhouette.
    if (mixCoef.undefined[p]) continue;
    const double expected = 0.25 * std::pow(1.0 - pixels.cosine(p), kFresnelPower);
    EXPECT_NEAR(mixCoef.reference[p], expected, 1e-12) << p;
    EXPECT_NEAR(mixCoef.strict[p], expected, 1e-6) << p;
  }
}

TEST(OracleShadertoy, MixCoefIsUndefinedWherePowsBaseMayBeNegative) {
  const Pixels pixels;
  for (const char* oracle : {"shadertoy_lens_fresnel", "shadertoy_bubble"}) {
    for (const OracleVarying& out : pixels.evaluate(oracle)) {
      if (out.name != "mix_coef") {
        for (std::uint8_t flag : out.undefined) ASSERT_EQ(flag, 0) << oracle << " " << out.name;
        continue;
      }
      // Head on, 1.0 + dot(ray_dir, point_normal) is 0 up to rounding.
      EXPECT_NEAR(pixels.cosine(0), 1.0, 1e-7);
      EXPECT_EQ(out.undefined[0], 1) << oracle;
      for (std::size_t p = 0; p < pixels.rays.size(); ++p) {
        if (pixels.cosine(p) < 0.99) {
          EXPECT_EQ(out.undefined[p], 0) << oracle << " " << p;
        }
      }
    }
  }
}

// Whether `sample` of a refracted output has k = 1 - eta^2 (1 - cos^2) below
// 1e-3, where sqrt(k)'s slope makes a legitimately wide interval.
bool nearCritical(const Pixels& pixels, const std::string& oracle, const std::string& output,
                  std::size_t sample) {
  double eta = 0.0;
  if (output == "TRed") eta = 1.03;
  if (output == "TGreen") eta = 1.06;
  if (output == "TBlue") eta = 1.09;
  if (output == "refracted_ray")
    eta = pixels.constants.count("refract_koef") ? pixels.constants.at("refract_koef") : 1.02;
  if (eta == 0.0 || oracle.empty()) return false;
  const double c = pixels.cosine(sample);
  return 1.0 - eta * eta * (1.0 - c * c) < 1e-3;
}

TEST(OracleShadertoy, IntervalsHoldTheDoubleAndFloatResults) {
  Pixels concave;
  concave.constants["refract_koef"] = 0.98;
  const std::pair<const char*, const Pixels*> runs[] = {{"shadertoy_lens", nullptr},
                                                        {"shadertoy_lens", &concave},
                                                        {"shadertoy_lens_fresnel", nullptr},
                                                        {"shadertoy_bubble", nullptr}};
  const Pixels pixels;
  for (const auto& [oracle, input] : runs) {
    const Pixels& in = input ? *input : pixels;
    for (const OracleVarying& out : in.evaluate(oracle)) {
      int either = 0;
      int steep = 0;
      for (std::size_t k = 0; k < out.reference.size(); ++k) {
        if (out.undefined[k]) continue;  // MixCoefIsUndefinedWherePowsBaseMayBeNegative
        ASSERT_LE(out.lo[k], out.reference[k]) << oracle << " " << out.name << " " << k;
        ASSERT_LE(out.reference[k], out.hi[k]) << oracle << " " << out.name << " " << k;
        ASSERT_LE(out.lo[k], out.strict[k]) << oracle << " " << out.name << " " << k;
        ASSERT_LE(out.strict[k], out.hi[k]) << oracle << " " << out.name << " " << k;
        // Where refract()'s k may round either way the interval is the union
        // of the ray and zero; just short of that, sqrt(k) multiplies every
        // rounding of k by 1 / (2 sqrt(k)); elsewhere tight.
        if (out.lo[k] <= 0.0 && out.hi[k] >= 0.0 && out.hi[k] - out.lo[k] > 1e-3) {
          ++either;
        } else if (nearCritical(in, oracle, out.name,
                                k / static_cast<std::size_t>(out.components))) {
          ++steep;
        } else {
          EXPECT_LT(out.hi[k] - out.lo[k], 1e-4) << oracle << " " << out.name << " " << k;
        }
      }
      if (out.name == "ray_dir" || out.name == "reflected_ray" || out.name == "mix_coef") {
        EXPECT_EQ(either, 0) << oracle << " " << out.name;
        EXPECT_EQ(steep, 0) << oracle << " " << out.name;
      }
    }
  }
}

// etaRatioRGB.g is a lens with refract_koef 1.06, and so on; the reflection
// and the mix are the Fresnel lens's lines.
TEST(OracleShadertoy, BubbleRefractsEachColourAsALensWithItsCoefficient) {
  const Pixels pixels;
  const auto bubble = pixels.evaluate("shadertoy_bubble");
  const std::pair<const char*, double> channels[] = {
      {"TRed", 1.03}, {"TGreen", 1.06}, {"TBlue", 1.09}};
  for (const auto& [name, koef] : channels) {
    Pixels lens;
    lens.constants["refract_koef"] = koef;
    const OracleVarying& expected = varying(lens.evaluate("shadertoy_lens"), "refracted_ray");
    EXPECT_EQ(varying(bubble, name).reference, expected.reference) << name;
    EXPECT_EQ(varying(bubble, name).strict, expected.strict) << name;
    EXPECT_EQ(varying(bubble, name).lo, expected.lo) << name;
    EXPECT_EQ(varying(bubble, name).hi, expected.hi) << name;
  }
  const auto fresnel = pixels.evaluate("shadertoy_lens_fresnel");
  for (const char* name : {"ray_dir", "reflected_ray", "mix_coef"}) {
    EXPECT_EQ(varying(bubble, name).lo, varying(fresnel, name).lo) << name;
    EXPECT_EQ(varying(bubble, name).hi, varying(fresnel, name).hi) << name;
  }
}

// 1.03 where the post prints 1.02 moves every refracted ray that is neither
// head on nor totally reflected out of its interval.
TEST(OracleShadertoy, AChangedKoefMovesTheRefractedRayOutOfItsInterval) {
  const Pixels printed;
  Pixels changed;
  changed.constants["refract_koef"] = 1.03;
  const OracleVarying& allowed = varying(printed.evaluate("shadertoy_lens"), "refracted_ray");
  const OracleVarying& moved = varying(changed.evaluate("shadertoy_lens"), "refracted_ray");
  std::size_t outside = 0, compared = 0;
  for (std::size_t p = 1; p < printed.rays.size(); ++p) {
    if (snell(printed.rays[p], printed.normals[p], 1.03).k < 1e-3) continue;
    bool out = false;
    for (std::size_t k = 3 * p; k < 3 * p + 3; ++k)
      out = out || moved.strict[k] < allowed.lo[k] || moved.strict[k] > allowed.hi[k];
    outside += out;
    ++compared;
  }
  EXPECT_GT(compared, printed.rays.size() / 2);
  EXPECT_EQ(outside, compared);
}

TEST(OracleShadertoy, NamesAMissingConstant) {
  Pixels pixels;
  pixels.constants.erase("etaRatioRGB.g");
  try {
    pixels.evaluate("shadertoy_bubble");
    FAIL() << "no UsageError";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("etaRatioRGB.g"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace snell
