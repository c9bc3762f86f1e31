// Listing 14.1 through the VertexOracle interface, on a unit sphere seen from
// a rotated camera, with a TextureMatrix that rotates and translates. The
// expected values are the optics written out independently: reflection as
// i + 2 cos(theta) n, refraction from Snell's law, Schlick's approximation.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/errors.h"
#include "oracle/vertex_oracle.h"
#include "test_geometry.h"

namespace snell {
namespace {

using test::Dir;

// A rigid transform: x -> R x + t, R column-major.
struct Rigid {
  std::array<double, 9> R;
  Dir t;
  Dir apply(const Dir& x) const { return test::plus(rotate(x), t); }
  Dir rotate(const Dir& x) const {
    return {R[0] * x[0] + R[3] * x[1] + R[6] * x[2], R[1] * x[0] + R[4] * x[1] + R[7] * x[2],
            R[2] * x[0] + R[5] * x[1] + R[8] * x[2]};
  }
  Dir rotateBack(const Dir& x) const {  // R^T x
    return {R[0] * x[0] + R[1] * x[1] + R[2] * x[2], R[3] * x[0] + R[4] * x[1] + R[5] * x[2],
            R[6] * x[0] + R[7] * x[1] + R[8] * x[2]};
  }
};

// Rodrigues' rotation, rounded to float as a uniform would be.
Rigid rigid(Dir axis, double angle, Dir translation) {
  axis = test::unit(axis);
  const double c = std::cos(angle), s = std::sin(angle), C = 1 - c;
  const double x = axis[0], y = axis[1], z = axis[2];
  const std::array<double, 9> rowMajor = {x * x * C + c,     x * y * C - z * s, x * z * C + y * s,
                                          y * x * C + z * s, y * y * C + c,     y * z * C - x * s,
                                          z * x * C - y * s, z * y * C + x * s, z * z * C + c};
  Rigid r{};
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 3; ++column)
      r.R[column * 3 + row] = static_cast<float>(rowMajor[row * 3 + column]);
  }
  for (int k = 0; k < 3; ++k) r.t[k] = static_cast<float>(translation[k]);
  return r;
}

Value mat4Of(const Rigid& m) {
  Value v{ValueType::Mat4, std::vector<float>(16, 0.0f)};
  for (int column = 0; column < 3; ++column) {
    for (int row = 0; row < 3; ++row)
      v.data[column * 4 + row] = static_cast<float>(m.R[column * 3 + row]);
  }
  for (int row = 0; row < 3; ++row) v.data[12 + row] = static_cast<float>(m.t[row]);
  v.data[15] = 1.0f;
  return v;
}

Value mat3Of(const Rigid& m) {
  Value v{ValueType::Mat3, {}};
  for (double e : m.R) v.data.push_back(static_cast<float>(e));
  return v;
}

struct Scene {
  Rigid modelView = rigid({1, 2, 3}, 0.3, {0.1, -0.2, -5.0});
  Rigid texture = rigid({0, 1, 0}, 0.7, {0.25, -0.5, 1.0});
  UniformMap uniforms;
  ConstantMap constants{{"Eta", 0.66}, {"FresnelPower", 5.0}};
  AttributeMap attributes;
  std::vector<Dir> positions;  // on the unit sphere, as given to the shader
  std::size_t facingVertex = 0;

  Scene() {
    uniforms["MVMatrix"] = mat4Of(modelView);
    // The projection plays no part in the captured vectors.
    uniforms["MVPMatrix"] = mat4Of(rigid({0, 0, 1}, 0.1, {0, 0, -1}));
    // For a rotation the normal matrix (inverse transpose) is the rotation.
    uniforms["NormalMatrix"] = mat3Of(modelView);
    uniforms["TextureMatrix"] = mat4Of(texture);
    // The point that faces the camera head on (normal incidence), then
    // points round the sphere to near the silhouette.
    positions.push_back(modelView.rotateBack(test::unit(test::scaled(modelView.t, -1.0))));
    std::mt19937_64 rng(5);
    while (positions.size() < 24) {
      const Dir p = test::randomUnit(rng);
      if (test::dotOf(modelView.rotate(p), test::unit(test::scaled(modelView.t, -1.0))) > 0.25)
        positions.push_back(p);
    }
    AttributeStream vertex{"MCvertex", 4, {}};
    AttributeStream normal{"MCnormal", 3, {}};
    for (Dir& p : positions) {
      const auto f = test::toFloats(p);
      p = {f[0], f[1], f[2]};
      vertex.data.insert(vertex.data.end(), {f[0], f[1], f[2], 1.0f});
      normal.data.insert(normal.data.end(), f.begin(), f.end());
    }
    attributes["MCvertex"] = vertex;
    attributes["MCnormal"] = normal;
  }

