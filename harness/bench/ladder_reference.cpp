#include "bench/ladder_reference.h"

#include <fmt/format.h>

#include <cmath>

#include "bench/dispersion_reference_image.h"
#include "bench/sphere_trace_image.h"
#include "core/errors.h"

namespace snell::bench {
namespace {

bool namesSpectrum(const Manifest& m) {
  return m.constants.count("B1") || m.constants.count("EtaR") || m.constants.count("Wavelengths");
}

double etaOf(const Manifest& m) {
  const auto eta = m.constants.find("Eta");
  if (eta == m.constants.end())
    throw UsageError(
        fmt::format("{}:1: a method needs `constants = {{ Eta = ... }}` (n1/n2 from "
                    "air into the glass) for the physics reference",
                    m.path.string()));
  return eta->second;
}

bool sameTerms(const Manifest& m, const physics::SellmeierGlass& glass) {
  for (std::size_t k = 0; k < 4; ++k) {
    const physics::SellmeierTerm term =
        k < glass.terms.size() ? glass.terms[k] : physics::SellmeierTerm{};
    const auto b = m.constants.find(fmt::format("B{}", k + 1));
    const auto c = m.constants.find(fmt::format("C{}", k + 1));
    const double bValue = b == m.constants.end() ? 0.0 : b->second;
    const double cValue = c == m.constants.end() ? 0.0 : c->second;
    // The manifest writes the data sheet's digits: they match to rounding.
    if (std::abs(bValue - term.b) > 1e-9 * std::abs(term.b) + 1e-15 ||
        std::abs(cValue - term.c) > 1e-9 * std::abs(term.c) + 1e-15)
      return false;
  }
  return true;
}

}  // namespace

const physics::SellmeierGlass* manifestGlass(const Manifest& m) {
  if (!m.constants.count("B1")) return nullptr;
  for (const physics::SellmeierGlass* glass : {&physics::nBk7(), &physics::water20C()})
    if (sameTerms(m, *glass)) return glass;
  throw UsageError(
      fmt::format("{}:1: the Sellmeier terms B1..B4, C1..C4 in `constants` are neither "
                  "N-BK7's (SCHOTT) nor water's (Daimon & Masumura 2007); the physics reference "
                  "knows only those: copy one's terms",
                  m.path.string()));
}

namespace {

bool namesAnySpectrum(const std::vector<Manifest>& methods) {
  for (const Manifest& m : methods)
    if (namesSpectrum(m)) return true;
  return false;
}

// A method's Eta, which must be n1/n2 into glass.
double checkedEta(const Manifest& m) {
  const double eta = etaOf(m);
  if (!(eta > 0.0 && eta < 1.0))
    throw UsageError(fmt::format("{}:1: Eta {} is not n1/n2 from air into glass (0 < Eta < 1)",
                                 m.path.string(), eta));
  return eta;
}

// The one glass a dispersion ladder names.
const physics::SellmeierGlass& ladderGlass(const std::vector<Manifest>& methods) {
  const physics::SellmeierGlass* glass = nullptr;
  const Manifest* namer = nullptr;
  for (const Manifest& m : methods) {
    const physics::SellmeierGlass* own = manifestGlass(m);
    if (!own) continue;
    if (glass && own != glass)
      throw UsageError(fmt::format(
          "{}:1: names the glass {}, but {} names {}; a ladder is measured against one glass",
          m.path.string(), own->name, namer->path.string(), glass->name));
    glass = own;
    namer = &m;
  }
  if (!glass)
    throw UsageError(fmt::format(
        "{}: a dispersion ladder needs a method that names its glass (Sellmeier terms B1..B4, "
        "C1..C4 in `constants`); --methods takes a ladder of methods of one effect, as "
        "shaders/methods/fresnel, dispersion and refraction are",
        methods.front().path.parent_path().parent_path().string()));
  return *glass;
}

}  // namespace

void LadderReference::check(const std::vector<Manifest>& methods) {
  if (namesAnySpectrum(methods)) {
    (void)ladderGlass(methods);
    return;
  }
  for (const Manifest& m : methods) (void)checkedEta(m);
}

LadderReference::LadderReference(const std::vector<Manifest>& methods, const Scene& scene, int size,
                                 int wavelengths) {
  dispersion_ = namesAnySpectrum(methods);
  for (const Manifest& m : methods)
    refraction_ = refraction_ || m.constants.count("InternalHits") > 0;
  if (!dispersion_) {
    model_ = refraction_ ? fmt::format("{} hits from inside: {}", kReferenceInternalHits,
                                       kSphereTraceReferenceModel)
                         : std::string(kFresnelReferenceModel);
    for (const Manifest& m : methods) {
      const double eta = checkedEta(m);
      if (images_.count(eta)) continue;
      images_.emplace(eta, refraction_
                               ? sphereTraceImage(scene, 1.0 / eta, kReferenceInternalHits, size)
                               : fresnelReferenceImage(scene, eta, size, size));
    }
    return;
  }
  const physics::SellmeierGlass& glass = ladderGlass(methods);
  model_ =
      fmt::format("{}, {} wavelengths: {}", glass.name, wavelengths, kDispersionReferenceModel);
  images_.emplace(0.0, dispersionReferenceImage(scene, glass, wavelengths, size, size));
}

const ReferenceImage& LadderReference::imageFor(const Manifest& method) const {
  return dispersion_ ? images_.begin()->second : images_.at(etaOf(method));
}

}  // namespace snell::bench
