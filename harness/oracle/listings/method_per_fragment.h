#pragma once
// The method ladders' per-fragment vertex stage, line by line over the
// number type T: the eye-space position and normal that the per-fragment
// rungs pass on. The listing is
// shaders/methods/fresnel/4-schlick-fragment/per_fragment.vert (Fresnel
// rungs 5 and 6, and every dispersion and refraction rung, have the same
// code).
#include <memory>

#include "oracle/glsl/glsl.h"
#include "oracle/vertex_oracle.h"

namespace snell::listings {

template <class T>
struct MethodPerFragment {
  // in vec4 MCvertex;
  // in vec3 MCnormal;
  glsl::vec4<T> MCvertex;
  glsl::vec3<T> MCnormal;

  // uniform mat4 MVMatrix;
  // uniform mat4 MVPMatrix;
  // uniform mat3 NormalMatrix;
  glsl::mat4<T> MVMatrix;
  glsl::mat4<T> MVPMatrix;
  glsl::mat3<T> NormalMatrix;

  // out vec3 EyePosition;
  // out vec3 EyeNormal;
  glsl::vec3<T> EyePosition;
  glsl::vec3<T> EyeNormal;
  glsl::vec4<T> gl_Position;

  void main() {
    using namespace glsl;
    vec4<T> ecPosition = MVMatrix * MCvertex;
    EyePosition = ecPosition.xyz() / ecPosition.w();
    EyeNormal = normalize(NormalMatrix * MCnormal);

    gl_Position = MVPMatrix * MCvertex;
  }

  template <class Visitor>
  void visit(Visitor& v) {
    v.input("MCvertex", MCvertex);
    v.input("MCnormal", MCnormal);
    v.uniform("MVMatrix", MVMatrix);
    v.uniform("MVPMatrix", MVPMatrix);
    v.uniform("NormalMatrix", NormalMatrix);
    v.output("EyePosition", EyePosition);
    v.output("EyeNormal", EyeNormal);
    v.output("gl_Position", gl_Position);
  }
};

extern template struct MethodPerFragment<double>;
extern template struct MethodPerFragment<float>;
extern template struct MethodPerFragment<Interval>;

inline constexpr const char* kMethodPerFragmentName = "snell_method_per_fragment";
std::unique_ptr<VertexOracle> makeMethodPerFragmentOracle();

}  // namespace snell::listings
