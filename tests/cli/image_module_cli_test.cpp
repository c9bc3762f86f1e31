// A run that draws needs snell's image module: when its file is nowhere,
// that is one set-up error before any case (exit 2), not a failure of every
// image case; a run without image cases does not need it, nor one whose
// image cases are all skipped.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
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

// A module file that is there but does not load is not fixed by building
// it: the message says what else to look at.
TEST(ImageModuleCli, AModuleThatIsThereButDoesNotLoadIsNotToBeBuilt) {
  namespace fs = std::filesystem;
  const fs::path fake =
      fs::temp_directory_path() / ("snell-not-a-module-" + std::to_string(getpid()) + ".so");
  std::ofstream(fake) << "not a shared library\n";
  const auto outcome =
      runSnell("run --backend gl --filter 'orange-book/14.1-fresnel/sphere' --oracle-cache off",
               "SNELL_IMAGE_LIBRARY=" + fake.string());
  fs::remove(fake);
  EXPECT_NE(outcome.code, 0) << outcome.out;
  EXPECT_NE(outcome.out.find("which is there but does not load: `ldd` on it"), std::string::npos)
      << outcome.out;
  EXPECT_EQ(outcome.out.find("build it"), std::string::npos) << outcome.out;
}

TEST(ImageModuleCli, ARunWithoutImageCasesNeedsNone) {
  const auto outcome = runSnell(
      "run --backend gl --filter 'orange-book/14.1-fresnel/sweep' --oracle-cache off", kNoModule);
  EXPECT_EQ(outcome.code, 0) << outcome.out;
}

// A machine without OpenImageIO runs the vector cases by listing the image
// ones as skips; the module was asked for by every case the catalog holds.
TEST(ImageModuleCli, ImageCasesSkippedByAnExpectationsFileNeedNone) {
  namespace fs = std::filesystem;
  const fs::path skips =
      fs::temp_directory_path() / ("snell-image-module-" + std::to_string(getpid()) + "-skips.txt");
  std::ofstream(skips) << "# reason: no image module on this machine\n"
                          "^orange-book/14.1-fresnel/(sphere|torus)$\n";
  const auto outcome = runSnell(
      "run --backend gl --filter 'orange-book/14.1-fresnel/*' "
      "--oracle-cache off --expectations " +
          skips.string(),
      kNoModule);
  fs::remove(skips);
  EXPECT_EQ(outcome.code, 0) << outcome.out;
  EXPECT_NE(outcome.out.find("skipped: gl orange-book/14.1-fresnel/sphere"), std::string::npos)
      << outcome.out;
  EXPECT_NE(outcome.out.find("orange-book/14.1-fresnel/sweep Pass"), std::string::npos)
      << outcome.out;
}

}  // namespace
