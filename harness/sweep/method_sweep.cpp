#include "sweep/method_sweep.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "oracle/physics/fresnel.h"

namespace snell::sweep {

const std::vector<std::string>& methodNames() {
  static const std::vector<std::string> names = {"constant", "schlick", "schlick_dense_side",
                                                 "exact"};
  return names;
}

const char* sideName(double eta) { return eta > 1 ? "n1>n2" : eta < 1 ? "n1<n2" : "n1=n2"; }

MethodSample methodSample(const std::string& method, double eta, double angleDegrees) {
  MethodSample s;
  s.method = method;
  s.eta = eta;
  s.n1 = eta > 1 ? eta : 1.0;
  s.n2 = eta > 1 ? 1.0 : 1.0 / eta;
  s.angleDegrees = angleDegrees;
  const double cosine = std::max(0.0, std::cos(angleDegrees * std::numbers::pi / 180.0));
  s.exact = physics::fresnelExact(cosine, s.n1, s.n2).unpolarised;
  if (method == "constant")
    s.value = physics::normalIncidenceReflectance(s.n1, s.n2);  // one weight at every angle
  else if (method == "schlick")
    s.value = physics::fresnelSchlick(cosine, s.n1, s.n2);
  else if (method == "schlick_dense_side")
    s.value = physics::fresnelSchlickDenseSide(cosine, s.n1, s.n2);
  else
    s.value = s.exact;
  return s;
}

std::vector<MethodSample> methodSweep(const SweepGrid& grid) {
  std::vector<MethodSample> samples;
  for (const std::string& method : methodNames())
    for (double eta : grid.etas)
      for (double angle : anglesFor(grid, eta)) samples.push_back(methodSample(method, eta, angle));
  return samples;
}

std::vector<Break> methodBreaks(const std::vector<MethodSample>& series, std::size_t firstIndex) {
  std::vector<Break> breaks;
  auto add = [&](std::size_t k, const char* kind, std::string detail) {
    breaks.push_back({series[k].method,
                      "physics",
                      firstIndex + k,
                      kind,
                      BreakClass::Method,
                      std::move(detail),
                      {series[k].value, series[k].exact}});
  };
  for (std::size_t k = 0; k < series.size(); ++k) {
    const MethodSample& s = series[k];
    if (!(s.value >= 0.0 && s.value <= 1.0))
      add(k, "weight_outside_0_1", fmt::format("weight {:.6g}", s.value));
    if (std::abs(s.error()) > kMethodErrorBound)
      add(k, "error_past_bound",
          fmt::format("{:.4f} against exact {:.4f} (error {:+.4f}, bound {})", s.value, s.exact,
                      s.error(), kMethodErrorBound));
    // Reflectance must not fall as the angle grows toward grazing; 1e-12
    // leaves room for the last bits of a flat stretch (R = 1 under TIR).
    if (k > 0 && s.value < series[k - 1].value - 1e-12)
      add(k, "falls_toward_grazing",
          fmt::format("{:.6g} at {:.6g} deg after {:.6g} at {:.6g} deg", s.value, s.angleDegrees,
                      series[k - 1].value, series[k - 1].angleDegrees));
  }
  return breaks;
}

std::vector<Break> classifyMethods(const std::vector<MethodSample>& samples) {
  std::vector<Break> breaks;
  std::size_t start = 0;
  while (start < samples.size()) {
    std::size_t end = start;
    while (end < samples.size() && samples[end].method == samples[start].method &&
           samples[end].eta == samples[start].eta)
      ++end;
    const std::vector<MethodSample> series(samples.begin() + start, samples.begin() + end);
    for (Break& b : methodBreaks(series, start)) breaks.push_back(std::move(b));
    start = end;
  }
  return breaks;
}

}  // namespace snell::sweep
