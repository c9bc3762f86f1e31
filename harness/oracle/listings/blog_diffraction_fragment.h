#pragma once
// The fragment shader of the blog's diffraction listing
// (shaders/blog/diffraction/diffraction.frag, as published), line by line,
// in double.
#include <memory>

#include "oracle/glsl/glsl.h"
#include "oracle/reference/fragment_oracle.h"

namespace snell::listings {

struct BlogDiffractionFragment {
  using vec4 = glsl::vec4<double>;

  // varying vec4 Color;
  vec4 Color;

  // (the legacy output)
  vec4 gl_FragColor;

  // void main(void)
  // {
  // gl_FragColor =Color ;
  // }
  void main() { gl_FragColor = Color; }

  template <class Visitor>
  void visit(Visitor& v) {
    v.input("Color", Color);
    v.output("gl_FragColor", gl_FragColor);
  }
};

std::unique_ptr<FragmentOracle> makeBlogDiffractionFragmentOracle();

}  // namespace snell::listings
