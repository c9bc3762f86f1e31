// The width tool's own checks: its dEQP-style interval holds every value its
// conforming machine returns, and its comparators catch an interval that is
// too narrow.
#include <gtest/gtest.h>

#include <cmath>

#include "widths/fp32_grid.h"
#include "widths/inputs.h"
#include "widths/measure.h"
#include "widths/report.h"

namespace snell::widths {
namespace {

TEST(WidthsGrid, UlpIsTheGapBelowAtAPowerOfTwo) {
  EXPECT_EQ(ulpOf(1.0), 0x1p-24);
  EXPECT_EQ(ulpOf(1.5), 0x1p-23);
  EXPECT_EQ(ulpOf(-2.0), 0x1p-23);
  EXPECT_EQ(ulpOf(0x1p-140), 0x1p-149);
}

TEST(WidthsGrid, RoundsInEachDirection) {
  const double third = 1.0 / 3.0;
  const float above = 0x1.555556p-2f;  // 0.333333343, the nearest float
  const float below = 0x1.555554p-2f;  // 0.333333313
  EXPECT_EQ(roundTo(third, 0.0, Rounding::Down), below);
  EXPECT_EQ(roundTo(third, 0.0, Rounding::Up), above);
  EXPECT_EQ(roundTo(third, 0.0, Rounding::Nearest), above);
  EXPECT_EQ(roundTo(-third, 0.0, Rounding::TowardZero), -below);
  EXPECT_EQ(roundTo(-third, 0.0, Rounding::Down), -above);
  // An exact float stays put; a tail below it moves the rounding down.
  EXPECT_EQ(roundTo(1.0, 0.0, Rounding::Down), 1.0f);
  EXPECT_EQ(roundTo(1.0, -0x1p-80, Rounding::Down), std::nextafter(1.0f, 0.0f));
  EXPECT_EQ(roundTo(1.0, 0x1p-80, Rounding::Up), std::nextafter(1.0f, 2.0f));
}

// Every value the conforming machine returns lies in the dEQP-style box,
// on random and edge inputs of both built-ins, under both rule sets.
TEST(WidthsDeqpStyle, HoldsEveryConformingValueOfTheBuiltins) {
  std::size_t held = 0;
  for (const PrecisionRules rules : {PrecisionRules::Glsl, PrecisionRules::Vulkan})
    for (const BuiltinInputSet& set : builtinInputSets(25, 3)) {
      std::uint64_t seed = 100;
      for (const BuiltinInput& input : set.inputs) {
        const SampleRecord record =
            builtinRecord(set.fn, input.I, input.N, input.eta, rules, 12, ++seed);
        for (const std::vector<float>& value : record.conforming) {
          EXPECT_TRUE(boxAllows(record.deqp, value))
              << set.fn << " / " << set.name << ": " << record.input;
          ++held;
        }
      }
    }
  EXPECT_GT(held, 2000u);
}

TEST(WidthsDeqpStyle, HoldsEveryConformingValueOfAListing) {
  for (const ListingInputSet& set : listingInputSets(SNELL_SOURCE_ROOT "/shaders", 6, 5)) {
    if (set.oracle != "orange_book_fresnel" && set.oracle != "shadertoy_bubble") continue;
    const auto outputs = listingRecords(set.oracle, set.bindings, PrecisionRules::Glsl, 8, 7);
    ASSERT_FALSE(outputs.empty());
    for (const auto& records : outputs)
      for (const SampleRecord& record : records)
        for (const std::vector<float>& value : record.conforming)
          EXPECT_TRUE(boxAllows(record.deqp, value)) << set.manifest << ": " << record.input;
  }
}

// A record whose boxes are narrowed by one float below a conforming value:
// both comparators must count the escape, and --check must name the row.
TEST(WidthsComparator, FlagsAnIntervalNarrowedBelowAConformingValue) {
  const BuiltinInput input = builtinInputSets(1, 11)[2].inputs[0];  // refract / random
  SampleRecord record =
      builtinRecord("refract", input.I, input.N, input.eta, PrecisionRules::Glsl, 4, 1);
  RowAccumulator honest("refract", PrecisionRules::Glsl);
  honest.add(record);
  const RowStats honestStats = honest.finish();
  ASSERT_EQ(honestStats.deqpEscapes, 0u);
  ASSERT_EQ(honestStats.snellEscapes, 0u);

  const float value = record.conforming[0][1];
  record.deqp[1].hi = std::nextafter(value, -INFINITY);
  record.deqp[1].lo = std::min(record.deqp[1].lo, record.deqp[1].hi);
  EXPECT_FALSE(boxAllows(record.deqp, record.conforming[0]));
  for (SnellWay& way : record.snell.ways) {
    way.hi[1] = std::nextafter(value, -INFINITY);
    way.lo[1] = std::min(way.lo[1], way.hi[1]);
  }
  EXPECT_FALSE(record.snell.allows(record.conforming[0]));

  RowAccumulator narrowed("refract", PrecisionRules::Glsl);
  narrowed.add(record);
  const RowStats stats = narrowed.finish();
  EXPECT_GE(stats.deqpEscapes, 1u);
  EXPECT_GE(stats.snellEscapes, 1u);
  EXPECT_NE(stats.snellEscape.find("\"fn\":\"refract\""), std::string::npos);

  // --check fails a row only where snell escapes and the dEQP-style box holds.
  WidthReport report{"test", {stats}};
  EXPECT_TRUE(unsoundRows(report).empty());
  report.rows[0].deqpEscapes = 0;
  EXPECT_EQ(unsoundRows(report).size(), 1u);
}

}  // namespace
}  // namespace snell::widths
