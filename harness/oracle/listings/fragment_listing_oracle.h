#pragma once
// The adapter from the reference renderer to a fragment part mirrored line
// by line: a struct with its GLSL globals as members (samplers as
// glsl::samplerCube or glsl::sampler2D, inputs and uniforms over double),
// `void main()`, and `template <class V> void visit(V&)` naming its
// samplers, uniforms, inputs and the colour output. Double only: the image
// gate has explicit thresholds.
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "oracle/glsl/texture.h"
#include "oracle/listings/interface_types.h"
#include "oracle/reference/fragment_oracle.h"

namespace snell::listings {

class DescribeFragmentInterface {
 public:
  void sampler(const char* name, glsl::samplerCube&) { samplers_.emplace_back(name); }
  void sampler(const char* name, glsl::sampler2D&) { samplers2D_.emplace_back(name); }
  template <class X>
  void uniform(const char* name, X&) {
    uniforms_.push_back(FragmentUniform{name, glslTypeOf<X>()});
  }
  template <class X>
  void input(const char* name, X&) {
    inputs_.push_back(FragmentInput{name, componentCount(glslTypeOf<X>())});
  }
  template <class X>
  void output(const char*, X&) {}

  const std::vector<FragmentInput>& inputs() const { return inputs_; }
  const std::vector<FragmentUniform>& uniforms() const { return uniforms_; }
  const std::vector<std::string>& samplers() const { return samplers_; }
  const std::vector<std::string>& samplers2D() const { return samplers2D_; }

 private:
  std::vector<FragmentInput> inputs_;
  std::vector<FragmentUniform> uniforms_;
  std::vector<std::string> samplers_;
  std::vector<std::string> samplers2D_;
};

// One fragment's inputs, uniforms and samplers. Expects checked bindings.
class BindFragment {
 public:
  BindFragment(std::span<const double> inputs, const FragmentBindings& bindings)
      : inputs_(inputs), bindings_(bindings) {}

  void sampler(const char* name, glsl::samplerCube& variable) {
    variable = glsl::samplerCube{bindings_.cubeMaps.at(name)};
  }
  void sampler(const char* name, glsl::sampler2D& variable) {
    variable = glsl::sampler2D{bindings_.textures2D.at(name)};
  }
  // The float the backends got, exactly: a uniform is set once, not computed.
  template <class X>
  void uniform(const char* name, X& variable) {
    const std::vector<float>& data = bindings_.uniforms.at(name).data;
    std::size_t next = 0;
    forEachComponent(variable, [&](double& component) { component = data[next++]; });
  }
  template <class X>
  void input(const char*, X& variable) {
    forEachComponent(variable, [&](double& component) { component = inputs_[next_++]; });
  }
  template <class X>
  void output(const char*, X&) {}

 private:
  std::span<const double> inputs_;
  const FragmentBindings& bindings_;
  std::size_t next_ = 0;
};

// The colour written and what the lookups ran into.
class ReadFragment {
 public:
  void sampler(const char*, glsl::samplerCube& variable) {
    result_.undefined = result_.undefined || variable.undefinedLookup;
    result_.faceEdge = result_.faceEdge || variable.faceEdgeLookup;
  }
  void sampler(const char*, glsl::sampler2D& variable) {
    result_.undefined = result_.undefined || variable.undefinedLookup;
  }
  template <class X>
  void uniform(const char*, X&) {}
  template <class X>
  void input(const char*, X&) {}
  void output(const char*, glsl::vec4<double>& fragColor) {
    for (int k = 0; k < 4; ++k) result_.color[k] = fragColor[k];
  }

  const FragmentResult& result() const { return result_; }

 private:
  FragmentResult result_;
};

template <class Shader>
class FragmentListingOracle final : public FragmentOracle {
 public:
  FragmentListingOracle() {
    Shader shader{};
    shader.visit(interface_);
  }

  std::vector<FragmentInput> inputs() const override { return interface_.inputs(); }
  std::vector<std::string> samplers() const override { return interface_.samplers(); }
  std::vector<std::string> samplers2D() const override { return interface_.samplers2D(); }
  std::vector<FragmentUniform> uniforms() const override { return interface_.uniforms(); }

  using FragmentOracle::shade;
  FragmentResult shade(std::span<const double> inputs,
                       const FragmentBindings& bindings) const override {
    Shader shader{};
    BindFragment bind(inputs, bindings);
    shader.visit(bind);
    shader.main();
    ReadFragment read;
    shader.visit(read);
    return read.result();
  }

 private:
  DescribeFragmentInterface interface_;
};

template <class Shader>
std::unique_ptr<FragmentOracle> makeFragmentListingOracle() {
  return std::make_unique<FragmentListingOracle<Shader>>();
}

}  // namespace snell::listings
