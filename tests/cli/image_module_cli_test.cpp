// A run that draws needs snell's image module: when its file is nowhere,
// that is one set-up error before any case (exit 2), not a failure of every
// image case; a run without image cases does not need it.
#include <gtest/gtest.h>

#include <string>

#include "snell_process.h"

namespace {

using snell::testing::runSnell;

constexpr const char* kNoModule = "SNELL_IMAGE_LIBRARY=/nonexistent/libsnell_image_library.so";

TEST(ImageModuleCli, AMissingModuleIsOneSetUpErrorBeforeAnyCase) {
  const auto outcome = runSnell(
      "run --backend gl --filter 'orange-book/14.1-fresnel/*' --oracle-cache off", kNoModule);
  EXPECT_EQ(outcome.code, 2) << outcome.out;
  EXPECT_NE(outcome.out.find("none of these files exists"), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("/nonexistent/libsnell_image_library.so"), std::string::npos);
  EXPECT_NE(outcome.out.find("--target snell_image_library"), std::string::npos) << outcome.out;
  EXPECT_EQ(outcome.out.find("[1/"), std::string::npos) << "no case ran:\n" << outcome.out;
}

TEST(ImageModuleCli, ARunWithoutImageCasesNeedsNone) {
  const auto outcome = runSnell(
      "run --backend gl --filter 'orange-book/14.1-fresnel/sweep' --oracle-cache off", kNoModule);
  EXPECT_EQ(outcome.code, 0) << outcome.out;
}

}  // namespace
