#include "sweep/sweep_points.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace snell::sweep {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// Every eta that appears in the catalog's sources (issue 15's list).
const std::vector<double> kSourceEtas = {0.6,     0.65,      0.66,      0.67, 0.69,
                                         1 / 1.1, 1 / 1.097, 1 / 1.103, 1.02, 0.98,
                                         1.03,    1.06,      1.09,      0.3,  0.9};

void sortUnique(std::vector<double>& values) {
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end(),
                           [](double a, double b) { return std::abs(a - b) < 1e-12; }),
               values.end());
}

// The incident direction at `degrees` from the normal (0, 1, 0), in the xy plane.
std::vector<float> incident(double degrees) {
  const double theta = degrees * kDegree;
  return {static_cast<float>(std::sin(theta)), static_cast<float>(-std::cos(theta)), 0.0f};
}

SweepPoint gridPoint(const std::string& fn, double degrees, double eta) {
  SweepPoint point;
  point.call.fn = fn;
  point.call.I = incident(degrees);
  point.call.N = {0.0f, 1.0f, 0.0f};
  point.call.eta = static_cast<float>(eta);
  point.angleDegrees = degrees;
  point.eta = eta;
  return point;
}

std::vector<float> scaled(std::vector<float> v, float factor) {
  for (float& x : v) x *= factor;
  return v;
}

// The inputs the listings assume away, each at 30 degrees (and at 60 for
// the dense side, where a wrong length moves the critical angle).
void addBadInputs(std::vector<SweepPoint>& points, const std::string& fn, double eta) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const float denormal = 1e-40f;  // below FLT_MIN (1.18e-38): may be flushed to 0
  const float huge = 1e30f;       // its square overflows fp32
  auto add = [&](const std::string& label, double degrees, std::vector<float> I,
                 std::vector<float> N, float etaValue) {
    SweepPoint point = gridPoint(fn, degrees, eta);
    point.input = label;
    point.call.I = std::move(I);
    point.call.N = std::move(N);
    point.call.eta = etaValue;
    points.push_back(std::move(point));
  };
  const float e = static_cast<float>(eta);
  const std::vector<float> N = {0, 1, 0};
  for (double degrees : {30.0, 60.0}) {
    const std::vector<float> I = incident(degrees);
    add("unnormalized-I-x2", degrees, scaled(I, 2), N, e);
    add("unnormalized-I-x0.5", degrees, scaled(I, 0.5f), N, e);
    add("unnormalized-N-x3", degrees, I, scaled(N, 3), e);
    add("back-facing-N", degrees, I, scaled(N, -1), e);
  }
  const std::vector<float> I = incident(30);
  add("I=-N", 0, scaled(N, -1), N, e);
  add("zero-I", 30, {0, 0, 0}, N, e);
  add("zero-N", 30, I, {0, 0, 0}, e);
  add("denormal-I", 30, scaled(I, denormal), N, e);
  add("denormal-component", 30, {I[0], I[1], denormal}, N, e);
  add("huge-I", 30, scaled(I, huge), N, e);
  add("huge-N", 30, I, scaled(N, huge), e);
  add("nan-I", 30, {nan, I[1], 0}, N, e);
  add("nan-N", 30, I, {0, nan, 0}, e);
  add("inf-I", 30, {inf, I[1], 0}, N, e);
  add("inf-N", 30, I, {0, inf, 0}, e);
  if (fn == "refract") {
    add("nan-eta", 30, I, N, nan);
    add("inf-eta", 30, I, N, inf);
    add("zero-eta", 30, I, N, 0.0f);
    add("negative-eta", 30, I, N, -e);
  }
}

SweepGrid build(int etaStepTenths, double angleStep, const std::vector<double>& offsets) {
  SweepGrid grid;
  // In tenths, so that 1.0 is exactly 1 (summing 0.1 steps would miss it).
  for (int tenths = 3; tenths <= 25; tenths += etaStepTenths) grid.etas.push_back(tenths / 10.0);
  grid.etas.push_back(1.0);
  grid.etas.push_back(1.5);
  grid.etas.push_back(1 / 1.5);
  grid.etas.insert(grid.etas.end(), kSourceEtas.begin(), kSourceEtas.end());
  sortUnique(grid.etas);
  for (double a = 0; a <= 90 + 1e-9; a += angleStep) grid.angles.push_back(a);
  for (int k = 0; k <= 20; ++k) grid.angles.push_back(89.0 + 0.05 * k);
  for (double shortBy : {1e-1, 1e-2, 1e-3, 1e-4}) grid.angles.push_back(90 - shortBy);
  sortUnique(grid.angles);
  grid.criticalOffsets = offsets;
  return grid;
}

}  // namespace

double criticalAngleRadians(double eta) { return std::asin(1.0 / eta); }

SweepGrid fullGrid() {
  return build(1, 1.0, {5e-7, 1e-6, 2e-6, 5e-6, 1e-5, 1e-4, 1e-3, 1e-2, 5e-2});
}

SweepGrid quickGrid() {
  SweepGrid grid = build(5, 10.0, {5e-7, 1e-5, 1e-3});
  // The quick grid keeps the etas its tests name, and drops the rest of the list.
  grid.etas = {0.66, 1.0, 1.02, 1.09, 1.5, 2.5};
  return grid;
}

std::vector<double> anglesFor(const SweepGrid& grid, double eta) {
  std::vector<double> angles = grid.angles;
  if (eta > 1) {
    const double critical = criticalAngleRadians(eta);
    angles.push_back(critical / kDegree);
    for (double offset : grid.criticalOffsets) {
      angles.push_back((critical - offset) / kDegree);
      angles.push_back((critical + offset) / kDegree);
    }
  }
  sortUnique(angles);
  return angles;
}

std::vector<SweepPoint> sweepPoints(const SweepGrid& grid) {
  std::vector<SweepPoint> points;
  for (double eta : grid.etas)
    for (double degrees : anglesFor(grid, eta))
      points.push_back(gridPoint("refract", degrees, eta));
  for (double degrees : grid.angles) points.push_back(gridPoint("reflect", degrees, 1.0));
  for (double eta : {0.66, 1.5}) addBadInputs(points, "refract", eta);
  addBadInputs(points, "reflect", 1.0);
  return points;
}

}  // namespace snell::sweep
