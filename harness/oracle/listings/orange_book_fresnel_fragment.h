#pragma once
// Listing 14.2 of the OpenGL Shading Language ("Orange Book"): the fragment
// shader for the Fresnel reflection/refraction effect, line by line, in
// double. The listing as published is
// shaders/orange-book/14.1-fresnel/fresnel.frag.
#include <memory>

#include "oracle/glsl/glsl.h"
#include "oracle/glsl/texture.h"
#include "oracle/reference/fragment_oracle.h"

namespace snell::listings {

struct OrangeBookFresnelFragment {
  using vec3 = glsl::vec3<double>;
  using vec4 = glsl::vec4<double>;

  // uniform samplerCube Cubemap;
  glsl::samplerCube Cubemap;

  // in vec3  Reflect;
  // in vec3  Refract;
  // in float Ratio;
  vec3 Reflect;
  vec3 Refract;
  double Ratio = 0;

  // out vec4 FragColor;
  vec4 FragColor;

  void main() {
    vec3 refractColor = vec3(texture(Cubemap, Refract));
    vec3 reflectColor = vec3(texture(Cubemap, Reflect));

    vec3 color = mix(refractColor, reflectColor, Ratio);

    FragColor = vec4(color, 1.0);
  }

  template <class Visitor>
  void visit(Visitor& v) {
    v.sampler("Cubemap", Cubemap);
    v.input("Reflect", Reflect);
    v.input("Refract", Refract);
    v.input("Ratio", Ratio);
    v.output("FragColor", FragColor);
  }
};

std::unique_ptr<FragmentOracle> makeOrangeBookFresnelFragmentOracle();

}  // namespace snell::listings
