#pragma once
// Colour from spectra: the CIE 1931 2-degree colour matching functions, as
// Wyman, Sloan & Shirley's multi-lobe analytic fit, spectral integration
// over N wavelengths, and XYZ to linear sRGB.
#include <span>
#include <vector>

namespace snell::physics {

struct Xyz {
  double x = 0.0, y = 0.0, z = 0.0;
};
struct LinearSrgb {
  double r = 0.0, g = 0.0, b = 0.0;
};
struct Chromaticity {
  double x = 0.0, y = 0.0;
};

// The fit's domain: the CIE table's 360 to 830 nm. Outside it, UsageError.
inline constexpr double kCieMinNm = 360.0;
inline constexpr double kCieMaxNm = 830.0;

// x-bar, y-bar, z-bar at lambda (nm): C. Wyman, P.-P. Sloan and P. Shirley,
// "Simple Analytic Approximations to the CIE XYZ Color Matching Functions",
// JCGT 2(2), 1-11 (2013), the multi-lobe piecewise Gaussian fit (their
// equation 4). Its error is described under cie1931.cpp's constants.
Xyz cie1931ColourMatching(double lambdaNm);

// IEC 61966-2-1 (sRGB, D65 white): the standard's XYZ to linear RGB matrix.
LinearSrgb xyzToLinearSrgb(const Xyz& xyz);

Chromaticity chromaticity(const Xyz& xyz);

// N wavelengths over [firstNm, lastNm] for the midpoint rule: the centres
// of N equal bins, each weighted by its width in nm.
struct SpectralSample {
  double lambdaNm = 0.0;
  double weightNm = 0.0;
};
inline constexpr double kVisibleMinNm = 380.0;
inline constexpr double kVisibleMaxNm = 780.0;
std::vector<SpectralSample> spectralSamples(int count, double firstNm = kVisibleMinNm,
                                            double lastNm = kVisibleMaxNm);

// XYZ = sum_i S(lambda_i) cmf(lambda_i) w_i, for a spectrum given at the
// samples (spectrum.size() == samples.size()).
Xyz integrateSpectrum(std::span<const SpectralSample> samples, std::span<const double> spectrum);

}  // namespace snell::physics
