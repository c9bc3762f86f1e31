// The OpenImageIO module: found, refused with a clear SetupError when it
// cannot be used, loaded only when an image is touched, and the image API
// through it.
#include "compare/image_library.h"

#include <gtest/gtest.h>
#include <stdlib.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "compare/image_compare.h"
#include "compare/image_io.h"
#include "core/errors.h"

namespace snell {
namespace {

namespace fs = std::filesystem;

class ImageLibrary : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("snell-image-library-" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static std::string setupError(const std::vector<std::string>& candidates) {
    try {
      openImageLibrary(candidates);
    } catch (const SetupError& error) {
      return error.what();
    }
    ADD_FAILURE() << "no SetupError";
    return {};
  }

  static Image ramp(int width, int height) {
    Image image(width, height);
    for (std::size_t k = 0; k < image.pixels.size(); ++k)
      image.pixels[k] = static_cast<float>(k % 97) / 96.0f;
    return image;
  }

  fs::path dir_;
};

TEST_F(ImageLibrary, TheBuiltModuleOpens) {
  const SnellImageLibraryFunctions& functions = openImageLibrary({SNELL_IMAGE_LIBRARY_PATH});
  EXPECT_EQ(functions.abi, SNELL_IMAGE_LIBRARY_ABI);
  EXPECT_NE(std::string(functions.libraryVersion), "");
}

TEST_F(ImageLibrary, AMissingModuleIsASetupErrorSayingWhatToDo) {
  const std::string missing = (dir_ / "libsnell_image_library.so").string();
  const std::string error = setupError({missing});
  EXPECT_NE(error.find(missing), std::string::npos) << error;
  EXPECT_NE(error.find("No such file"), std::string::npos) << error;  // dlerror's reason
  EXPECT_NE(error.find("snell_image_library"), std::string::npos) << error;
  EXPECT_NE(error.find("SNELL_IMAGE_LIBRARY"), std::string::npos) << error;
}

TEST_F(ImageLibrary, AFileThatIsNoLibraryIsASetupError) {
  const fs::path garbage = dir_ / "garbage.so";
  std::ofstream(garbage) << "not a shared object\n";
  const std::string error = setupError({garbage.string()});
  EXPECT_NE(error.find(garbage.string()), std::string::npos) << error;
}

TEST_F(ImageLibrary, ALibraryWithoutTheEntryPointIsASetupError) {
  const std::string error = setupError({"libm.so.6"});
  EXPECT_NE(error.find("libm.so.6 has no snell_image_library() entry point"), std::string::npos)
      << error;
}

TEST_F(ImageLibrary, LaterCandidatesAreTriedWhenEarlierOnesDoNotLoad) {
  const SnellImageLibraryFunctions& functions =
      openImageLibrary({(dir_ / "none.so").string(), SNELL_IMAGE_LIBRARY_PATH});
  EXPECT_EQ(functions.abi, SNELL_IMAGE_LIBRARY_ABI);
}

TEST_F(ImageLibrary, TheEnvironmentOverridesWhereItIsLooked) {
  const char* before = getenv("SNELL_IMAGE_LIBRARY");
  const std::string saved = before ? before : "";
  setenv("SNELL_IMAGE_LIBRARY", "/elsewhere/libsnell_image_library.so", 1);
  const std::vector<std::string> overridden = imageLibraryCandidates();
  unsetenv("SNELL_IMAGE_LIBRARY");
  const std::vector<std::string> defaults = imageLibraryCandidates();
  if (before) setenv("SNELL_IMAGE_LIBRARY", saved.c_str(), 1);
  EXPECT_EQ(overridden, std::vector<std::string>{"/elsewhere/libsnell_image_library.so"});
  ASSERT_EQ(defaults.size(), 2u);
  EXPECT_EQ(defaults[0], SNELL_IMAGE_LIBRARY_PATH);
  EXPECT_EQ(fs::path(defaults[1]).filename(), "libsnell_image_library.so");
}

// In a fresh process (threadsafe death tests re-run the binary), so that
// nothing earlier has loaded the module yet.
bool mapped(const char* library) {
  std::ifstream maps("/proc/self/maps");
  const std::string text{std::istreambuf_iterator<char>(maps), {}};
  return text.find(library) != std::string::npos;
}

TEST_F(ImageLibrary, OpenImageIOIsLoadedOnlyWhenAnImageIsTouched) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  // Not an image: reading it needs the module all the same, and the test
  // body (which the child runs again) must not touch an image before.
  const fs::path file = dir_ / "text.exr";
  std::ofstream(file) << "not an image\n";
  EXPECT_EXIT(
      {
        const bool before = mapped("libOpenImageIO");
        try {
          readImage(file);
        } catch (const UsageError&) {
        }
        const bool after = mapped("libOpenImageIO");
        std::fprintf(stderr, "before=%d after=%d\n", before, after);
        std::exit(0);
      },
      ::testing::ExitedWithCode(0), "before=0 after=1");
}

TEST_F(ImageLibrary, ReadingWithAnUnloadableModuleIsASetupError) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const fs::path file = dir_ / "text.exr";
  std::ofstream(file) << "not an image\n";
  const std::string missing = (dir_ / "gone.so").string();
  EXPECT_EXIT(
      {
        setenv("SNELL_IMAGE_LIBRARY", missing.c_str(), 1);
        try {
          readImage(file);
        } catch (const SetupError& error) {
          std::fprintf(stderr, "SetupError: %s\n", error.what());
          std::exit(2);
        }
        std::exit(0);
      },
      ::testing::ExitedWithCode(2), "SetupError: cannot load .*gone.so.*SNELL_IMAGE_LIBRARY");
}

