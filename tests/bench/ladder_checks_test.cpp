// The order physics puts a dispersion ladder's errors in, checked on
// hand-made results: it passes a ladder that converges and names the pair
// that does not.
#include "bench/ladder_checks.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "core/errors.h"

namespace snell::bench {
namespace {

BenchRecord spectral(const std::string& backend, double wavelengths, double deMean) {
  BenchRecord r;
  r.method = fmt::format("methods/dispersion/spectral-{}", wavelengths);
  r.backend = backend;
  r.parameters = {{"Wavelengths", wavelengths}};
  r.error.deMean = deMean;
  r.error.rms = deMean / 100;
  return r;
}

TEST(WavelengthOrder, AConvergingLadderAndOneWithinNoisePass) {
  BenchResults results;
  for (const auto& [n, e] : std::vector<std::pair<double, double>>{
           {4, 0.30}, {8, 0.10}, {16, 0.061}, {32, 0.062}})  // 32 above 16 by less than noise
    results.records.push_back(spectral("gl", n, e));
  EXPECT_TRUE(wavelengthOrderViolations(results, "de_mean", errorNoise("de_mean")).empty());
}

TEST(WavelengthOrder, MoreWavelengthsFartherThanNoiseIsNamed) {
  BenchResults results;
  results.records = {spectral("gl", 4, 0.30), spectral("gl", 8, 0.10), spectral("vk", 4, 0.30),
                     spectral("vk", 8, 0.10), spectral("vk", 16, 0.20)};  // 16 worse than 8
  // A method with no wavelength count is not part of the order.
  BenchRecord rgb = spectral("vk", 0, 5.0);
  rgb.parameters = {{"EtaR", 0.65}};
  results.records.push_back(rgb);
  const auto violations = wavelengthOrderViolations(results, "de_mean", errorNoise("de_mean"));
  ASSERT_EQ(violations.size(), 1u);
  EXPECT_NE(violations[0].find("vk: 16 wavelengths"), std::string::npos) << violations[0];
  EXPECT_NE(violations[0].find("than 8"), std::string::npos) << violations[0];
}

TEST(WavelengthOrder, NoiseIsBelowWhatADisplayShowsAndUnknownMetricsAreRefused) {
  EXPECT_LT(errorNoise("rms"), 1.0 / 255.0);
  EXPECT_LT(errorNoise("de_mean"), 1.0);
  EXPECT_THROW(errorNoise("psnr"), UsageError);
}

}  // namespace
}  // namespace snell::bench
