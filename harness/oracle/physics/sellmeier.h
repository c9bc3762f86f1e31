#pragma once
// Dispersion: the refractive index as a function of wavelength, from a
// Sellmeier fit n^2 - 1 = sum_k B_k lambda^2 / (lambda^2 - C_k), lambda in
// micrometres. A fit holds only over the wavelengths it was fitted to;
// outside them the index is refused, not extrapolated.
#include <string_view>
#include <vector>

namespace snell::physics {

struct SellmeierTerm {
  double b = 0.0;  // dimensionless
  double c = 0.0;  // square micrometres
};

struct SellmeierGlass {
  std::string_view name;
  std::string_view source;
  std::vector<SellmeierTerm> terms;
  double minNm = 0.0;  // the range the fit is valid over
  double maxNm = 0.0;
};

// Schott's N-BK7 (optical glass data sheet), valid 300 to 2500 nm.
const SellmeierGlass& nBk7();
// Distilled water at 20 degrees C (Daimon & Masumura 2007), 182 to 1129 nm.
const SellmeierGlass& water20C();

// By name, "N-BK7" or "water"; an unknown name throws UsageError naming both.
const SellmeierGlass& findGlass(std::string_view name);

// Throws UsageError for a wavelength outside the glass's range.
double refractiveIndex(const SellmeierGlass& glass, double lambdaNm);

// The Fraunhofer lines that define the Abbe number (ISO 7944): helium d,
// hydrogen F and C, in nm.
inline constexpr double kHeliumDNm = 587.5618;
inline constexpr double kHydrogenFNm = 486.1327;
inline constexpr double kHydrogenCNm = 656.2725;

// V_d = (n_d - 1) / (n_F - n_C).
double abbeNumber(const SellmeierGlass& glass);

}  // namespace snell::physics