TEST_F(ImageLibrary, ExrKeepsFloatsExactly) {
  const Image image = ramp(5, 3);
  const fs::path file = dir_ / "ramp.exr";
  writeImageAtomically(file, image);
  const Image back = readImage(file);
  EXPECT_EQ(back.width, 5);
  EXPECT_EQ(back.height, 3);
  EXPECT_EQ(back.pixels, image.pixels);
}

TEST_F(ImageLibrary, PngIsSrgbIn8Bits) {
  Image image(2, 1);
  image.pixels = {0.0f, 0.2140f, 1.0f, 1.0f, 2.0f, -1.0f, 0.5f, 1.0f};
  const fs::path file = dir_ / "two.png";
  writeImageAtomically(file, image);
  const Image back = readImage(file);
  ASSERT_EQ(back.pixels.size(), 8u);
  // linear 0.214 is sRGB 0.5; out-of-range values clamp; 8 bits in between.
  const float expected[8] = {0.0f, 0.5f, 1.0f, 1.0f, 1.0f, 0.0f, 0.7354f, 1.0f};
  for (int k = 0; k < 8; ++k) EXPECT_NEAR(back.pixels[k], expected[k], 1.0 / 255) << k;
}

TEST_F(ImageLibrary, AFileThatIsNoImageIsTheUsersError) {
  const fs::path file = dir_ / "text.exr";
  std::ofstream(file) << "not an image\n";
  try {
    readImage(file);
    ADD_FAILURE() << "no UsageError";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find(file.string() + ": unreadable"), std::string::npos)
        << error.what();
  }
}

TEST_F(ImageLibrary, AnImageWithoutAlphaIsTheUsersError) {
  const fs::path file = dir_ / "grey.png";
  // One channel, written through the module's own table.
  const std::vector<float> values(4, 0.5f);
  SnellImageError error;
  ASSERT_EQ(imageLibrary().write(file.c_str(), values.data(), 2, 2, 1, SNELL_IMAGE_SRGB8, &error),
            SNELL_IMAGE_OK)
      << error.message;
  try {
    readImage(file);
    ADD_FAILURE() << "no UsageError";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("has 1 channels, RGBA (4) expected"),
              std::string::npos)
        << error.what();
  }
}

TEST_F(ImageLibrary, AnUnwritableFileIsASetupError) {
  EXPECT_THROW(writeImageAtomically(dir_ / "no-such-folder" / "x.exr", ramp(2, 2)), SetupError);
  EXPECT_THROW(
      writeDifferenceHeatMap(dir_ / "no-such-folder" / "x.png", ramp(2, 2), ramp(2, 2), {}, 0.01),
      SetupError);
}

}  // namespace
}  // namespace snell
