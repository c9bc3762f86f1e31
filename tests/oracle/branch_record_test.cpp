// RecordBranches: the outcomes of a double evaluation's own branches, which
// evaluateBuiltin compares with each Interval path so that it replays only
// the paths the double evaluation did not take itself.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "oracle/branch_paths.h"
#include "oracle/builtin_probe.h"
#include "oracle/glsl/branch.h"

namespace snell {
namespace {

int takeBoth(bool first, bool second) {
  const int a = glsl::branch(
      first, [] { return 1; }, [] { return 0; });
  const int b = glsl::branch(
      second, [] { return 2; }, [] { return 0; });
  return a + b;
}

TEST(RecordBranches, RecordsEachOutcomeInOrderWhileAlive) {
  std::vector<bool> outcomes;
  {
    const RecordBranches recording(outcomes);
    EXPECT_EQ(takeBoth(true, false), 1);
    EXPECT_EQ(takeBoth(false, true), 2);
  }
  EXPECT_EQ(outcomes, (std::vector<bool>{true, false, false, true}));
  EXPECT_EQ(activeBranchRecord(), nullptr);
  takeBoth(true, true);
  EXPECT_EQ(outcomes.size(), 4u);  // nothing recorded once it is gone
}

TEST(RecordBranches, AReplayDecidesAndIsNotRecorded) {
  std::vector<bool> outcomes;
  const RecordBranches recording(outcomes);
  const std::vector<bool> forced = {false, false};
  BranchReplay replay(forced);
  {
    const UseBranchReplay replaying(&replay);
    EXPECT_EQ(takeBoth(true, true), 0);
  }
  EXPECT_TRUE(outcomes.empty());
}

// Near the critical angle refract's k < 0 may go either way: one way is
// the double evaluation's own path (its value is `value`), the other the
// replayed one, and both carry the exact value along their own branch.
TEST(RecordBranches, EachWayOfAnUndecidedRefractHasTheValueOfItsOwnBranch) {
  const float eta = 1.5f;
  const float s = 1.0f / eta;
  const BuiltinCall call{"refract", {s, -std::sqrt(1.0f - s * s), 0.0f}, {0.0f, 1.0f, 0.0f}, eta};
  const BuiltinResult r = evaluateBuiltin(call);
  ASSERT_EQ(r.ways.size(), 2u);
  int zeroWays = 0, ownWays = 0;
  for (const BuiltinWay& way : r.ways) {
    const bool zero = way.value[0] == 0.0 && way.value[1] == 0.0 && way.value[2] == 0.0;
    zeroWays += zero ? 1 : 0;
    ownWays += way.value == r.value ? 1 : 0;
    if (!zero) {
      EXPECT_NEAR(way.value[0], double(eta) * s, 1e-6);  // sin t = eta sin i
    }
  }
  EXPECT_EQ(zeroWays, 1);
  EXPECT_EQ(ownWays, 1);
}

}  // namespace
}  // namespace snell
