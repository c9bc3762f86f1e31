#include "core/sealed_record.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

namespace snell {
namespace {

TEST(SealedRecord, OpensOnlyUnderItsOwnTagAndKey) {
  const RecordTag mine = recordTag("snelltst", 1, 2);
  const Digest key = digestOf("key");
  const std::string bytes = sealRecord(mine, key, "payload");
  ASSERT_EQ(openRecord(mine, key, bytes), std::optional<std::string_view>("payload"));
  EXPECT_FALSE(openRecord(recordTag("snellxxx", 1, 2), key, bytes));
  EXPECT_FALSE(openRecord(recordTag("snelltst", 2, 2), key, bytes));
  EXPECT_FALSE(openRecord(recordTag("snelltst", 1, 3), key, bytes));
  EXPECT_FALSE(openRecord(mine, digestOf("other"), bytes));
  EXPECT_FALSE(openRecord(mine, key, bytes.substr(0, bytes.size() - 1)));
  EXPECT_FALSE(openRecord(mine, key, bytes + "!"));
  std::string flipped = bytes;
  flipped.back() = 'x';
  EXPECT_FALSE(openRecord(mine, key, flipped));
  EXPECT_FALSE(openRecord(mine, key, ""));
}

TEST(SealedRecord, FieldsReadBackAndAShortReadFails) {
  ByteWriter w;
  w.put(std::uint32_t{7});
  w.put(std::string("text"));
  w.putArray(std::vector<double>{1.5, -0.0});
  const std::string bytes = w.take();
  ByteReader r(bytes);
  EXPECT_EQ(r.get<std::uint32_t>(), 7u);
  EXPECT_EQ(r.getString(), "text");
  const std::vector<double> values = r.getArray<double>();
  ASSERT_EQ(values.size(), 2u);
  EXPECT_TRUE(std::signbit(values[1]));
  EXPECT_TRUE(r.ok());
  EXPECT_TRUE(r.atEnd());
  EXPECT_EQ(r.get<std::uint8_t>(), 0);
  EXPECT_FALSE(r.ok());
}

TEST(SealedRecord, AHugeCountIsRefusedWithoutAllocating) {
  ByteWriter w;
  w.put(std::numeric_limits<std::uint64_t>::max());
  const std::string bytes = w.take();
  ByteReader strings(bytes);
  EXPECT_EQ(strings.getString(), "");
  EXPECT_FALSE(strings.ok());
  ByteReader arrays(bytes);
  EXPECT_TRUE(arrays.getArray<double>().empty());
  EXPECT_FALSE(arrays.ok());
  ByteReader widened(bytes);
  EXPECT_TRUE((widened.getArrayAs<float, double>().empty()));
  EXPECT_FALSE(widened.ok());
}

TEST(SealedRecord, FloatsReadAsDoublesKeepTheirValuesAndAShortArrayFails) {
  ByteWriter w;
  const float tiny = std::numeric_limits<float>::denorm_min();
  w.putArray(std::vector<float>{0.1f, -0.0f, tiny, std::numeric_limits<float>::infinity()});
  const std::string bytes = w.take();
  ByteReader r(bytes);
  const std::vector<double> values = r.getArrayAs<float, double>();
  ASSERT_EQ(values.size(), 4u);
  EXPECT_EQ(values[0], static_cast<double>(0.1f));
  EXPECT_TRUE(std::signbit(values[1]));
  EXPECT_EQ(values[2], static_cast<double>(tiny));
  EXPECT_TRUE(std::isinf(values[3]));
  EXPECT_TRUE(r.ok() && r.atEnd());
  // Two floats short: nothing read, and the reader says so.
  ByteReader cut(std::string_view(bytes).substr(0, bytes.size() - 8));
  EXPECT_TRUE((cut.getArrayAs<float, double>().empty()));
  EXPECT_FALSE(cut.ok());
}

}  // namespace
}  // namespace snell
