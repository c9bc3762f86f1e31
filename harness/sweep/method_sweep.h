#pragma once
// The Fresnel weighting methods the listings use, swept over incidence angle
// and eta in double on the CPU, against the exact Fresnel equations of the
// physics reference: where a method's error passes a stated bound the break
// is the method's, and a weight outside [0, 1] or one that falls toward
// grazing incidence is flagged whatever the error.
#include <string>
#include <vector>

#include "sweep/sweep_classify.h"
#include "sweep/sweep_points.h"

namespace snell::sweep {

// Largest |method - exact| reflectance a method may show before the sweep
// calls it a method break: 0.02 is about 5 steps of an 8-bit channel, a
// difference a viewer sees in a mixed reflection/refraction colour; Schlick
// (1994) quotes his approximation within 1% (0.01) for the air side.
constexpr double kMethodErrorBound = 0.02;

struct MethodSample {
  std::string method;  // constant, schlick, schlick_dense_side, exact
  double eta = 0;      // n1 / n2
  double n1 = 1, n2 = 1;
  double angleDegrees = 0;
  double value = 0;  // the method's reflectance weight
  double exact = 0;  // exact Fresnel, unpolarised
  double error() const { return value - exact; }
};

const std::vector<std::string>& methodNames();

// Which side the light comes from: "n1>n2" (the dense side, where total
// internal reflection happens), "n1<n2" or "n1=n2".
const char* sideName(double eta);

// Light from n1 into n2 with n1 / n2 = eta: glass to air (n2 = 1) for eta > 1,
// air to glass (n1 = 1) otherwise.
MethodSample methodSample(const std::string& method, double eta, double angleDegrees);

// Every method at every eta and angle of the grid (refract's angles).
std::vector<MethodSample> methodSweep(const SweepGrid& grid);

// Breaks of one method's samples (one eta, sorted by angle): error past the
// bound (class method), weight outside [0, 1] or not finite, reflectance
// that falls toward grazing (both physical-range violations, class method).
std::vector<Break> methodBreaks(const std::vector<MethodSample>& series, std::size_t firstIndex);

// methodBreaks over every (method, eta) series of a sweep; Break::point
// indexes `samples`.
std::vector<Break> classifyMethods(const std::vector<MethodSample>& samples);

}  // namespace snell::sweep
