// The listing oracles by the name a manifest's `oracle` field gives. A new
// listing adds its file under listings/ and one line here (two when it
// draws: its fragment part goes under the same name).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>

#include "core/errors.h"
#include "oracle/listings/blog_chromatic.h"
#include "oracle/listings/blog_diffraction.h"
#include "oracle/listings/blog_diffraction_fragment.h"
#include "oracle/listings/blog_fresnel.h"
#include "oracle/listings/cg_refraction.h"
#include "oracle/listings/cg_refraction_builtin.h"
#include "oracle/listings/cg_refraction_decal.h"
#include "oracle/listings/cg_refraction_fragment.h"
#include "oracle/listings/cs381_chromatic_aberration.h"
#include "oracle/listings/cs381_glass.h"
#include "oracle/listings/cs381_refraction.h"
#include "oracle/listings/method_directions.h"
#include "oracle/listings/method_empirical.h"
#include "oracle/listings/method_per_fragment.h"
#include "oracle/listings/orange_book_chromatic.h"
#include "oracle/listings/orange_book_chromatic_fragment.h"
#include "oracle/listings/orange_book_diffraction.h"
#include "oracle/listings/orange_book_diffraction_fragment.h"
#include "oracle/listings/orange_book_fresnel.h"
#include "oracle/listings/orange_book_fresnel_fragment.h"
#include "oracle/listings/shadertoy_bubble.h"
#include "oracle/listings/shadertoy_lens.h"
#include "oracle/listings/shadertoy_lens_fresnel.h"
#include "oracle/reference/fragment_oracle.h"
#include "oracle/reference/reference_image.h"
#include "oracle/vertex_oracle.h"

namespace snell {
namespace {

struct RegisteredOracle {
  const char* name;
  std::unique_ptr<VertexOracle> (*make)();
};

constexpr std::array kOracles = {
    RegisteredOracle{listings::kBlogFresnelName, &listings::makeBlogFresnelOracle},
    RegisteredOracle{listings::kBlogChromaticName, &listings::makeBlogChromaticOracle},
    RegisteredOracle{listings::kBlogDiffractionName, &listings::makeBlogDiffractionOracle},
    RegisteredOracle{listings::kOrangeBookFresnelName, &listings::makeOrangeBookFresnelOracle},
    RegisteredOracle{listings::kOrangeBookChromaticName, &listings::makeOrangeBookChromaticOracle},
    RegisteredOracle{listings::kCgRefractionName, &listings::makeCgRefractionOracle},
    RegisteredOracle{listings::kCgRefractionBuiltinName, &listings::makeCgRefractionBuiltinOracle},
    RegisteredOracle{listings::kCgRefractionDecalName, &listings::makeCgRefractionDecalOracle},
    RegisteredOracle{listings::kCs381RefractionName, &listings::makeCs381RefractionOracle},
    RegisteredOracle{listings::kCs381ChromaticAberrationName,
                     &listings::makeCs381ChromaticAberrationOracle},
    RegisteredOracle{listings::kCs381GlassName, &listings::makeCs381GlassOracle},
    RegisteredOracle{listings::kOrangeBookDiffractionName,
                     &listings::makeOrangeBookDiffractionOracle},
    RegisteredOracle{listings::kShadertoyLensName, &listings::makeShadertoyLensOracle},
    RegisteredOracle{listings::kShadertoyLensFresnelName,
                     &listings::makeShadertoyLensFresnelOracle},
    RegisteredOracle{listings::kShadertoyBubbleName, &listings::makeShadertoyBubbleOracle},
    RegisteredOracle{listings::kMethodDirectionsName, &listings::makeMethodDirectionsOracle},
    RegisteredOracle{listings::kMethodEmpiricalName, &listings::makeMethodEmpiricalOracle},
    RegisteredOracle{listings::kMethodPerFragmentName, &listings::makeMethodPerFragmentOracle},
};

struct RegisteredFragmentOracle {
  const char* name;
  std::unique_ptr<FragmentOracle> (*make)();
};

constexpr std::array kFragmentOracles = {
    RegisteredFragmentOracle{listings::kBlogDiffractionName,
                             &listings::makeBlogDiffractionFragmentOracle},
    RegisteredFragmentOracle{listings::kOrangeBookFresnelName,
                             &listings::makeOrangeBookFresnelFragmentOracle},
    RegisteredFragmentOracle{listings::kOrangeBookChromaticName,
                             &listings::makeOrangeBookChromaticFragmentOracle},
    RegisteredFragmentOracle{listings::kOrangeBookDiffractionName,
                             &listings::makeOrangeBookDiffractionFragmentOracle},
    RegisteredFragmentOracle{listings::kCgRefractionDecalName,
                             &listings::makeCgRefractionFragmentOracle},
};

}  // namespace

std::vector<std::string> vertexOracleNames() {
  std::vector<std::string> names;
  for (const RegisteredOracle& oracle : kOracles) names.emplace_back(oracle.name);
  std::sort(names.begin(), names.end());
  return names;
}

std::unique_ptr<VertexOracle> makeVertexOracle(const std::string& name) {
  for (const RegisteredOracle& oracle : kOracles) {
    if (name == oracle.name) return oracle.make();
  }
  throw UsageError(fmt::format("unknown oracle '{}'; known oracles: {}", name,
                               fmt::join(vertexOracleNames(), ", ")));
}

bool hasFragmentOracle(const std::string& name) {
  return std::any_of(kFragmentOracles.begin(), kFragmentOracles.end(),
                     [&](const RegisteredFragmentOracle& oracle) { return name == oracle.name; });
}

std::unique_ptr<FragmentOracle> makeFragmentOracle(const std::string& name) {
  for (const RegisteredFragmentOracle& oracle : kFragmentOracles) {
    if (name == oracle.name) return oracle.make();
  }
  throw UsageError(fmt::format("oracle '{}' has no fragment part: it does not draw", name));
}

}  // namespace snell
