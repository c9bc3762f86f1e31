#include "oracle/physics/cie1931.h"

#include <fmt/format.h>

#include <cmath>

#include "core/errors.h"

namespace snell::physics {
namespace {

// A Gaussian lobe with different widths below and above its peak.
struct Lobe {
  double weight;
  double peakNm;
  double sigmaBelowNm;
  double sigmaAboveNm;

  double at(double lambdaNm) const {
    const double t = (lambdaNm - peakNm) / (lambdaNm < peakNm ? sigmaBelowNm : sigmaAboveNm);
    return weight * std::exp(-0.5 * t * t);
  }
};

// Wyman, Sloan & Shirley 2013, equation 4 (means and widths in nm). The
// paper gives the fit's error as smaller than the spread between the
// colour-matching data sets the CIE standard aggregates; against the CIE
// 1931 5 nm table (380 to 780 nm) the largest differences are 0.024 in
// z-bar (425 nm, on its steep flank), 0.015 in x-bar (630 nm) and 0.007 in
// y-bar (620 nm), and each function's integral is within 0.1% of the
// table's (tests/oracle/physics/cie1931_test.cpp holds it to those).
constexpr Lobe kX[] = {
    {1.056, 599.8, 37.9, 31.0}, {0.362, 442.0, 16.0, 26.7}, {-0.065, 501.1, 20.4, 26.2}};
constexpr Lobe kY[] = {{0.821, 568.8, 46.9, 40.5}, {0.286, 530.9, 16.3, 31.1}};
constexpr Lobe kZ[] = {{1.217, 437.0, 11.8, 36.0}, {0.681, 459.0, 26.0, 13.8}};

template <std::size_t N>
double sum(const Lobe (&lobes)[N], double lambdaNm) {
  double s = 0.0;
  for (const Lobe& lobe : lobes) s += lobe.at(lambdaNm);
  return s;
}

// IEC 61966-2-1:1999, XYZ (D65, Y = 1 white) to linear sRGB, rows R, G, B.
constexpr double kXyzToSrgb[3][3] = {
    {3.2406, -1.5372, -0.4986}, {-0.9689, 1.8758, 0.0415}, {0.0557, -0.2040, 1.0570}};

}  // namespace

Xyz cie1931ColourMatching(double lambdaNm) {
  if (!(lambdaNm >= kCieMinNm && lambdaNm <= kCieMaxNm))
    throw UsageError(fmt::format(
        "wavelength {} nm is outside the CIE 1931 colour matching functions' {} to {} nm", lambdaNm,
        kCieMinNm, kCieMaxNm));
  return {sum(kX, lambdaNm), sum(kY, lambdaNm), sum(kZ, lambdaNm)};
}

LinearSrgb xyzToLinearSrgb(const Xyz& c) {
  const auto row = [&](const double(&m)[3]) { return m[0] * c.x + m[1] * c.y + m[2] * c.z; };
  return {row(kXyzToSrgb[0]), row(kXyzToSrgb[1]), row(kXyzToSrgb[2])};
}

Chromaticity chromaticity(const Xyz& c) {
  const double total = c.x + c.y + c.z;
  return {c.x / total, c.y / total};
}

std::vector<SpectralSample> spectralSamples(int count, double firstNm, double lastNm) {
  if (count < 1)
    throw UsageError(fmt::format("a spectrum needs 1 or more wavelengths, not {}", count));
  if (!(firstNm >= kCieMinNm && lastNm <= kCieMaxNm && firstNm < lastNm))
    throw UsageError(
        fmt::format("spectral range {} to {} nm must be increasing and within {} to {} nm", firstNm,
                    lastNm, kCieMinNm, kCieMaxNm));
  const double width = (lastNm - firstNm) / count;
  std::vector<SpectralSample> samples;
  samples.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) samples.push_back({firstNm + (i + 0.5) * width, width});
  return samples;
}

Xyz integrateSpectrum(std::span<const SpectralSample> samples, std::span<const double> spectrum) {
  if (samples.size() != spectrum.size())
    throw UsageError(
        fmt::format("{} spectral values for {} wavelengths", spectrum.size(), samples.size()));
  Xyz total;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const Xyz cmf = cie1931ColourMatching(samples[i].lambdaNm);
    const double w = spectrum[i] * samples[i].weightNm;
    total.x += cmf.x * w;
    total.y += cmf.y * w;
    total.z += cmf.z * w;
  }
  return total;
}

}  // namespace snell::physics
