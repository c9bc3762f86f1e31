// The critical and Brewster angles against their closed forms.
#include "oracle/physics/interface_angles.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/errors.h"

namespace snell::physics {
namespace {

TEST(InterfaceAngles, CriticalAngleOfGlassToAir) {
  EXPECT_NEAR(criticalAngleDegrees(1.5, 1.0), 41.8103, 5e-5);
  EXPECT_NEAR(criticalAngleDegrees(1.333, 1.0), 48.6066, 5e-5);  // asin(1 / 1.333)
  // A different glass gives a plainly different angle: the check can fail.
  EXPECT_GT(std::fabs(criticalAngleDegrees(1.52, 1.0) - 41.8103), 0.5);
  // Indices that nearly match: the angle nears 90 degrees, still finite.
  EXPECT_NEAR(criticalAngleDegrees(1.0 + 1e-12, 1.0), 90.0, 1e-4);
}

// A huge index: asin(1 / 1e200) is 1e-200 radians; n1^2 would overflow.
TEST(InterfaceAngles, CriticalAngleOfAHugeIndexDoesNotOverflow) {
  const double expected = 1e-200 * 180.0 / 3.14159265358979323846;
  EXPECT_NEAR(criticalAngleDegrees(1e200, 1.0) / expected, 1.0, 1e-12);
  EXPECT_NEAR(criticalAngleDegrees(1e300, 1e299), std::asin(0.1) * 180.0 / 3.14159265358979323846,
              1e-12);
  // n1 + n2 past the double range.
  EXPECT_NEAR(criticalAngleDegrees(1.7e308, 1e308),
              std::asin(1.0 / 1.7) * 180.0 / 3.14159265358979323846, 1e-12);
}

TEST(InterfaceAngles, CriticalAngleNeedsTheDenserSideFirst) {
  EXPECT_THROW(criticalAngleDegrees(1.0, 1.5), UsageError);
  EXPECT_THROW(criticalAngleDegrees(1.5, 1.5), UsageError);
  EXPECT_THROW(criticalAngleDegrees(1.5, 0.0), UsageError);
  try {
    criticalAngleDegrees(1.0, 1.5);
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("n1 > n2"), std::string::npos) << error.what();
  }
}

TEST(InterfaceAngles, BrewsterAngles) {
  EXPECT_NEAR(brewsterAngleDegrees(1.0, 1.5), 56.3099, 5e-5);  // atan(1.5)
  EXPECT_NEAR(brewsterAngleDegrees(1.0, 1.0), 45.0, 1e-14);
  // Brewster's angles into and out of a medium are complementary: the
  // refracted ray at one is at the other.
  for (const double n : {1.333, 1.5168, 2.42})
    EXPECT_NEAR(brewsterAngleDegrees(1.0, n) + brewsterAngleDegrees(n, 1.0), 90.0, 1e-12);
  EXPECT_GT(std::fabs(brewsterAngleDegrees(1.0, 1.52) - 56.3099), 0.1);
  EXPECT_THROW(brewsterAngleDegrees(-1.0, 1.5), UsageError);
}

}  // namespace
}  // namespace snell::physics
