#pragma once
// Section 14.2 of the OpenGL Shading Language ("Orange Book"): the fragment
// shader of the diffraction effect, line by line, in double. The listing is
// shaders/orange-book/14.2-diffraction/diffraction.frag.
#include <memory>

#include "oracle/glsl/glsl.h"
#include "oracle/reference/fragment_oracle.h"

namespace snell::listings {

struct OrangeBookDiffractionFragment {
  using vec4 = glsl::vec4<double>;

  // in vec4 Color;
  vec4 Color;

  // out vec4 FragColor;
  vec4 FragColor;

  void main() { FragColor = Color; }

  template <class Visitor>
  void visit(Visitor& v) {
    v.input("Color", Color);
    v.output("FragColor", FragColor);
  }
};

std::unique_ptr<FragmentOracle> makeOrangeBookDiffractionFragmentOracle();

}  // namespace snell::listings
