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
}

}  // namespace
}  // namespace snell