  OracleInput input() const {
    return OracleInput{uniforms, constants, attributes, positions.size()};
  }
};

const double kEta = static_cast<float>(0.66);  // `const float Eta = 0.66;`

double schlickF(double eta) { return ((1 - eta) * (1 - eta)) / ((1 + eta) * (1 + eta)); }

struct Expected {
  Dir reflect, refract;
  double ratio;
  double cosine;  // dot(-i, n)
};

Expected expectedAt(const Scene& scene, const Dir& position) {
  const Dir i = test::unit(scene.modelView.apply(position));
  const Dir n = test::unit(scene.modelView.rotate(position));
  const double cosine = -test::dotOf(i, n);
  const Dir reflected = test::plus(i, test::scaled(n, 2.0 * cosine));
  const double sinT2 = kEta * kEta * (1.0 - cosine * cosine);  // Snell: sin t = eta sin i
  const Dir refracted =
      test::plus(test::scaled(i, kEta), test::scaled(n, kEta * cosine - std::sqrt(1.0 - sinT2)));
  const double F = schlickF(kEta);
  return {scene.texture.apply(reflected), scene.texture.apply(refracted),
          F + (1 - F) * std::pow(1 - cosine, 5), cosine};
}

const OracleVarying& varying(const std::vector<OracleVarying>& all, const std::string& name) {
  for (const OracleVarying& v : all) {
    if (v.name == name) return v;
  }
  throw std::runtime_error("no varying " + name);
}

TEST(OracleOrangeBookFresnel, MatchesTheOpticsOnASphere) {
  const Scene scene;
  const auto out = makeVertexOracle("orange_book_fresnel")->evaluate(scene.input());
  ASSERT_EQ(out.size(), 4u);  // and gl_Position
  const OracleVarying& reflect = varying(out, "Reflect");
  const OracleVarying& refract = varying(out, "Refract");
  const OracleVarying& ratio = varying(out, "Ratio");
  ASSERT_EQ(reflect.components, 3);
  ASSERT_EQ(ratio.components, 1);
  ASSERT_EQ(refract.reference.size(), 3 * scene.positions.size());
  for (std::size_t v = 0; v < scene.positions.size(); ++v) {
    const Expected e = expectedAt(scene, scene.positions[v]);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(reflect.reference[3 * v + k], e.reflect[k], 1e-12) << "vertex " << v;
      EXPECT_NEAR(refract.reference[3 * v + k], e.refract[k], 1e-12) << "vertex " << v;
      EXPECT_NEAR(reflect.strict[3 * v + k], e.reflect[k], 1e-5) << "vertex " << v;
      EXPECT_NEAR(refract.strict[3 * v + k], e.refract[k], 1e-5) << "vertex " << v;
    }
    EXPECT_NEAR(ratio.reference[v], e.ratio, 1e-12) << "vertex " << v;
    EXPECT_NEAR(ratio.strict[v], e.ratio, 1e-5) << "vertex " << v;
  }
}

TEST(OracleOrangeBookFresnel, GlPositionIsTheModelViewProjectionOfTheVertex) {
  const Scene scene;
  const auto out = makeVertexOracle("orange_book_fresnel")->evaluate(scene.input());
  const OracleVarying& position = varying(out, "gl_Position");
  ASSERT_EQ(position.components, 4);
  const Rigid mvp = rigid({0, 0, 1}, 0.1, {0, 0, -1});  // as the Scene sets MVPMatrix
  for (std::size_t v = 0; v < scene.positions.size(); ++v) {
    const Dir expected = mvp.apply(scene.positions[v]);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(position.reference[4 * v + k], expected[k], 1e-12) << "vertex " << v;
    EXPECT_EQ(position.reference[4 * v + 3], 1.0) << "vertex " << v;
  }
}

