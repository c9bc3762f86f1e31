// The CIE 1931 fit against the CIE's own 5 nm table, and what follows from
// it: y-bar's peak, the equal-energy white point, the sRGB white.
#include "oracle/physics/cie1931.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/errors.h"

namespace snell::physics {
namespace {

// CIE 1931 2-degree colour matching functions, 380 to 780 nm in 5 nm steps
// (CIE 15:2004 table, to the four decimals it is usually printed with).
constexpr std::array<std::array<double, 3>, 81> kCieTable = {{
    {0.0014, 0.0000, 0.0065}, {0.0022, 0.0001, 0.0105}, {0.0042, 0.0001, 0.0201},
    {0.0076, 0.0002, 0.0362}, {0.0143, 0.0004, 0.0679}, {0.0232, 0.0006, 0.1102},
    {0.0435, 0.0012, 0.2074}, {0.0776, 0.0022, 0.3713}, {0.1344, 0.0040, 0.6456},
    {0.2148, 0.0073, 1.0391}, {0.2839, 0.0116, 1.3856}, {0.3285, 0.0168, 1.6230},
    {0.3483, 0.0230, 1.7471}, {0.3481, 0.0298, 1.7826}, {0.3362, 0.0380, 1.7721},
    {0.3187, 0.0480, 1.7441}, {0.2908, 0.0600, 1.6692}, {0.2511, 0.0739, 1.5281},
    {0.1954, 0.0910, 1.2876}, {0.1421, 0.1126, 1.0419}, {0.0956, 0.1390, 0.8130},
    {0.0580, 0.1693, 0.6162}, {0.0320, 0.2080, 0.4652}, {0.0147, 0.2586, 0.3533},
    {0.0049, 0.3230, 0.2720}, {0.0024, 0.4073, 0.2123}, {0.0093, 0.5030, 0.1582},
    {0.0291, 0.6082, 0.1117}, {0.0633, 0.7100, 0.0782}, {0.1096, 0.7932, 0.0573},
    {0.1655, 0.8620, 0.0422}, {0.2257, 0.9149, 0.0298}, {0.2904, 0.9540, 0.0203},
    {0.3597, 0.9803, 0.0134}, {0.4334, 0.9950, 0.0087}, {0.5121, 1.0000, 0.0057},
    {0.5945, 0.9950, 0.0039}, {0.6784, 0.9786, 0.0027}, {0.7621, 0.9520, 0.0021},
    {0.8425, 0.9154, 0.0018}, {0.9163, 0.8700, 0.0017}, {0.9786, 0.8163, 0.0014},
    {1.0263, 0.7570, 0.0011}, {1.0567, 0.6949, 0.0010}, {1.0622, 0.6310, 0.0008},
    {1.0456, 0.5668, 0.0006}, {1.0026, 0.5030, 0.0003}, {0.9384, 0.4412, 0.0002},
    {0.8544, 0.3810, 0.0002}, {0.7514, 0.3210, 0.0001}, {0.6424, 0.2650, 0.0000},
    {0.5419, 0.2170, 0.0000}, {0.4479, 0.1750, 0.0000}, {0.3608, 0.1382, 0.0000},
    {0.2835, 0.1070, 0.0000}, {0.2187, 0.0816, 0.0000}, {0.1649, 0.0610, 0.0000},
    {0.1212, 0.0446, 0.0000}, {0.0874, 0.0320, 0.0000}, {0.0636, 0.0232, 0.0000},
    {0.0468, 0.0170, 0.0000}, {0.0329, 0.0119, 0.0000}, {0.0227, 0.0082, 0.0000},
    {0.0158, 0.0057, 0.0000}, {0.0114, 0.0041, 0.0000}, {0.0081, 0.0029, 0.0000},
    {0.0058, 0.0021, 0.0000}, {0.0041, 0.0015, 0.0000}, {0.0029, 0.0010, 0.0000},
    {0.0020, 0.0007, 0.0000}, {0.0014, 0.0005, 0.0000}, {0.0010, 0.0004, 0.0000},
    {0.0007, 0.0002, 0.0000}, {0.0005, 0.0002, 0.0000}, {0.0003, 0.0001, 0.0000},
    {0.0002, 0.0001, 0.0000}, {0.0002, 0.0001, 0.0000}, {0.0001, 0.0000, 0.0000},
    {0.0001, 0.0000, 0.0000}, {0.0001, 0.0000, 0.0000}, {0.0000, 0.0000, 0.0000},
}};

// The fit's error against the table, as stated beside the fit's constants
// (harness/oracle/physics/cie1931.cpp): largest differences 0.015 (x-bar),
// 0.007 (y-bar), 0.024 (z-bar); integrals within 0.1%.
constexpr std::array<double, 3> kPointwiseBound = {0.015, 0.008, 0.025};
constexpr double kIntegralBound = 1e-3;

std::array<double, 3> components(const Xyz& c) { return {c.x, c.y, c.z}; }

double worstDifference(double shiftNm, int component) {
  double worst = 0.0;
  for (std::size_t i = 0; i < kCieTable.size(); ++i) {
    const double nm = 380.0 + 5.0 * static_cast<double>(i) + shiftNm;
    const double fit = components(cie1931ColourMatching(nm))[static_cast<std::size_t>(component)];
    worst = std::max(worst, std::fabs(fit - kCieTable[i][static_cast<std::size_t>(component)]));
  }
  return worst;
}

TEST(Cie1931, FitFollowsTheTable) {
  for (int k = 0; k < 3; ++k) {
    EXPECT_LE(worstDifference(0.0, k), kPointwiseBound[static_cast<std::size_t>(k)]) << k;
    // The same fit read 5 nm off is far outside: the bound can fail.
    EXPECT_GT(worstDifference(5.0, k), 2.0 * kPointwiseBound[static_cast<std::size_t>(k)]) << k;
  }
}

TEST(Cie1931, YBarPeaksNear555nmAtAboutOne) {
  double peakNm = 0.0, peak = 0.0;
  for (double nm = 500.0; nm <= 600.0; nm += 0.1) {
    const double y = cie1931ColourMatching(nm).y;
    if (y > peak) peak = y, peakNm = nm;
  }
  // The table peaks at 555 nm with 1.0000; the fit within its y-bar bound,
  // at a wavelength within one table step.
  EXPECT_NEAR(peakNm, 555.0, 5.0);
  EXPECT_NEAR(peak, 1.0, kPointwiseBound[1]);
}

// Each function's integral over 380..780 nm (the fit by the midpoint rule
// at 1 nm, the table by the trapezoid rule at 5 nm) within 0.1%; with
// integrals off by at most e, the chromaticity of the equal-energy
// spectrum x = X / (X + Y + Z) is off 1/3 by at most 4e/9.
TEST(Cie1931, EqualEnergySpectrumIsWhiteAtOneThird) {
  const std::vector<SpectralSample> samples = spectralSamples(400);
  const std::vector<double> flat(samples.size(), 1.0);
  const std::array<double, 3> fit = components(integrateSpectrum(samples, flat));
  std::array<double, 3> table{};
  for (std::size_t i = 0; i < kCieTable.size(); ++i)
    for (std::size_t k = 0; k < 3; ++k)
      table[k] += kCieTable[i][k] * ((i == 0 || i + 1 == kCieTable.size()) ? 2.5 : 5.0);
  for (std::size_t k = 0; k < 3; ++k)
    EXPECT_NEAR(fit[k] / table[k], 1.0, kIntegralBound) << "integral " << k;
  const Chromaticity white = chromaticity({fit[0], fit[1], fit[2]});
  const double tolerance = 4.0 * kIntegralBound / 9.0;
  EXPECT_NEAR(white.x, 1.0 / 3.0, tolerance);
  EXPECT_NEAR(white.y, 1.0 / 3.0, tolerance);
  // A spectrum tilted towards red is not white.
  std::vector<double> tilted;
  for (const SpectralSample& s : samples) tilted.push_back(s.lambdaNm / 580.0);
  EXPECT_GT(chromaticity(integrateSpectrum(samples, tilted)).x, 1.0 / 3.0 + 10 * tolerance);
}

// D65's white (x, y) = (0.3127, 0.3290), scaled to Y = 1, is (1, 1, 1) in
// linear sRGB, to the matrix's four decimals.
TEST(Cie1931, D65WhiteIsSrgbWhite) {
  const double x = 0.3127, y = 0.3290;
  const LinearSrgb white = xyzToLinearSrgb({x / y, 1.0, (1.0 - x - y) / y});
  EXPECT_NEAR(white.r, 1.0, 1e-3);
  EXPECT_NEAR(white.g, 1.0, 1e-3);
  EXPECT_NEAR(white.b, 1.0, 1e-3);
  const LinearSrgb yellowish = xyzToLinearSrgb({1.0, 1.0, 1.0});  // equal-energy white
  EXPECT_GT(yellowish.r - yellowish.b, 0.05) << "E is redder than D65";
}

TEST(Cie1931, SpectralSamplesAreBinCentres) {
  const std::vector<SpectralSample> four = spectralSamples(4);
  ASSERT_EQ(four.size(), 4u);
  EXPECT_DOUBLE_EQ(four[0].lambdaNm, 430.0);
  EXPECT_DOUBLE_EQ(four[3].lambdaNm, 730.0);
  EXPECT_DOUBLE_EQ(four[2].weightNm, 100.0);
  // More wavelengths come closer to the 1 nm integral of a smooth spectrum.
  const auto luminance = [](int count) {
    const std::vector<SpectralSample> s = spectralSamples(count);
    return integrateSpectrum(s, std::vector<double>(s.size(), 1.0)).y;
  };
  const double reference = luminance(400);
  EXPECT_LT(std::fabs(luminance(32) - reference), std::fabs(luminance(4) - reference));
  EXPECT_THROW(spectralSamples(0), UsageError);
  EXPECT_THROW(spectralSamples(8, 300.0, 780.0), UsageError);
  EXPECT_THROW(cie1931ColourMatching(900.0), UsageError);
  const std::vector<double> tooFew(3, 1.0);
  EXPECT_THROW(integrateSpectrum(four, tooFew), UsageError);
}

}  // namespace
}  // namespace snell::physics
