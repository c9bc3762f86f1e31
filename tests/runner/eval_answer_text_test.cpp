// Eval answers written as text are byte for byte what building the answer
// as an nlohmann::json document and dumping it gives (as eval wrote them
// before), for the oracle alone and with a driver's vector: alternatives,
// undefined components, non-finite values, vectors inside and outside.
#include "runner/eval_answer_text.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "compare/slack.h"

namespace snell {
namespace {

using nlohmann::json;

json finite(const std::vector<double>& values) {
  json out = json::array();
  for (double x : values)
    out.push_back(std::isfinite(x) ? json(x) : json(x > 0 ? "inf" : x < 0 ? "-inf" : "nan"));
  return out;
}

json wayJson(const BuiltinWay& way) {
  json out = {{"value", finite(way.value)}, {"lo", finite(way.lo)}, {"hi", finite(way.hi)}};
  if (std::find(way.undefined.begin(), way.undefined.end(), true) != way.undefined.end())
    out["undefined"] = way.undefined;
  return out;
}

// The answer as a JSON document, as eval built it before it wrote text.
std::string documentAnswer(std::size_t number, const BuiltinCall& call, const BuiltinResult& oracle,
                           const std::vector<float>* driver, PrecisionRules rules) {
  json out = {{"line", number}, {"fn", call.fn}, {"rules", precisionRulesName(rules)}};
  if (!driver) {
    out["value"] = finite(oracle.value);
  } else {
    const bool within = oracle.allows(*driver);
    const BuiltinWay& way = oracle.nearestWay(*driver);
    double worst = 0;
    for (std::size_t c = 0; c < driver->size(); ++c)
      if (!way.undefined[c])
        worst = std::max(worst, slack((*driver)[c], way.value[c], way.lo[c], way.hi[c]));
    out["value"] = finite(std::vector<double>(driver->begin(), driver->end()));
    out["exact"] = finite(oracle.value);
    out["within_spec"] = within;
    out["slack"] = std::isfinite(worst) ? json(worst) : json("inf");
  }
  out["lo"] = finite(oracle.lo);
  out["hi"] = finite(oracle.hi);
  if (std::find(oracle.undefined.begin(), oracle.undefined.end(), true) != oracle.undefined.end())
    out["undefined"] = oracle.undefined;
  if (oracle.ways.size() > 1) {
    json ways = json::array();
    for (const BuiltinWay& w : oracle.ways) ways.push_back(wayJson(w));
    out["alternatives"] = ways;
  }
  return out.dump() + "\n";
}

std::vector<BuiltinCall> calls() {
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<BuiltinCall> out;
  for (int k = 0; k < 400; ++k) {
    const float a = 0.0039f * static_cast<float>(k);
    const float x = std::sin(a), y = -std::cos(a);
    const float critical = 1.0f / std::sqrt(1.0f - y * y);
    const float eta = k % 3 == 0 ? critical : 0.6f + 0.0025f * static_cast<float>(k);
    out.push_back({"refract", {x, y, 0.0f}, {0.0f, 1.0f, 0.0f}, eta});
    out.push_back({"reflect", {x, y}, {0.0f, 1.0f}, 1.0f});
    out.push_back({"refract", {y}, {1.0f}, eta});
    out.push_back({"refract", {x, y, -0.0f, 1e-30f}, {0.0f, 1.0f, 0.0f, 0.0f}, eta});
  }
  out.push_back({"refract", {nan, -1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 0.66f});
  out.push_back({"reflect", {inf, -1.0f, -inf}, {0.0f, 1.0f, 0.0f}, 1.0f});
  out.push_back({"refract", {1e30f, -1e30f, 0.0f}, {0.0f, 1.0f, 0.0f}, 1e-30f});
  out.push_back({"reflect", {0.0f, 0.0f}, {0.0f, 0.0f}, 1.0f});
  return out;
}

std::string textAnswer(std::size_t number, const BuiltinCall& call, const BuiltinResult& oracle,
                       const std::vector<float>* driver, PrecisionRules rules) {
  fmt::memory_buffer out;
  appendEvalAnswer(out, {number, &call, &oracle, driver, rules});
  return fmt::to_string(out);
}

TEST(EvalAnswerText, IsWhatTheJsonDocumentDumps) {
  std::size_t alternatives = 0, undefined = 0, outside = 0, inside = 0;
  std::size_t number = 1;
  for (PrecisionRules rules : {PrecisionRules::Glsl, PrecisionRules::Vulkan})
    for (const BuiltinCall& call : calls()) {
      const BuiltinResult oracle = evaluateBuiltin(call, rules);
      alternatives += oracle.ways.size() > 1;
      undefined += std::count(oracle.undefined.begin(), oracle.undefined.end(), true) > 0;
      ASSERT_EQ(textAnswer(number, call, oracle, nullptr, rules),
                documentAnswer(number, call, oracle, nullptr, rules));
      // Driver vectors: the fp32 formula, one nudged far out, zero, NaN.
      std::vector<std::vector<float>> drivers = {oracle.strict, oracle.strict,
                                                 std::vector<float>(call.I.size(), 0.0f),
                                                 std::vector<float>(call.I.size(), NAN)};
      drivers[1][0] = std::nextafter(drivers[1][0], 1e30f) * 1.001f + 1e-3f;
      for (const std::vector<float>& driver : drivers) {
        fmt::memory_buffer out;
        const bool isOutside = appendEvalAnswer(out, {number, &call, &oracle, &driver, rules});
        ASSERT_EQ(fmt::to_string(out), documentAnswer(number, call, oracle, &driver, rules));
        EXPECT_EQ(isOutside, !oracle.allows(driver));
        (isOutside ? outside : inside) += 1;
      }
      number = number * 3 + 1;  // line numbers of every length
      if (number > 1'000'000'000'000) number = 7;
    }
  // The cases this test is about did occur.
  EXPECT_GT(alternatives, 10u);
  EXPECT_GT(undefined, 0u);
  EXPECT_GT(outside, 10u);
  EXPECT_GT(inside, 10u);
}

}  // namespace
}  // namespace snell
