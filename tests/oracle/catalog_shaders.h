#pragma once
// Every catalog listing's shader template with its registry name, for tests
// that run the listings over their own number types (the adversarial
// machine, the high-precision check). `legacy`: the listing reads
// fixed-function state derived from the bound matrices
// (core/legacy_builtins.h).
#include "oracle/listings/blog_chromatic.h"
#include "oracle/listings/blog_diffraction.h"
#include "oracle/listings/blog_fresnel.h"
#include "oracle/listings/cg_refraction.h"
#include "oracle/listings/cg_refraction_builtin.h"
#include "oracle/listings/cg_refraction_decal.h"
#include "oracle/listings/cs381_chromatic_aberration.h"
#include "oracle/listings/cs381_glass.h"
#include "oracle/listings/cs381_refraction.h"
#include "oracle/listings/method_directions.h"
#include "oracle/listings/method_empirical.h"
#include "oracle/listings/method_per_fragment.h"
#include "oracle/listings/orange_book_chromatic.h"
#include "oracle/listings/orange_book_diffraction.h"
#include "oracle/listings/orange_book_fresnel.h"
#include "oracle/listings/shadertoy_bubble.h"
#include "oracle/listings/shadertoy_lens.h"
#include "oracle/listings/shadertoy_lens_fresnel.h"

namespace snell::test {

// Calls visit.template operator()<Shader>(name, legacy) for each listing.
template <class Visit>
void forEachCatalogShader(Visit&& visit) {
  using namespace listings;
  visit.template operator()<BlogFresnel>(kBlogFresnelName, true);
  visit.template operator()<BlogChromatic>(kBlogChromaticName, true);
  visit.template operator()<BlogDiffraction>(kBlogDiffractionName, true);
  visit.template operator()<OrangeBookFresnel>(kOrangeBookFresnelName, false);
  visit.template operator()<OrangeBookChromatic>(kOrangeBookChromaticName, false);
  visit.template operator()<OrangeBookDiffraction>(kOrangeBookDiffractionName, false);
  visit.template operator()<CgRefraction>(kCgRefractionName, false);
  visit.template operator()<CgRefractionBuiltin>(kCgRefractionBuiltinName, false);
  visit.template operator()<CgRefractionDecal>(kCgRefractionDecalName, false);
  visit.template operator()<Cs381Refraction>(kCs381RefractionName, false);
  visit.template operator()<Cs381ChromaticAberration>(kCs381ChromaticAberrationName, false);
  visit.template operator()<Cs381Glass>(kCs381GlassName, false);
  visit.template operator()<ShadertoyLens>(kShadertoyLensName, false);
  visit.template operator()<ShadertoyLensFresnel>(kShadertoyLensFresnelName, false);
  visit.template operator()<ShadertoyBubble>(kShadertoyBubbleName, false);
  visit.template operator()<MethodDirections>(kMethodDirectionsName, false);
  visit.template operator()<MethodEmpirical>(kMethodEmpiricalName, false);
  visit.template operator()<MethodPerFragment>(kMethodPerFragmentName, false);
}

}  // namespace snell::test
