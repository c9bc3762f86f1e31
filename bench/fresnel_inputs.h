#pragma once
// The inputs Listing 14.1 binds, by its GLSL names, from the sphere scene:
// what the oracle benchmarks evaluate.
#include "core/scene.h"
#include "core/values.h"
#include "oracle/reference/reference_image.h"

namespace snell {

struct FresnelInputs {
  Scene scene = makeScene("sphere");
  UniformMap uniforms{{"MVMatrix", scene.values.at("modelview")},
                      {"MVPMatrix", scene.values.at("modelview_projection")},
                      {"NormalMatrix", scene.values.at("normal_matrix")},
                      {"TextureMatrix", scene.values.at("texture_matrix")}};
  AttributeMap attributes;
  ConstantMap constants{{"Eta", 0.66}, {"FresnelPower", 5.0}};
  FresnelInputs() {
    attributes["MCvertex"] = scene.attributes.at("position");
    attributes["MCnormal"] = scene.attributes.at("normal");
  }
  // The sphere's reference image input for the listing's parts: those
  // registered under `oracle`, or `vertex` and `fragment` when given.
  ReferenceInput referenceInput(const std::string& oracle, const VertexOracle* vertex = nullptr,
                                const FragmentOracle* fragment = nullptr) const {
    ReferenceInput input{oracle,
                         uniforms,
                         constants,
                         attributes,
                         scene.vertexCount,
                         scene.indices,
                         {{"Cubemap", scene.environment.get()}},
                         scene.width,
                         scene.height};
    input.vertex = vertex;
    input.fragment = fragment;
    return input;
  }
};

}  // namespace snell
