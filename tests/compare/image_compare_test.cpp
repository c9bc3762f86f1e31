#include "compare/image_compare.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <thread>

#include "compare/image_io.h"

namespace snell {
namespace {

Image flat(float value, int size = 8) {
  Image image(size, size);
  std::fill(image.pixels.begin(), image.pixels.end(), value);
  return image;
}

const ImageTolerance kTolerance{0.004, 0.002, 0.0, 0.05};

TEST(ImageCompare, IdenticalImagesPass) {
  const ImageComparison r = compareImages("reference", flat(0.5f), flat(0.5f), {}, kTolerance);
  EXPECT_EQ(r.verdict, ImageVerdict::Pass);
  EXPECT_EQ(r.maxError, 0.0);
  EXPECT_EQ(r.compared, 64u);
}

TEST(ImageCompare, OnePixelBeyondFailFails) {
  Image observed = flat(0.5f);
  observed.at(3, 2)[1] += 0.005f;
  const ImageComparison r = compareImages("golden", observed, flat(0.5f), {}, kTolerance);
  EXPECT_EQ(r.verdict, ImageVerdict::Fail);
  EXPECT_EQ(r.failed, 1u);
  EXPECT_EQ(r.maxX, 3);
  EXPECT_EQ(r.maxY, 2);
  EXPECT_NEAR(r.maxError, 0.005, 1e-6);
}

TEST(ImageCompare, BetweenWarnAndFailWarns) {
  Image observed = flat(0.5f);
  observed.at(0, 0)[0] += 0.003f;
  const ImageComparison r = compareImages("golden", observed, flat(0.5f), {}, kTolerance);
  EXPECT_EQ(r.verdict, ImageVerdict::Warn);
  EXPECT_EQ(r.warned, 1u);
  EXPECT_EQ(r.failed, 0u);
}

TEST(ImageCompare, FailPercentAllowsThatShareAndNoMore) {
  const ImageTolerance lenient{0.004, 0.002, 2.0, 0.05};  // 2% of 64 pixels is 1.28
  Image one = flat(0.5f);
  one.at(1, 1)[0] += 0.01f;
  EXPECT_EQ(compareImages("golden", one, flat(0.5f), {}, lenient).verdict, ImageVerdict::Warn);
  one.at(2, 1)[0] += 0.01f;
  EXPECT_EQ(compareImages("golden", one, flat(0.5f), {}, lenient).verdict, ImageVerdict::Fail);
}

TEST(ImageCompare, HardFailFailsWhateverThePercent) {
  const ImageTolerance lenient{0.004, 0.002, 50.0, 0.05};
  Image observed = flat(0.5f);
  observed.at(1, 1)[2] += 0.06f;
  EXPECT_EQ(compareImages("golden", observed, flat(0.5f), {}, lenient).verdict, ImageVerdict::Fail);
}

TEST(ImageCompare, MaskedPixelsAreCountedNotCompared) {
  Image observed = flat(0.5f);
  observed.at(4, 4)[0] = 10.0f;
  std::vector<PixelMask> mask(64, PixelMask::None);
  mask[4 * 8 + 4] = PixelMask::Silhouette;
  const ImageComparison r = compareImages("reference", observed, flat(0.5f), mask, kTolerance);
  EXPECT_EQ(r.verdict, ImageVerdict::Pass);
  EXPECT_EQ(r.compared, 63u);
  EXPECT_EQ(r.masked.at(pixelMaskName(PixelMask::Silhouette)), 1u);
}

TEST(ImageCompare, NanFails) {
  Image observed = flat(0.5f);
  observed.at(0, 7)[0] = std::nanf("");
  EXPECT_EQ(compareImages("reference", observed, flat(0.5f), {}, kTolerance).verdict,
            ImageVerdict::Fail);
}

TEST(ImageCompare, SizeMismatchFailsWithAReason) {
  const ImageComparison r = compareImages("golden", flat(0.5f, 8), flat(0.5f, 4), {}, kTolerance);
  EXPECT_EQ(r.verdict, ImageVerdict::Fail);
  EXPECT_NE(r.problem.find("8x8"), std::string::npos);
}

TEST(ImageCompare, HeatMapIsWritten) {
  const auto path = std::filesystem::temp_directory_path() / "snell-heat-test.png";
  Image observed = flat(0.5f);
  observed.at(1, 1)[0] = 0.6f;
  writeDifferenceHeatMap(path, observed, flat(0.5f), {}, 0.004);
  EXPECT_GT(std::filesystem::file_size(path), 0u);
  std::filesystem::remove(path);
}

// The same picture is not encoded twice: a file written from the same
// pixels (its mark, core/written_mark.h) is left as it is; other pixels,
// or a file changed since, are written.
TEST(ImageFiles, TheSamePicturesAreWrittenOnce) {
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::temp_directory_path() / ("snell-written-once-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path exr = dir / "image.exr", png = dir / "image.png", heat = dir / "heat.png";
  Image observed = flat(0.5f);
  observed.at(1, 1)[0] = 0.6f;
  const auto write = [&] {
    writeImageAtomically(exr, observed);
    writeImageAtomically(png, observed);
    writeDifferenceHeatMap(heat, observed, flat(0.5f), {}, 0.004);
  };
  write();
  const auto past = fs::file_time_type::clock::now() - std::chrono::hours(2);
  // Written again from the same pixels: untouched, but a file whose
  // mark no longer matches its time is written.
  for (const fs::path& f : {exr, png, heat}) fs::last_write_time(f, past);
  write();
  for (const fs::path& f : {exr, png, heat})
    EXPECT_GT(fs::last_write_time(f), past) << f << " was changed since its mark: written again";
  const auto then = fs::last_write_time(exr);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  write();
  EXPECT_EQ(fs::last_write_time(exr), then) << "the same pixels: not written again";
  EXPECT_EQ(readImage(exr).pixels, observed.pixels);
  observed.at(2, 2)[1] = 0.25f;
  write();
  EXPECT_GT(fs::last_write_time(exr), then) << "other pixels";
  EXPECT_EQ(readImage(exr).pixels, observed.pixels);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace snell
