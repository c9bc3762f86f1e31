#pragma once
// Listing 14.4 of the OpenGL Shading Language ("Orange Book"): the fragment
// shader for the chromatic aberration effect, line by line, in double. The
// listing as published is shaders/orange-book/14.3-chromatic/chromatic.frag.
#include <memory>

#include "oracle/glsl/glsl.h"
#include "oracle/glsl/texture.h"
#include "oracle/reference/fragment_oracle.h"

namespace snell::listings {

struct OrangeBookChromaticFragment {
  using vec3 = glsl::vec3<double>;
  using vec4 = glsl::vec4<double>;

  // uniform samplerCube Cubemap;
  glsl::samplerCube Cubemap;

  // in vec3  Reflect;
  // in vec3  RefractR;
  // in vec3  RefractG;
  // in vec3  RefractB;
  // in float Ratio;
  vec3 Reflect;
  vec3 RefractR;
  vec3 RefractG;
  vec3 RefractB;
  double Ratio = 0;

  // out vec4 FragColor;
  vec4 FragColor;

  void main() {
    vec3 refractColor, reflectColor;

    refractColor.r() = vec3(texture(Cubemap, RefractR)).r();
    refractColor.g() = vec3(texture(Cubemap, RefractG)).g();
    refractColor.b() = vec3(texture(Cubemap, RefractB)).b();

    reflectColor = vec3(texture(Cubemap, Reflect));

    vec3 color = mix(refractColor, reflectColor, Ratio);

    FragColor = vec4(color, 1.0);
  }

  template <class Visitor>
  void visit(Visitor& v) {
    v.sampler("Cubemap", Cubemap);
    v.input("Reflect", Reflect);
    v.input("RefractR", RefractR);
    v.input("RefractG", RefractG);
    v.input("RefractB", RefractB);
    v.input("Ratio", Ratio);
    v.output("FragColor", FragColor);
  }
};

std::unique_ptr<FragmentOracle> makeOrangeBookChromaticFragmentOracle();

}  // namespace snell::listings
