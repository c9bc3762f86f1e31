// The report's heat maps: failing pixels circled while there are few, and
// no longer once rings would bury the errors they mark.
#include "report/heat_map_chart.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace snell {
namespace {

namespace fs = std::filesystem;

// A 64x64 image whose first `failing` pixels are off by 0.01 (over a fail
// threshold of 0.004), and the script gnuplot ran to draw its heat map.
std::string heatMapScript(std::size_t failing, HeatMapSummary& summary) {
  const fs::path dir =
      fs::temp_directory_path() / fmt::format("snell-heat-{}-{}", getpid(), failing);
  fs::remove_all(dir);
  fs::create_directories(dir);
  Image expected(64, 64), observed(64, 64);
  for (std::size_t p = 0; p < failing; ++p)
    observed.at(static_cast<int>(p % 64), static_cast<int>(p / 64))[0] += 0.01f;
  GnuplotBatch batch(dir);
  const fs::path png =
      addHeatMap(batch, "gl against the reference", observed, expected, {}, 0.004, summary);
  batch.run();
  EXPECT_GT(fs::file_size(png), 0u);
  const std::string script = readBytes(dir / "charts.gp");
  fs::remove_all(dir);
  return script;
}

TEST(HeatMapChart, FewFailingPixelsAreCircledAndManyAreNot) {
  HeatMapSummary few, many;
  const std::string fewScript = heatMapScript(13, few);
  EXPECT_EQ(few.overThreshold, 13u);
  EXPECT_NE(fewScript.find("13 pixels over 0.004 (circled)"), std::string::npos) << fewScript;
  EXPECT_NE(fewScript.find("with points"), std::string::npos) << fewScript;
  const std::string manyScript = heatMapScript(600, many);
  EXPECT_EQ(many.overThreshold, 600u);
  EXPECT_NE(manyScript.find("600 pixels over 0.004 (too many to circle)"), std::string::npos)
      << manyScript;
  EXPECT_EQ(manyScript.find("with points"), std::string::npos) << manyScript;
  // Either way the scale marks the threshold.
  for (const std::string* script : {&fewScript, &manyScript})
    EXPECT_NE(script->find("set cbtics add ('fail' 0.004)"), std::string::npos) << *script;
}

}  // namespace
}  // namespace snell
