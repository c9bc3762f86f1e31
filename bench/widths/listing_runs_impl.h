#pragma once
// The table behind runListing, instantiated once per number type
// (listing_runs_*.cpp) to keep each translation unit small.
#include <map>
#include <stdexcept>

#include "core/legacy_builtins.h"
#include "oracle/listings/blog_chromatic.h"
#include "oracle/listings/blog_diffraction.h"
#include "oracle/listings/blog_fresnel.h"
#include "oracle/listings/cg_refraction.h"
#include "oracle/listings/cg_refraction_builtin.h"
#include "oracle/listings/cg_refraction_decal.h"
#include "oracle/listings/cs381_chromatic_aberration.h"
#include "oracle/listings/cs381_glass.h"
#include "oracle/listings/cs381_refraction.h"
#include "oracle/listings/interface_visitors.h"
#include "oracle/listings/method_directions.h"
#include "oracle/listings/method_empirical.h"
#include "oracle/listings/method_per_fragment.h"
#include "oracle/listings/orange_book_chromatic.h"
#include "oracle/listings/orange_book_diffraction.h"
#include "oracle/listings/orange_book_fresnel.h"
#include "oracle/listings/shadertoy_bubble.h"
#include "oracle/listings/shadertoy_lens.h"
#include "oracle/listings/shadertoy_lens_fresnel.h"
#include "widths/listing_runs.h"
#include "widths/number_types.h"

namespace snell::widths {
namespace listing_runs_detail {

template <template <class> class Shader, class T>
std::vector<T> runOnce(const ListingBindings& bindings, std::size_t vertex) {
  // Legacy listings read GL's derived state; it is added only where its
  // sources are bound, so every listing gets the same call.
  const UniformMap uniforms = withDerivedLegacyState(bindings.uniforms);
  Shader<T> shader{};
  listings::BindUniforms<T> bindUniforms(uniforms, bindings.constants);
  shader.visit(bindUniforms);
  listings::BindVertex<T> bindVertex(bindings.attributes, vertex);
  shader.visit(bindVertex);
  shader.main();
  listings::CollectOutputs<T> collect;
  shader.visit(collect);
  return collect.values;
}

class DescribeInputs {
 public:
  template <class X>
  void input(const char* name, X& variable) {
    int components = 0;
    listings::forEachComponent(variable, [&](double&) { ++components; });
    inputs.push_back(ListingInput{name, components});
  }
  template <class X>
  void uniform(const char*, X&) {}
  void constant(const char*, double&) {}
  template <class X>
  void output(const char*, X&) {}
  std::vector<ListingInput> inputs;
};

// Each input's name and component count, in visit order.
template <template <class> class Shader>
std::vector<ListingInput> inputsOf() {
  DescribeInputs describe;
  Shader<double> shader{};
  shader.visit(describe);
  return describe.inputs;
}

template <class T>
struct Runner {
  std::vector<T> (*run)(const ListingBindings&, std::size_t);
  std::vector<ListingInput> (*inputs)();
};

template <class T>
const std::map<std::string, Runner<T>>& runners() {
  using namespace listings;
  static const std::map<std::string, Runner<T>> table = {
      {kBlogFresnelName, {&runOnce<BlogFresnel, T>, &inputsOf<BlogFresnel>}},
      {kBlogChromaticName, {&runOnce<BlogChromatic, T>, &inputsOf<BlogChromatic>}},
      {kBlogDiffractionName, {&runOnce<BlogDiffraction, T>, &inputsOf<BlogDiffraction>}},
      {kOrangeBookFresnelName, {&runOnce<OrangeBookFresnel, T>, &inputsOf<OrangeBookFresnel>}},
      {kOrangeBookChromaticName,
       {&runOnce<OrangeBookChromatic, T>, &inputsOf<OrangeBookChromatic>}},
      {kOrangeBookDiffractionName,
       {&runOnce<OrangeBookDiffraction, T>, &inputsOf<OrangeBookDiffraction>}},
      {kCgRefractionName, {&runOnce<CgRefraction, T>, &inputsOf<CgRefraction>}},
      {kCgRefractionBuiltinName,
       {&runOnce<CgRefractionBuiltin, T>, &inputsOf<CgRefractionBuiltin>}},
      {kCgRefractionDecalName, {&runOnce<CgRefractionDecal, T>, &inputsOf<CgRefractionDecal>}},
      {kCs381RefractionName, {&runOnce<Cs381Refraction, T>, &inputsOf<Cs381Refraction>}},
      {kCs381ChromaticAberrationName,
       {&runOnce<Cs381ChromaticAberration, T>, &inputsOf<Cs381ChromaticAberration>}},
      {kCs381GlassName, {&runOnce<Cs381Glass, T>, &inputsOf<Cs381Glass>}},
      {kShadertoyLensName, {&runOnce<ShadertoyLens, T>, &inputsOf<ShadertoyLens>}},
      {kShadertoyLensFresnelName,
       {&runOnce<ShadertoyLensFresnel, T>, &inputsOf<ShadertoyLensFresnel>}},
      {kShadertoyBubbleName, {&runOnce<ShadertoyBubble, T>, &inputsOf<ShadertoyBubble>}},
      {kMethodDirectionsName, {&runOnce<MethodDirections, T>, &inputsOf<MethodDirections>}},
      {kMethodEmpiricalName, {&runOnce<MethodEmpirical, T>, &inputsOf<MethodEmpirical>}},
      {kMethodPerFragmentName, {&runOnce<MethodPerFragment, T>, &inputsOf<MethodPerFragment>}},
  };
  return table;
}

}  // namespace listing_runs_detail

template <class T>
std::vector<T> runListing(const std::string& oracle, const ListingBindings& bindings,
                          std::size_t vertex) {
  return listing_runs_detail::runners<T>().at(oracle).run(bindings, vertex);
}

}  // namespace snell::widths
