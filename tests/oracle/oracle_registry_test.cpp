// Listing oracles by the names manifests use.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/errors.h"
#include "oracle/vertex_oracle.h"

namespace snell {
namespace {

TEST(OracleRegistry, KnowsTheFresnelListing) {
  const std::vector<std::string> names = vertexOracleNames();
  EXPECT_NE(std::find(names.begin(), names.end(), "orange_book_fresnel"), names.end());
  const auto oracle = makeVertexOracle("orange_book_fresnel");
  ASSERT_NE(oracle, nullptr);
  // gl_Position is there for the reference renderer; manifests capture the others.
  EXPECT_EQ(oracle->outputs(),
            (std::vector<std::string>{"Reflect", "Refract", "Ratio", "gl_Position"}));
}

TEST(OracleRegistry, UnknownNameIsAUsageErrorNamingTheKnownOracles) {
  try {
    makeVertexOracle("no_such_oracle");
    FAIL() << "no UsageError";
  } catch (const UsageError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("no_such_oracle"), std::string::npos) << message;
    EXPECT_NE(message.find("orange_book_fresnel"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace snell