TEST(OracleOrangeBookFresnel, IntervalsHoldTheDoubleAndFloatResults) {
  const Scene scene;
  for (const OracleVarying& out :
       makeVertexOracle("orange_book_fresnel")->evaluate(scene.input())) {
    for (std::size_t k = 0; k < out.reference.size(); ++k) {
      EXPECT_LE(out.lo[k], out.reference[k]) << out.name << " " << k;
      EXPECT_LE(out.reference[k], out.hi[k]) << out.name << " " << k;
      EXPECT_LE(out.lo[k], out.strict[k]) << out.name << " " << k;
      EXPECT_LE(out.strict[k], out.hi[k]) << out.name << " " << k;
      if (!out.undefined[k]) {
        // A bound, not the whole line: well under a thousandth for unit rays.
        EXPECT_LT(out.hi[k] - out.lo[k], 1e-4) << out.name << " " << k;
      }
    }
  }
}

TEST(OracleOrangeBookFresnel, SchlickRatioAtNormalIncidenceIsF) {
  const Scene scene;
  const auto out = makeVertexOracle("orange_book_fresnel")->evaluate(scene.input());
  const OracleVarying& ratio = varying(out, "Ratio");
  const double F = schlickF(kEta);
  EXPECT_NEAR(expectedAt(scene, scene.positions[scene.facingVertex]).cosine, 1.0, 1e-7);
  EXPECT_NEAR(ratio.reference[scene.facingVertex], F, 1e-12);
  // Eta is the float nearest 0.66, as `const float` makes it; F from the
  // printed 0.66 is measurably different.
  EXPECT_GT(std::fabs(schlickF(0.66) - F), 1e-9);
}

TEST(OracleOrangeBookFresnel, RatioIsUndefinedWhereThePowBaseMayBeNegative) {
  const Scene scene;
  const auto out = makeVertexOracle("orange_book_fresnel")->evaluate(scene.input());
  const OracleVarying& ratio = varying(out, "Ratio");
  // Head on, 1.0 - dot(-i, n) is 0 up to rounding: pow of a possibly
  // negative base.
  EXPECT_EQ(ratio.undefined[scene.facingVertex], 1);
  for (std::size_t v = 0; v < scene.positions.size(); ++v) {
    if (expectedAt(scene, scene.positions[v]).cosine < 0.99) {
      EXPECT_EQ(ratio.undefined[v], 0) << "vertex " << v;
    }
  }
  for (const char* name : {"Reflect", "Refract"}) {
    for (std::uint8_t flag : varying(out, name).undefined) EXPECT_EQ(flag, 0) << name;
  }
}

// The message of the UsageError evaluate() throws.
std::string usageErrorOf(const Scene& scene) {
  try {
    makeVertexOracle("orange_book_fresnel")->evaluate(scene.input());
  } catch (const UsageError& e) {
    return e.what();
  }
  return "no UsageError";
}

TEST(OracleOrangeBookFresnel, NamesAMissingOrMistypedUniform) {
  Scene missing;
  missing.uniforms.erase("NormalMatrix");
  EXPECT_NE(usageErrorOf(missing).find("NormalMatrix"), std::string::npos) << usageErrorOf(missing);
  Scene mistyped;
  mistyped.uniforms["MVMatrix"] = mat3Of(mistyped.modelView);
  const std::string message = usageErrorOf(mistyped);
  EXPECT_NE(message.find("MVMatrix"), std::string::npos) << message;
  EXPECT_NE(message.find("mat4"), std::string::npos) << message;
  Scene short_;
  short_.uniforms["TextureMatrix"].data.pop_back();
  EXPECT_NE(usageErrorOf(short_).find("TextureMatrix"), std::string::npos) << usageErrorOf(short_);
}

TEST(OracleOrangeBookFresnel, NamesAMissingConstant) {
  Scene scene;
  scene.constants.erase("FresnelPower");
  EXPECT_NE(usageErrorOf(scene).find("FresnelPower"), std::string::npos) << usageErrorOf(scene);
}

TEST(OracleOrangeBookFresnel, NamesAMissingOrMisshapedAttribute) {
  Scene missing;
  missing.attributes.erase("MCnormal");
  EXPECT_NE(usageErrorOf(missing).find("MCnormal"), std::string::npos) << usageErrorOf(missing);
  Scene misshaped;
  misshaped.attributes["MCvertex"].components = 3;
  EXPECT_NE(usageErrorOf(misshaped).find("MCvertex"), std::string::npos) << usageErrorOf(misshaped);
  Scene tooFew;
  tooFew.attributes["MCnormal"].data.resize(3 * 5);
  EXPECT_NE(usageErrorOf(tooFew).find("MCnormal"), std::string::npos) << usageErrorOf(tooFew);
}

}  // namespace
}  // namespace snell
