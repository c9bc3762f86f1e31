#pragma once
// Listing 14.1 of the OpenGL Shading Language ("Orange Book"): the vertex
// shader for the Fresnel reflection/refraction effect, line by line, over
// the number type T. The listing as published is
// shaders/orange-book/14.1-fresnel/fresnel.vert.
#include <memory>

#include "oracle/glsl/glsl.h"
#include "oracle/vertex_oracle.h"

namespace snell::listings {

template <class T>
struct OrangeBookFresnel {
  // in vec4 MCvertex;
  // in vec3 MCnormal;
  glsl::vec4<T> MCvertex;
  glsl::vec3<T> MCnormal;

  // uniform mat4 MVMatrix;
  // uniform mat4 MVPMatrix;
  // uniform mat3 NormalMatrix;
  // uniform mat4 TextureMatrix;
  glsl::mat4<T> MVMatrix;
  glsl::mat4<T> MVPMatrix;
  glsl::mat3<T> NormalMatrix;
  glsl::mat4<T> TextureMatrix;

  // const float Eta = 0.66; // Ratio of indices of refraction
  // const float FresnelPower = 5.0;
  // (the values come from the manifest's `constants`)
  T Eta;
  T FresnelPower;

  // out vec3  Reflect;
  // out vec3  Refract;
  // out float Ratio;
  glsl::vec3<T> Reflect;
  glsl::vec3<T> Refract;
  T Ratio;
  glsl::vec4<T> gl_Position;

  void main() {
    using namespace glsl;
    const T one = lit<T>(1.0);

    // const float F = ((1.0-Eta) * (1.0-Eta)) / ((1.0+Eta) * (1.0+Eta));
    const T F = ((one - Eta) * (one - Eta)) / ((one + Eta) * (one + Eta));

    vec4<T> ecPosition = MVMatrix * MCvertex;
    vec3<T> ecPosition3 = ecPosition.xyz() / ecPosition.w();

    vec3<T> i = normalize(ecPosition3);
    vec3<T> n = normalize(NormalMatrix * MCnormal);

    Ratio = F + (one - F) * pow((one - dot(-i, n)), FresnelPower);

    Refract = refract(i, n, Eta);
    Refract = vec3<T>(TextureMatrix * vec4<T>(Refract, one));

    Reflect = reflect(i, n);
    Reflect = vec3<T>(TextureMatrix * vec4<T>(Reflect, one));

    gl_Position = MVPMatrix * MCvertex;
  }

  // The interface by GLSL name. gl_Position is an output for the reference
  // renderer; a manifest captures only the listing's own `out` variables.
  template <class Visitor>
  void visit(Visitor& v) {
    v.input("MCvertex", MCvertex);
    v.input("MCnormal", MCnormal);
    v.uniform("MVMatrix", MVMatrix);
    v.uniform("MVPMatrix", MVPMatrix);
    v.uniform("NormalMatrix", NormalMatrix);
    v.uniform("TextureMatrix", TextureMatrix);
    v.constant("Eta", Eta);
    v.constant("FresnelPower", FresnelPower);
    v.output("Reflect", Reflect);
    v.output("Refract", Refract);
    v.output("Ratio", Ratio);
    v.output("gl_Position", gl_Position);
  }
};

extern template struct OrangeBookFresnel<double>;
extern template struct OrangeBookFresnel<float>;
extern template struct OrangeBookFresnel<Interval>;

inline constexpr const char* kOrangeBookFresnelName = "orange_book_fresnel";
std::unique_ptr<VertexOracle> makeOrangeBookFresnelOracle();

}  // namespace snell::listings
