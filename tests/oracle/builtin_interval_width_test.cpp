// The intervals are not vacuous. For ordinary inputs (unit vectors, away from
// the critical angle) each reflect/refract component must be no wider than a
// first-order forward error budget built from the precision rules, sample by
// sample, and no wider than that budget's worst case over the input class.
// The measured median and maximum widths are printed and recorded.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "test_geometry.h"

namespace snell {
namespace {

using test::Dir;

// Widths are in fp32 ULPs of the result's length, taken as 2^-23 * length:
// the results are unit vectors, and a length of 1 - 6e-8 (the binade below 1)
// must not halve the unit against one of 1 + 1e-7.
double unitInLast(const glsl::vec3<double>& exact) {
  return 0x1p-23 * test::lengthOf(test::fromVec(exact));
}

// Each correctly rounded step may land on either float around its exact
// value: an error under the gap between the floats around the (possibly
// already perturbed) value.
double rounding(double value, double error) { return gapAbove(std::fabs(value) + error); }

// dot(x, y) in any order, fused or not: gamma_3 * sum |x_i y_i| (Higham),
// with unit roundoff 2^-23 for either-neighbour rounding.
double dotError(const Dir& x, const Dir& y) {
  const double u = 0x1p-23;
  const double gamma3 = 3 * u / (1 - 3 * u);
  return gamma3 * (std::fabs(x[0] * y[0]) + std::fabs(x[1] * y[1]) + std::fabs(x[2] * y[2]));
}

// reflect: I - 2.0 * dot(N, I) * N, first order, per component.
std::array<double, 3> reflectErrorBudget(const Dir& I, const Dir& N) {
  const double d = test::dotOf(N, I);
  const double eD = dotError(N, I);
  const double s = 2.0 * d;
  const double eS = 2.0 * eD + rounding(s, 2.0 * eD);
  std::array<double, 3> budget{};
  for (int j = 0; j < 3; ++j) {
    const double p = s * N[j];
    const double eP = eS * std::fabs(N[j]) + rounding(p, eS * std::fabs(N[j]));
    budget[j] = eP + rounding(I[j] - p, eP);
  }
  return budget;
}

// refract: k = 1 - eta*eta*(1 - d*d); eta*I - (eta*d + sqrt(k))*N with
// sqrt(k) = 1.0 / inversesqrt(k) (2 ULP, then 2.5 ULP). The product
// eta*eta*(1 - d*d) may be grouped either way (Mesa computes
// eta*(eta*(1 - d*d))): its first rounding is at most 2^-23 of the whole.
std::array<double, 3> refractErrorBudget(const Dir& I, const Dir& N, double eta) {
  const double d = test::dotOf(N, I);
  const double eD = dotError(N, I);
  const double dd = d * d;
  const double eDd = 2.0 * std::fabs(d) * eD + rounding(dd, 2.0 * std::fabs(d) * eD);
  const double s2 = 1.0 - dd;
  const double eS2 = eDd + rounding(s2, eDd);
  const double e2 = eta * eta;
  const double m = e2 * s2;
  const double eFirst = 0x1p-23 * std::fabs(m);
  const double eM = e2 * eS2 + eFirst + rounding(m, e2 * eS2 + eFirst);
  const double k = 1.0 - m;
  const double eK = eM + rounding(k, eM);
  const double r = 1.0 / std::sqrt(k);
  const double eR = 0.5 * r * r * r * eK + 2.0 * rounding(r, 0.5 * r * r * r * eK);
  const double q = std::sqrt(k);
  const double eQ = eR * q * q + 2.5 * rounding(q, eR * q * q);
  const double a = eta * d;
  const double eA = eta * eD + rounding(a, eta * eD);
  const double b = a + q;
  const double eB = eA + eQ + rounding(b, eA + eQ);
  std::array<double, 3> budget{};
  for (int j = 0; j < 3; ++j) {
    const double p = b * N[j];
    const double eP = eB * std::fabs(N[j]) + rounding(p, eB * std::fabs(N[j]));
    const double c = eta * I[j];
    const double eC = rounding(c, 0.0);
    budget[j] = eC + eP + rounding(c - p, eC + eP);
  }
  return budget;
}

struct Sample {
  std::array<float, 3> I, N;
  float eta;
};

// Unit vectors on random planes, incidence from 0 to 89.9 degrees, into a
// denser (eta < 1) and a rarer (eta > 1) medium. "Away from the critical
// angle" is k = 1 - eta^2 sin^2(theta) >= 0.4, which every eta < 0.75 meets
// at every angle.
constexpr double kMinK = 0.4;
std::vector<Sample> ordinarySamples() {
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> angle(0.0, 89.9 * M_PI / 180.0);
  const float etas[] = {0.66f, 0.75f, 1.0f / 1.33f, 1.33f, 1.5f};
  std::vector<Sample> samples;
  while (samples.size() < 20000) {
    const float eta = etas[samples.size() % 5];
    const Dir normal = test::randomUnit(rng);
    const double theta = angle(rng);
    const double sinTheta = std::sin(theta);
    if (1.0 - double(eta) * eta * sinTheta * sinTheta < kMinK) continue;
    const Dir incident = test::incidentAt(normal, test::randomTangent(normal, rng), theta);
    samples.push_back({test::toFloats(incident), test::toFloats(normal), eta});
  }
  return samples;
}

Dir exactly(const std::array<float, 3>& v) { return {v[0], v[1], v[2]}; }

struct Widths {
  std::vector<double> ulps;
  double median() {
    std::sort(ulps.begin(), ulps.end());
    return ulps[ulps.size() / 2];
  }
  double max() const { return *std::max_element(ulps.begin(), ulps.end()); }
};

void report(const char* name, Widths& widths) {
  const double median = widths.median();
  const double max = widths.max();
  ::testing::Test::RecordProperty(std::string(name) + "_median_ulps", std::to_string(median));
  ::testing::Test::RecordProperty(std::string(name) + "_max_ulps", std::to_string(max));
  std::printf("%s interval width over %zu components: median %.1f ULP, max %.1f ULP\n", name,
              widths.ulps.size(), median, max);
}

// Second-order terms and the oracle's own double-rounding guards.
double withSlack(double budget) { return budget * (1.0 + 0x1p-20) + 0x1p-100; }

TEST(OracleBuiltinIntervalWidth, ReflectStaysWithinTheErrorBudget) {
  Widths widths;
  for (const Sample& s : ordinarySamples()) {
    const auto allowed = glsl::reflect(test::asVec<Interval>(s.I), test::asVec<Interval>(s.N));
    const auto exact = glsl::reflect(test::asVec<double>(s.I), test::asVec<double>(s.N));
    const auto budget = reflectErrorBudget(exactly(s.I), exactly(s.N));
    for (int j = 0; j < 3; ++j) {
      ASSERT_LE(width(allowed[j]), withSlack(2.0 * budget[j])) << "component " << j;
      widths.ulps.push_back(width(allowed[j]) / unitInLast(exact));
    }
  }
  report("reflect", widths);
  // The budget's worst case for unit vectors, in 2^-23: |dot| <= 1 with
  // sum |N_i I_i| <= 1 gives 3; 2*dot adds 2 (ULP of a value up to 2): 8;
  // times N_j (|N_j| <= 1) adds 2: 10; I_j - p adds 2 (a length just over
  // 1): 12 each side, 24 in all.
  EXPECT_LE(widths.max(), 24.0);
}

TEST(OracleBuiltinIntervalWidth, RefractStaysWithinTheErrorBudgetAwayFromTheCriticalAngle) {
  Widths widths;
  for (const Sample& s : ordinarySamples()) {
    const auto allowed = glsl::refract(test::asVec<Interval>(s.I), test::asVec<Interval>(s.N),
                                       Interval::point(s.eta));
    const auto exact =
        glsl::refract(test::asVec<double>(s.I), test::asVec<double>(s.N), double(s.eta));
    const auto budget = refractErrorBudget(exactly(s.I), exactly(s.N), s.eta);
    for (int j = 0; j < 3; ++j) {
      ASSERT_LE(width(allowed[j]), withSlack(2.0 * budget[j]))
          << "component " << j << " eta " << s.eta;
      widths.ulps.push_back(width(allowed[j]) / unitInLast(exact));
    }
  }
  report("refract", widths);
  // The budget's worst case for eta <= 1.5 and k >= 0.4, in 2^-23: dot 3;
  // d*d 7; 1-d*d 8; eta*eta 2; their product 2.25*8+2+1 = 21; k 22;
  // sqrt(k) 22/(2*sqrt(0.4)) + 2 ULP of inversesqrt (1.6) + 2.5 = 21.5;
  // eta*d 6.5; the sum 30; times N_j 32; eta*I_j 2; the difference 35.5
  // each side: 71 in all.
  EXPECT_LE(widths.max(), 71.0);
}

}  // namespace
}  // namespace snell
