#include "runner/physics_eval_line.h"

#include <fmt/format.h>

#include <string>

#include "core/errors.h"
#include "oracle/physics/fresnel.h"
#include "oracle/physics/interface_angles.h"
#include "oracle/physics/sellmeier.h"

namespace snell {
namespace {

using nlohmann::json;

double number(const json& object, const std::string& fn, const char* key) {
  if (!object.contains(key) || !object.at(key).is_number())
    throw UsageError(fmt::format("{} needs a number \"{}\"", fn, key));
  return object.at(key).get<double>();
}

std::string text(const json& object, const std::string& fn, const char* key, const char* choices) {
  if (!object.contains(key) || !object.at(key).is_string())
    throw UsageError(fmt::format("{} needs \"{}\": {}", fn, key, choices));
  return object.at(key).get<std::string>();
}

json fresnel(const json& object) {
  constexpr const char* kModels = "\"exact\", \"schlick\" or \"schlick_dense_side\"";
  const std::string model = text(object, "fresnel", "model", kModels);
  const double cosI = number(object, "fresnel", "cos_i");
  const double n1 = number(object, "fresnel", "n1");
  const double n2 = number(object, "fresnel", "n2");
  double value = 0.0;
  if (model == "exact")
    value = physics::fresnelExact(cosI, n1, n2).unpolarised;
  else if (model == "schlick")
    value = physics::fresnelSchlick(cosI, n1, n2);
  else if (model == "schlick_dense_side")
    value = physics::fresnelSchlickDenseSide(cosI, n1, n2);
  else
    throw UsageError(fmt::format("unknown fresnel model \"{}\": use {}", model, kModels));
  return {{"model", model}, {"value", value}};
}

json ior(const json& object) {
  const std::string glass = text(object, "ior", "glass", "\"N-BK7\" or \"water\"");
  const double lambdaNm = number(object, "ior", "lambda_nm");
  return {{"glass", glass},
          {"value", physics::refractiveIndex(physics::findGlass(glass), lambdaNm)}};
}

json angle(const json& object, const std::string& fn, double (*degrees)(double, double)) {
  return {{"value", degrees(number(object, fn, "n1"), number(object, fn, "n2"))},
          {"unit", "degrees"}};
}

}  // namespace

bool isPhysicsCall(const json& object) {
  if (!object.is_object() || !object.contains("fn") || !object.at("fn").is_string()) return false;
  const std::string fn = object.at("fn").get<std::string>();
  return fn == "fresnel" || fn == "ior" || fn == "critical_angle" || fn == "brewster_angle";
}

json evaluatePhysicsCall(const json& object) {
  const std::string fn = object.at("fn").get<std::string>();
  json answer = fn == "fresnel"          ? fresnel(object)
                : fn == "ior"            ? ior(object)
                : fn == "critical_angle" ? angle(object, fn, physics::criticalAngleDegrees)
                                         : angle(object, fn, physics::brewsterAngleDegrees);
  answer["fn"] = fn;
  answer["reference"] = "physics";
  return answer;
}

}  // namespace snell
