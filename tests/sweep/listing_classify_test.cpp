// The listing classifier on hand-made draws: a clean series gives no
// break, and each kind of bad data gives its break with its class: a weight
// over 1 that the listing computes (method) or that only a backend gives
// outside its interval (implementation), a weight falling toward grazing,
// a refracted ray on the incident side, backends that disagree, and the
// zero vector's switch found at the critical angle.
#include "sweep/listing_classify.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace snell::sweep {
namespace {

constexpr double kDegree = std::numbers::pi / 180;

std::vector<ListingPoint> gridPoints(const std::vector<double>& angles) {
  SweepGrid grid;
  grid.angles = angles;
  std::vector<ListingPoint> points;
  for (const ListingPoint& p : listingPoints(grid, {}, false))
    if (std::find(angles.begin(), angles.end(), p.angleDegrees) != angles.end())
      points.push_back(p);
  return points;
}

// A weight output whose oracle says `reference` with a tight interval.
OracleVarying weightOracle(const std::vector<double>& reference) {
  OracleVarying v;
  v.name = "Ratio";
  v.components = 1;
  for (double r : reference) {
    v.reference.push_back(r);
    v.strict.push_back(static_cast<float>(r));
    v.lo.push_back(r - 1e-6);
    v.hi.push_back(r + 1e-6);
    v.undefined.push_back(0);
  }
  return v;
}

CapturedVarying captured(const std::string& name, int components, std::vector<float> data) {
  return {name, components, std::move(data)};
}

bool has(const std::vector<ListingBreak>& breaks, const std::string& kind, BreakClass cls) {
  return std::any_of(breaks.begin(), breaks.end(),
                     [&](const ListingBreak& b) { return b.kind == kind && b.cls == cls; });
}

struct Fixture {
  std::vector<ListingPoint> points = gridPoints({0, 30, 60});
  ListingDrawView view() const { return {"test/listing", "unit", 0, &points, {}}; }
};

TEST(ListingClassify, ACleanRisingWeightHasNoBreak) {
  Fixture f;
  const std::vector<OracleVarying> expected = {weightOracle({0.04, 0.05, 0.09})};
  const std::vector<CapturedVarying> observed = {captured("Ratio", 1, {0.04f, 0.05f, 0.09f})};
  const ListingBackendView gl{"gl", true, "", true, "", &expected, &observed, false};
  EXPECT_TRUE(classifyListingDraw(f.view(), gl).empty());
}

TEST(ListingClassify, AWeightOverOneTheListingComputesIsTheMethods) {
  Fixture f;
  const std::vector<OracleVarying> expected = {weightOracle({1.5, 1.4, 1.2})};
  const std::vector<CapturedVarying> observed = {captured("Ratio", 1, {1.5f, 1.4f, 1.2f})};
  const ListingBackendView gl{"gl", true, "", true, "", &expected, &observed, false};
  const std::vector<ListingBreak> breaks = classifyListingDraw(f.view(), gl);
  EXPECT_TRUE(has(breaks, "weight_above_one_energy_grows", BreakClass::Method));
  EXPECT_TRUE(has(breaks, "weight_falls_toward_grazing", BreakClass::Method));
  EXPECT_FALSE(has(breaks, "outside_spec", BreakClass::Implementation));
}

TEST(ListingClassify, AWeightOnlyTheBackendGetsWrongIsTheImplementations) {
  Fixture f;
  const std::vector<OracleVarying> expected = {weightOracle({0.04, 0.05, 0.09})};
  const std::vector<CapturedVarying> observed = {captured("Ratio", 1, {0.04f, 1.25f, 0.09f})};
  const ListingBackendView gl{"gl", true, "", true, "", &expected, &observed, false};
  const std::vector<ListingBreak> breaks = classifyListingDraw(f.view(), gl);
  EXPECT_TRUE(has(breaks, "outside_spec", BreakClass::Implementation));
  EXPECT_TRUE(has(breaks, "weight_above_one_energy_grows", BreakClass::Implementation));
  EXPECT_TRUE(has(breaks, "discontinuity", BreakClass::Implementation));
}

TEST(ListingClassify, ARefractedRayOnTheIncidentSideIsFlagged) {
  Fixture f;
  // Correct: into the surface (negative along the normal); wrong: mirrored out.
  OracleVarying v;
  v.name = "Refract";
  v.components = 3;
  std::vector<float> wrong;
  for (const ListingPoint& p : f.points) {
    // Snell's law into glass (n = 1.5): along the surface's tangent in the
    // plane of incidence, and into the surface along -N.
    const double theta = p.angleDegrees * kDegree;
    const double a = std::asin(std::sin(theta) / 1.5);
    const double tangent[3] = {std::cos(theta), 0, -std::sin(theta)};
    double t[3];
    for (int c = 0; c < 3; ++c) t[c] = std::sin(a) * tangent[c] - std::cos(a) * p.trueNormal[c];
    for (int c = 0; c < 3; ++c) {
      v.reference.push_back(t[c]);
      v.lo.push_back(t[c] - 1e-6);
      v.hi.push_back(t[c] + 1e-6);
      v.undefined.push_back(0);
      // Mirrored across the surface: out on the incident side.
      wrong.push_back(static_cast<float>(t[c] + 2 * std::cos(a) * p.trueNormal[c]));
    }
  }
  std::vector<OracleVarying> expected = {v};
  std::vector<CapturedVarying> observed = {captured("Refract", 3, wrong)};
  const ListingBackendView gl{"gl", true, "", true, "", &expected, &observed, false};
  const ListingDrawView view{"test/listing", "unit", 1 / 1.5, &f.points, {}};
  std::vector<ListingBreak> breaks = classifyListingDraw(view, gl);
  EXPECT_TRUE(has(breaks, "refracted_wrong_side", BreakClass::Implementation));
  EXPECT_TRUE(has(breaks, "refracted_direction_error", BreakClass::Implementation));
  std::vector<float> right(v.reference.begin(), v.reference.end());
  observed = {captured("Refract", 3, right)};
  EXPECT_TRUE(classifyListingDraw(view, gl).empty());
  // A listing that refracts with the wrong eta: the backends follow it, the
  // method is off Snell's law.
  const ListingDrawView glass{"test/listing", "unit", 1 / 1.2, &f.points, {}};
  breaks = classifyListingDraw(glass, gl);
  EXPECT_TRUE(has(breaks, "refracted_direction_error", BreakClass::Method));
  EXPECT_FALSE(has(breaks, "refracted_direction_error", BreakClass::Implementation));
}

TEST(ListingClassify, BackendsThatDisagreeOutsideTheSpec) {
  Fixture f;
  const std::vector<OracleVarying> expected = {weightOracle({0.04, 0.05, 0.09})};
  const std::vector<CapturedVarying> good = {captured("Ratio", 1, {0.04f, 0.05f, 0.09f})};
  const std::vector<CapturedVarying> bad = {captured("Ratio", 1, {0.04f, 0.06f, 0.09f})};
  const ListingBackendView gl{"gl", true, "", true, "", &expected, &good, false};
  const ListingBackendView vk{"vk", true, "", true, "", &expected, &bad, false};
  const std::vector<ListingBreak> breaks = listingDisagreements(f.view(), gl, vk);
  ASSERT_EQ(breaks.size(), 1u);
  EXPECT_EQ(breaks[0].cls, BreakClass::Implementation);
  EXPECT_EQ(breaks[0].backend, "gl|vk");
  EXPECT_TRUE(listingDisagreements(f.view(), gl, gl).empty());
}

TEST(ListingClassify, AColourTheSpecNoLongerBoundsNearDotNHZeroIsAMethodBreak) {
  std::vector<ListingPoint> points(2);
  for (ListingPoint& p : points) p.input = "dot(N,H)->0";
  OracleVarying v;
  v.name = "Color";
  v.components = 1;
  v.reference = {0.5, 0.5};
  v.lo = {0.49, 0.0};
  v.hi = {0.51, 1.0};  // the second point's interval spans the whole range
  v.undefined = {0, 0};
  const std::vector<OracleVarying> expected = {v};
  const std::vector<CapturedVarying> observed = {captured("Color", 1, {0.5f, 0.5f})};
  const ListingDrawView view{"test/diffraction", "unit", 0, &points, {}};
  const std::vector<ListingBreak> breaks =
      classifyListingDraw(view, {"gl", true, "", true, "", &expected, &observed});
  ASSERT_EQ(breaks.size(), 1u);
  EXPECT_EQ(breaks[0].kind, "diffraction_dot_NH_to_0");
  EXPECT_EQ(breaks[0].cls, BreakClass::Method);
}

TEST(ListingClassify, ACrashedDrawIsOneCrashBreak) {
  Fixture f;
  const ListingBackendView vk{"vk",    false, "killed by signal 11", true, "", nullptr,
                              nullptr, false};
  const std::vector<ListingBreak> breaks = classifyListingDraw(f.view(), vk);
  ASSERT_EQ(breaks.size(), 1u);
  EXPECT_EQ(breaks[0].kind, "crash");
  // Cut off at --timeout, the draw did not crash.
  const ListingBackendView slow{"vk",    false, "no answer within 0.001 s", true, "", nullptr,
                                nullptr, true};
  const std::vector<ListingBreak> cut = classifyListingDraw(f.view(), slow);
  ASSERT_EQ(cut.size(), 1u);
  EXPECT_EQ(cut[0].kind, "timeout");
}

TEST(ListingClassify, FindsTheZeroVectorsSwitchAtTheCriticalAngle) {
  const double critical = std::asin(1 / 1.5) / kDegree;
  std::vector<ListingPoint> points = gridPoints({0, 30, 60});
  for (double a : {critical - 1e-4, critical + 1e-4}) {
    ListingPoint p = points[1];
    p.angleDegrees = a;
    points.push_back(p);
  }
  OracleVarying v;
  v.name = "T";
  v.components = 3;
  std::vector<float> data;
  for (const ListingPoint& p : points) {
    const float x = p.angleDegrees < critical ? 0.5f : 0.0f;
    for (int c = 0; c < 3; ++c) {
      v.reference.push_back(c == 0 ? x : 0);
      v.lo.push_back(c == 0 ? x : 0);
      v.hi.push_back(c == 0 ? x : 0);
      v.undefined.push_back(0);
      data.push_back(c == 0 ? x : 0.0f);
    }
  }
  const std::vector<OracleVarying> expected = {v};
  const std::vector<CapturedVarying> observed = {captured("T", 3, data)};
  const ListingDrawView view{"test/listing", "unit", 1.5, &points, {}};
  const std::vector<ListingCriticalAngle> found =
      listingCriticalAngles(view, {"gl", true, "", true, "", &expected, &observed});
  ASSERT_EQ(found.size(), 1u);
  EXPECT_TRUE(found[0].found);
  EXPECT_NEAR(found[0].closedFormDegrees, 41.8103149, 1e-6);
  EXPECT_NEAR(found[0].foundDegrees, critical, 1e-4);
}

}  // namespace
}  // namespace snell::sweep
