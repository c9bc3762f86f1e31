// `snell eval` physics lines, as a user runs them: each answer is the
// physics reference's own double (checked bit for bit here; the reference
// against 256-bit MPFR is tests/oracle/physics/physics_mpfr_test.cpp), bad
// input gets its line number and exit code 2, and a driver refuses them.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "json_lines.h"
#include "oracle/physics/fresnel.h"
#include "oracle/physics/interface_angles.h"
#include "oracle/physics/sellmeier.h"
#include "snell_process.h"

namespace snell::testing {
namespace {

namespace fs = std::filesystem;

Outcome evalLines(const std::string& backend, const std::string& input) {
  const fs::path in = fs::temp_directory_path() / fmt::format("snell-eval-physics-{}", ::getpid());
  std::ofstream(in) << input;
  Outcome o = runSnell(fmt::format("eval --backend {} < {}", backend, in.string()));
  fs::remove(in);
  return o;
}

TEST(EvalPhysics, AnswersAreThePhysicsReference) {
  const Outcome o = evalLines("oracle",
                              R"({"fn":"fresnel","model":"exact","cos_i":1,"n1":1,"n2":1.5}
{"fn":"fresnel","model":"exact","cos_i":0.3,"n1":1.5,"n2":1}
{"fn":"fresnel","model":"schlick","cos_i":0.6,"n1":1,"n2":1.333}
{"fn":"fresnel","model":"schlick_dense_side","cos_i":0.9,"n1":1.5,"n2":1}
{"fn":"ior","glass":"N-BK7","lambda_nm":587.5618}
{"fn":"ior","glass":"water","lambda_nm":589.3}
{"fn":"critical_angle","n1":1.5,"n2":1}
{"fn":"brewster_angle","n1":1,"n2":1.5}
)");
  ASSERT_EQ(o.code, 0) << o.out;
  const auto lines = jsonLines(o.out);
  ASSERT_EQ(lines.size(), 8u) << o.out;
  const auto value = [&](std::size_t k) { return lines[k]["value"].get<double>(); };
  EXPECT_EQ(value(0), physics::fresnelExact(1.0, 1.0, 1.5).unpolarised);
  EXPECT_NEAR(value(0), 0.04, 1e-16);  // ((1.5 - 1) / (1.5 + 1))^2
  EXPECT_EQ(value(1), 1.0) << "past the critical angle";
  EXPECT_EQ(value(2), physics::fresnelSchlick(0.6, 1.0, 1.333));
  EXPECT_EQ(value(3), physics::fresnelSchlickDenseSide(0.9, 1.5, 1.0));
  EXPECT_EQ(value(4), physics::refractiveIndex(physics::nBk7(), 587.5618));
  EXPECT_NEAR(value(4), 1.5168, 1e-5);
  EXPECT_EQ(value(5), physics::refractiveIndex(physics::water20C(), 589.3));
  EXPECT_NEAR(value(6), 41.8103, 5e-5);
  EXPECT_EQ(value(7), physics::brewsterAngleDegrees(1.0, 1.5));
  for (std::size_t k = 0; k < lines.size(); ++k) EXPECT_EQ(lines[k]["line"], k + 1);
}

TEST(EvalPhysics, BadLinesNameTheirNumberAndTheRestAreAnswered) {
  const Outcome o = evalLines("oracle",
                              R"({"fn":"fresnel","model":"exact","cos_i":0.5,"n1":1,"n2":1.5}
{"fn":"fresnel","model":"exact","n1":1,"n2":1.5}
{"fn":"fresnel","model":"fast","cos_i":0.5,"n1":1,"n2":1.5}
{"fn":"fresnel","model":"exact","cos_i":1.5,"n1":1,"n2":1.5}
{"fn":"ior","glass":"BK7","lambda_nm":500}
{"fn":"ior","glass":"water","lambda_nm":100}
{"fn":"critical_angle","n1":1,"n2":1.5}
{"fn":"brewster_angle","n1":"one","n2":1.5}
{"fn":"ior","glass":"N-BK7","lambda_nm":500}
)");
  EXPECT_EQ(o.code, 2) << o.out;
  const auto lines = jsonLines(o.out);
  ASSERT_EQ(lines.size(), 9u) << o.out;
  EXPECT_TRUE(lines[0].contains("value"));
  EXPECT_TRUE(lines[8].contains("value"));
  const std::vector<std::string> expected = {"needs a number \"cos_i\"", "unknown fresnel model",
                                             "cos_i must lie in [0, 1]", "unknown glass \"BK7\"",
                                             "182 to 1129 nm",           "n1 > n2",
                                             "needs a number \"n1\""};
  for (std::size_t k = 0; k < expected.size(); ++k) {
    const std::string error = lines[k + 1].value("error", "");
    EXPECT_NE(error.find(fmt::format("line {}:", k + 2)), std::string::npos) << error;
    EXPECT_NE(error.find(expected[k]), std::string::npos) << error;
  }
}

TEST(EvalPhysics, ADriverRefersPhysicsLinesToTheReference) {
  const Outcome o = evalLines("gl", R"({"fn":"critical_angle","n1":1.5,"n2":1})"
                                    "\n");
  EXPECT_EQ(o.code, 2) << o.out;
  const auto lines = jsonLines(o.out);
  ASSERT_EQ(lines.size(), 1u) << o.out;
  EXPECT_NE(lines[0]["error"].get<std::string>().find("physics reference"), std::string::npos)
      << o.out;
  EXPECT_FALSE(lines[0].contains("value"));
}

}  // namespace
}  // namespace snell::testing
