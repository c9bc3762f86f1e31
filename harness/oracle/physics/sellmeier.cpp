#include "oracle/physics/sellmeier.h"

#include <fmt/format.h>

#include <cmath>

#include "core/errors.h"

namespace snell::physics {

const SellmeierGlass& nBk7() {
  // SCHOTT optical glass data sheet, N-BK7 (517642.251): B1..B3, C1..C3.
  // Its reference values: n_d = 1.51680, v_d = 64.17.
  static const SellmeierGlass glass{
      "N-BK7",
      "SCHOTT optical glass data sheet, N-BK7",
      {{1.03961212, 0.00600069867}, {0.231792344, 0.0200179144}, {1.01046945, 103.560653}},
      300.0,
      2500.0};
  return glass;
}

const SellmeierGlass& water20C() {
  // M. Daimon and A. Masumura, "Measurement of the refractive index of
  // distilled water from the near-infrared region to the ultraviolet
  // region", Applied Optics 46(18), 3811-3820 (2007): the four-term fit for
  // 20.0 degrees C, over their measured range 0.182 to 1.129 um.
  static const SellmeierGlass glass{"water",
                                    "Daimon & Masumura 2007, Appl. Opt. 46, 3811, 20.0 C fit",
                                    {{5.684027565e-1, 5.101829712e-3},
                                     {1.726177391e-1, 1.821153936e-2},
                                     {2.086189578e-2, 2.620722293e-2},
                                     {1.130748688e-1, 1.069792721e1}},
                                    182.0,
                                    1129.0};
  return glass;
}

const SellmeierGlass& findGlass(std::string_view name) {
  if (name == nBk7().name) return nBk7();
  if (name == water20C().name) return water20C();
  throw UsageError(fmt::format("unknown glass \"{}\": use \"N-BK7\" or \"water\"", name));
}

double refractiveIndex(const SellmeierGlass& glass, double lambdaNm) {
  if (!(lambdaNm >= glass.minNm && lambdaNm <= glass.maxNm))
    throw UsageError(fmt::format("lambda_nm = {} is outside the {} fit's range, {} to {} nm ({})",
                                 lambdaNm, glass.name, glass.minNm, glass.maxNm, glass.source));
  const double um = lambdaNm / 1000.0;
  const double l2 = um * um;
  double sum = 1.0;
  for (const SellmeierTerm& term : glass.terms) sum += term.b * l2 / (l2 - term.c);
  return std::sqrt(sum);
}

double abbeNumber(const SellmeierGlass& glass) {
  const double nd = refractiveIndex(glass, kHeliumDNm);
  return (nd - 1.0) / (refractiveIndex(glass, kHydrogenFNm) - refractiveIndex(glass, kHydrogenCNm));
}

}  // namespace snell::physics
