// Charts are replaced whole or not at all: a batch that fails part way (a
// bad plot, or gnuplot stopped by Ctrl-C) leaves every chart of an earlier
// run as it was, and no drawing of its own.
#include "report/gnuplot_batch.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/errors.h"

namespace snell {
namespace {

namespace fs = std::filesystem;

const char* kGoodPlot = "set terminal svg size 200,100 name 'line'\nset output '{}'\nplot x";

TEST(GnuplotBatch, AFailingBatchLeavesEveryEarlierChartAsItWas) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("snell-gnuplot-batch-{}", getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "first.svg") << "an earlier run's chart";
  GnuplotBatch failing(dir);
  failing.add(fmt::format(fmt::runtime(kGoodPlot), "first.svg"));
  failing.add("set output 'second.svg'\nplot no_such_function(x)");
  EXPECT_THROW(failing.run(), SetupError);
  EXPECT_EQ(readBytes(dir / "first.svg"), "an earlier run's chart");
  EXPECT_FALSE(fs::exists(dir / "second.svg"));
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_EQ(entry.path().string().find(".drawing"), std::string::npos) << entry.path();

  GnuplotBatch good(dir);
  good.add(fmt::format(fmt::runtime(kGoodPlot), (dir / "first.svg").string()));  // absolute too
  good.run();
  EXPECT_NE(readBytes(dir / "first.svg").find("<svg"), std::string::npos);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace snell
