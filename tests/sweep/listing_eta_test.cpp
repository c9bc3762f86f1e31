// Setting a listing's eta: the program's `const float` line and the
// manifest constant the oracle reads change together, ratios between
// dispersion etas are kept, and a constant the program does not write as
// `const float NAME = number;` is refused with the reason.
#include "sweep/listing_eta.h"

#include <gtest/gtest.h>

namespace snell::sweep {
namespace {

Manifest chromatic() {
  Manifest m;
  m.path = "chromatic/manifest.toml";
  m.constants = {{"EtaR", 0.65}, {"EtaG", 0.67}, {"EtaB", 0.69}, {"FresnelPower", 5.0}};
  return m;
}

ProgramSource chromaticProgram() {
  ProgramSource p;
  p.vertex =
      "const float EtaR = 0.65;\nconst float EtaG = 0.67; // main\nconst float EtaB=0.69;\n"
      "const float FresnelPower = 5.0;\n";
  return p;
}

TEST(ListingEta, FindsTheEtaConstantsAndPrefersTheMiddleOne) {
  const EtaBinding b = etaBinding(chromatic());
  EXPECT_EQ(b.constants.size(), 3u);
  EXPECT_EQ(b.main, "EtaG");
  EXPECT_DOUBLE_EQ(b.published, 0.67);
}

TEST(ListingEta, RewritesProgramAndConstantsTogetherKeepingRatios) {
  const Manifest m = chromatic();
  std::string why;
  const auto variant = withEta(m, chromaticProgram(), etaBinding(m), 1.34, why);
  ASSERT_TRUE(variant) << why;
  EXPECT_FLOAT_EQ(static_cast<float>(variant->manifest.constants.at("EtaG")), 1.34f);
  EXPECT_FLOAT_EQ(static_cast<float>(variant->manifest.constants.at("EtaR")), 1.30f);
  EXPECT_DOUBLE_EQ(variant->manifest.constants.at("FresnelPower"), 5.0);
  EXPECT_NE(variant->program.vertex.find("const float EtaG = 1.34"), std::string::npos)
      << variant->program.vertex;
  EXPECT_NE(variant->program.vertex.find("const float EtaB=1.38"), std::string::npos)
      << variant->program.vertex;
  // The comment after the constant is kept.
  EXPECT_NE(variant->program.vertex.find("; // main"), std::string::npos);
}

TEST(ListingEta, RefusesAConstantTheProgramDoesNotWrite) {
  const Manifest m = chromatic();
  ProgramSource p = chromaticProgram();
  p.vertex = "uniform float EtaR;\nconst float EtaG = 0.67;\nconst float EtaB = 0.69;\n";
  std::string why;
  EXPECT_FALSE(withEta(m, p, etaBinding(m), 1.0, why));
  EXPECT_NE(why.find("EtaR"), std::string::npos) << why;
}

TEST(ListingEta, ScalesALiteralEtaUniform) {
  Manifest m;
  m.uniforms.push_back({"etaRatio", Value{ValueType::Float, {1.5f}}, 3});
  const EtaBinding b = etaBinding(m);
  ASSERT_EQ(b.uniforms, std::vector<std::string>{"etaRatio"});
  std::string why;
  const auto variant = withEta(m, {}, b, 0.9, why);
  ASSERT_TRUE(variant) << why;
  EXPECT_FLOAT_EQ(std::get<Value>(variant->manifest.uniforms.at(0).source).data.at(0), 0.9f);
}

TEST(ListingEta, FloatLiteralsRoundTripAndHaveAPoint) {
  EXPECT_EQ(glslFloat(2.0), "2.0");
  EXPECT_EQ(std::stof(glslFloat(1 / 1.1)), static_cast<float>(1 / 1.1));
}

}  // namespace
}  // namespace snell::sweep
