// A driver child's answer survives the pipe: NaN and infinities as text,
// every float exact; a draw's description round-trips through the job file.
#include "sweep/listing_capture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace snell::sweep {
namespace {

TEST(ListingCapture, AnswerLineRoundTripsNonFiniteValues) {
  DrawCapture c;
  c.compiled = true;
  c.varyings.push_back({"Ratio",
                        1,
                        {0.1f, std::numeric_limits<float>::quiet_NaN(),
                         -std::numeric_limits<float>::infinity(), 1e-40f}});
  const DrawCapture back = drawCaptureFromLine(drawCaptureLine(3, c));
  EXPECT_TRUE(back.answered);
  EXPECT_TRUE(back.compiled);
  ASSERT_EQ(back.varyings.size(), 1u);
  EXPECT_EQ(back.varyings[0].data[0], 0.1f);
  EXPECT_TRUE(std::isnan(back.varyings[0].data[1]));
  EXPECT_EQ(back.varyings[0].data[2], -std::numeric_limits<float>::infinity());
  EXPECT_EQ(back.varyings[0].data[3], 1e-40f);
}

TEST(ListingCapture, DrawLineRoundTrips) {
  const DrawSpec spec{"/x/manifest.toml", "stretched", 1 / 1.1, true};
  const DrawSpec back = parseDrawLine(drawLine(spec));
  EXPECT_EQ(back.manifestPath, spec.manifestPath);
  EXPECT_EQ(back.frame, "stretched");
  EXPECT_EQ(back.eta, spec.eta);
  EXPECT_TRUE(back.quick);
  EXPECT_THROW(parseDrawLine("just one field"), std::exception);
}

}  // namespace
}  // namespace snell::sweep
