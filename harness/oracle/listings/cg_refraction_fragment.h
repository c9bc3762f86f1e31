#pragma once
// The Cg Tutorial's fragment program C7E4f_refraction (Example 7-4), line
// by line, in double: the decal colour mixed with the refracted
// environment colour. The GLSL port is
// shaders/cg-tutorial/c7e4f-refraction/c7e4f_refraction.frag; its vertex
// part is cg_refraction_decal.h, registered under the same name.
#include <memory>

#include "oracle/glsl/glsl.h"
#include "oracle/glsl/texture.h"
#include "oracle/reference/fragment_oracle.h"

namespace snell::listings {

struct CgRefractionFragment {
  using vec2 = glsl::vec2<double>;
  using vec3 = glsl::vec3<double>;
  using vec4 = glsl::vec4<double>;

  // in vec2 oTexCoord;
  // in vec3 T;
  vec2 oTexCoord;
  vec3 T;

  // out vec4 color;
  vec4 color;

  // uniform float transmittance;
  // uniform sampler2D decalMap;
  // uniform samplerCube environmentMap;
  double transmittance = 0;
  glsl::sampler2D decalMap;
  glsl::samplerCube environmentMap;

  void main() {
    // Fetch the decal base color
    vec4 decalColor = texture(decalMap, oTexCoord);

    // Fetch refracted environment color
    vec4 refractedColor = texture(environmentMap, T);

    // Compute the final color
    color = mix(decalColor, refractedColor, transmittance);
  }

  template <class Visitor>
  void visit(Visitor& v) {
    v.input("oTexCoord", oTexCoord);
    v.input("T", T);
    v.uniform("transmittance", transmittance);
    v.sampler("decalMap", decalMap);
    v.sampler("environmentMap", environmentMap);
    v.output("color", color);
  }
};

std::unique_ptr<FragmentOracle> makeCgRefractionFragmentOracle();

}  // namespace snell::listings
