#include "golden/golden_store.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "compare/image_io.h"
#include "core/errors.h"

namespace snell {
namespace {

namespace fs = std::filesystem;

class GoldenStore : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("snell-golden-" + std::to_string(getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_);
    image_ = Image(16, 8);
    for (std::size_t k = 0; k < image_.pixels.size(); ++k) image_.pixels[k] = 0.001f * k + 0.1f;
  }
  void TearDown() override { fs::remove_all(root_); }

  std::string errorReading(int width = 16, int height = 8) {
    try {
      readGolden(root_, "a/b/sphere", "gl", width, height, "snell bless --golden g --filter 'a/b/sphere'");
    } catch (const UsageError& error) {
      return error.what();
    }
    ADD_FAILURE() << "no error";
    return {};
  }

  fs::path root_;
  Image image_;
};

TEST_F(GoldenStore, RoundTripIsExact) {
  writeGolden(root_, "a/b/sphere", "gl", image_, {{"renderer", "llvmpipe"}});
  const Golden golden = readGolden(root_, "a/b/sphere", "gl", 16, 8, "");
  EXPECT_EQ(golden.image.pixels, image_.pixels);
  EXPECT_EQ(golden.metadata["renderer"], "llvmpipe");
  EXPECT_TRUE(fs::exists(goldenFiles(root_, "a/b/sphere", "gl").preview));
}

TEST_F(GoldenStore, MissingGoldenSaysHowToBless) {
  const std::string message = errorReading();
  EXPECT_NE(message.find("missing"), std::string::npos) << message;
  EXPECT_NE(message.find("bless a new one with `snell bless --golden g --filter 'a/b/sphere'`"),
            std::string::npos)
      << message;
}

TEST_F(GoldenStore, TruncatedGoldenIsAClearErrorAndStaysAsItWas) {
  writeGolden(root_, "a/b/sphere", "gl", image_, {});
  const fs::path exr = goldenFiles(root_, "a/b/sphere", "gl").image;
  fs::resize_file(exr, fs::file_size(exr) / 2);
  const auto size = fs::file_size(exr);
  const std::string message = errorReading();
  EXPECT_NE(message.find(exr.string()), std::string::npos) << message;
  EXPECT_EQ(fs::file_size(exr), size);
}

TEST_F(GoldenStore, WrongSizeIsAClearError) {
  writeGolden(root_, "a/b/sphere", "gl", image_, {});
  EXPECT_NE(errorReading(32, 32).find("is 16x8, the scene renders 32x32"), std::string::npos);
}

TEST_F(GoldenStore, WrongChannelCountIsAClearError) {
  writeGolden(root_, "a/b/sphere", "gl", image_, {});
  // Replace the EXR by a 3-channel image.
  const fs::path exr = goldenFiles(root_, "a/b/sphere", "gl").image;
  std::ofstream(root_ / "x.ppm") << "P3\n1 1\n255\n1 2 3\n";
  fs::copy_file(root_ / "x.ppm", exr, fs::copy_options::overwrite_existing);
  EXPECT_NE(errorReading().find(exr.string()), std::string::npos);
}

TEST_F(GoldenStore, BrokenMetadataIsAClearError) {
  writeGolden(root_, "a/b/sphere", "gl", image_, {});
  std::ofstream(goldenFiles(root_, "a/b/sphere", "gl").metadata, std::ios::trunc) << "{ not json";
  EXPECT_NE(errorReading().find("not valid JSON"), std::string::npos);
}

}  // namespace
}  // namespace snell
