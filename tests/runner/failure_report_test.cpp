#include "runner/failure_report.h"

#include <gtest/gtest.h>

namespace snell {
namespace {

VaryingCheck varying(const char* name, std::size_t checked, std::size_t undefined) {
  VaryingCheck v;
  v.name = name;
  v.checked = checked;
  v.undefined = undefined;
  return v;
}

Manifest manifestWithLimit(double maxUndefined) {
  Manifest m;
  m.path = "shaders/x/manifest.toml";
  m.maxUndefinedFraction = maxUndefined;
  return m;
}

TEST(NothingChecked, ACaptureTheSpecLeavesUndefinedEverywhereFails) {
  CaseResult result;
  result.varyings = {varying("Refract", 0, 300)};
  const std::string reasons = nothingCheckedReasons(manifestWithLimit(0.01), result);
  EXPECT_NE(reasons.find("Refract: nothing checked: the spec leaves all 300 components undefined"),
            std::string::npos)
      << reasons;
}

TEST(NothingChecked, AnUndefinedFractionAboveTheManifestsLimitFails) {
  CaseResult result;
  result.varyings = {varying("Ratio", 98, 2)};
  EXPECT_NE(nothingCheckedReasons(manifestWithLimit(0.01), result).find("2 of 100 components (2.00%)"),
            std::string::npos);
  EXPECT_EQ(nothingCheckedReasons(manifestWithLimit(0.02), result), "");  // at the limit: fine
}

TEST(NothingChecked, AnImageComparisonThatComparedNoPixelFails) {
  CaseResult result;
  ImageComparison image;
  image.against = "reference";
  image.compared = 0;
  result.images = {image};
  EXPECT_NE(nothingCheckedReasons(manifestWithLimit(0.01), result).find("nothing compared"),
            std::string::npos);
  result.images[0].compared = 10;
  EXPECT_EQ(nothingCheckedReasons(manifestWithLimit(0.01), result), "");
}

TEST(FailureReport, TheLineAssigningAnOutputIsTheLastAssignment) {
  const std::string source =
      "out vec3 R;\n"
      "void main() {\n"
      "  R = vec3(0.0);   // line 3\n"
      "  if (R == vec3(1.0)) {}\n"
      "  R.xy *= 2.0;     // line 5\n"
      "  float RR = 1.0;\n"
      "}\n";
  EXPECT_EQ(lineAssigning(source, "R"), 5);
  EXPECT_EQ(lineAssigning(source, "Q"), 0);
}

TEST(FailureReport, AConstantTheManifestGivesDifferentlyIsNamedWithItsLine) {
  Manifest m;
  m.path = "shaders/x/manifest.toml";
  m.constants = {{"Eta", 0.66}, {"FresnelPower", 5.0}};
  ProgramSource program;
  program.vertexPath = "x.vert";
  program.vertex = "// const float Eta = 9.0; in a comment is no declaration\n"
                   "const float Eta = 0.7;\n"
                   "const float FresnelPower = 5.0;\n";
  const std::string text = constantsDisagreement(m, program);
  EXPECT_NE(text.find("x.vert:2: the listing says `const float Eta = 0.7;` but manifest.toml "
                      "gives Eta = 0.66"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("FresnelPower"), std::string::npos) << text;
  m.constants["Eta"] = 0.7;
  EXPECT_EQ(constantsDisagreement(m, program), "");
}

TEST(FailureReport, WorstSamplesComeWithTheirInputs) {
  Manifest m;
  m.path = "shaders/x/manifest.toml";
  ProgramSource program;
  program.vertexPath = "x.vert";
  program.vertex = "in vec3 N;\nout vec3 R;\nvoid main() {\n  R = N;\n}\n";
  ResolvedBindings bindings;
  bindings.attributes["N"] = AttributeStream{"N", 3, {0, 0, 1, 0.25f, 0.5f, 0.75f}};
  bindings.uniforms["eta"] = Value{ValueType::Float, {0.66f}};
  bindings.uniforms["M"] = Value{ValueType::Mat3, std::vector<float>(9, 1.0f)};
  VaryingCheck v = varying("R", 6, 0);
  v.failed = 1;
  v.worstFailures = {{1, 2, 9.0f, 0.75, 0.74, 0.76, 826.0, 1}};
  const std::string text = describeVertexFailures(m, program, bindings, {v});
  EXPECT_NE(text.find("R: 1 of 6 components outside the spec interval (assigned at x.vert:4)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("vertex 1 [2]: got 9, exact 0.75, allowed [0.74, 0.76], slack 826"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("inputs: N = (0.25, 0.5, 0.75), eta = 0.66"), std::string::npos) << text;
  EXPECT_EQ(text.find("M = "), std::string::npos) << text;  // matrices are the scene's
}

}  // namespace
}  // namespace snell
