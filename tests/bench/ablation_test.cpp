// The ablation table of the physics reference, on a small image: each
// further effect changes the picture less than the one before, the
// geometric steps end at the first invisible one, and the table's JSON
// says what its text says.
#include "bench/ablation.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "bench/dispersion_reference_image.h"
#include "bench/sphere_trace_image.h"
#include "core/scene.h"

namespace snell::bench {
namespace {

const AblationTable& table() {
  static const AblationTable t = ablationTable(makeScene("sphere"), 48, 24, 64);
  return t;
}

TEST(Ablation, EachInternalReflectionChangesLessAndTheLastStepIsInvisible) {
  const auto& rows = table().geometric;
  ASSERT_GE(rows.size(), 3u);
  EXPECT_EQ(rows.front().effect, "second interface");
  EXPECT_TRUE(rows.front().visible);  // the methods' one interface is far from a real sphere
  for (std::size_t k = 2; k < rows.size(); ++k)
    EXPECT_LT(rows[k].change.rms, rows[k - 1].change.rms) << rows[k].effect;
  for (std::size_t k = 0; k + 1 < rows.size(); ++k) EXPECT_TRUE(rows[k].visible) << rows[k].effect;
  EXPECT_FALSE(rows.back().visible) << rows.back().effect;
}

TEST(Ablation, DoublingTheWavelengthsConvergesBelowTheNoiseBeforeTheReferenceCount) {
  const auto& rows = table().spectral;
  ASSERT_EQ(rows.size(), 4u);  // 4 -> 8 ... 32 -> 64
  for (std::size_t k = 1; k < rows.size(); ++k)
    EXPECT_LT(rows[k].change.rms, rows[k - 1].change.rms) << rows[k].effect;
  EXPECT_FALSE(rows.back().visible);
}

// The references the bench uses go at least as deep as the table shows
// visible: every hit from inside before the first invisible one, and more
// wavelengths than the first doubling that changes nothing.
TEST(Ablation, TheBenchReferencesModelEveryVisibleStep) {
  EXPECT_LE(static_cast<int>(table().geometric.size()), kReferenceInternalHits);
  int enough = 0;
  for (const AblationRow& row : table().spectral)
    if (!row.visible && enough == 0)
      enough = std::stoi(row.effect.substr(row.effect.rfind(' ') + 1));
  ASSERT_GT(enough, 0);
  EXPECT_GE(kReferenceWavelengths, enough);
}

TEST(Ablation, JsonHoldsTheRows) {
  const auto path =
      std::filesystem::temp_directory_path() / fmt::format("snell_ablation_{}.json", getpid());
  writeAblationJson(table(), path);
  const nlohmann::json doc = nlohmann::json::parse(std::ifstream(path));
  std::filesystem::remove(path);
  ASSERT_EQ(doc["geometric"].size(), table().geometric.size());
  EXPECT_EQ(doc["geometric"][0]["effect"], "second interface");
  EXPECT_DOUBLE_EQ(doc["spectral"][0]["rms"].get<double>(), table().spectral[0].change.rms);
  EXPECT_NE(ablationText(table()).find("internal reflection 1"), std::string::npos);
}

}  // namespace
}  // namespace snell::bench
