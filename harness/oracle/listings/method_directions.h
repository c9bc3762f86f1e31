#pragma once
// The Fresnel method ladder's vertex stage, line by line over the number
// type T: the reflected and refracted directions per vertex (rung 1, a constant mix). The
// listing is shaders/methods/fresnel/1-constant-mix/directions.vert.
#include <memory>

#include "oracle/glsl/glsl.h"
#include "oracle/vertex_oracle.h"

namespace snell::listings {

template <class T>
struct MethodDirections {
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
  // uniform mat4 TextureMatrix;
  glsl::mat4<T> TextureMatrix;

  // const float Eta = 0.6666667;
  // (the values come from the manifest's `constants`)
  T Eta;

  // out vec3 Reflect;
  // out vec3 Refract;
  glsl::vec3<T> Reflect;
  glsl::vec3<T> Refract;
  glsl::vec4<T> gl_Position;

  void main() {
    using namespace glsl;
    const T one = lit<T>(1.0);

    vec4<T> ecPosition = MVMatrix * MCvertex;
    vec3<T> ecPosition3 = ecPosition.xyz() / ecPosition.w();

    vec3<T> i = normalize(ecPosition3);
    vec3<T> n = normalize(NormalMatrix * MCnormal);

    Refract = refract(i, n, Eta);
    Refract = vec3<T>(TextureMatrix * vec4<T>(Refract, one));

    Reflect = reflect(i, n);
    Reflect = vec3<T>(TextureMatrix * vec4<T>(Reflect, one));

    gl_Position = MVPMatrix * MCvertex;
  }

  template <class Visitor>
  void visit(Visitor& v) {
    v.input("MCvertex", MCvertex);
    v.input("MCnormal", MCnormal);
    v.uniform("MVMatrix", MVMatrix);
    v.uniform("MVPMatrix", MVPMatrix);
    v.uniform("NormalMatrix", NormalMatrix);
    v.uniform("TextureMatrix", TextureMatrix);
    v.constant("Eta", Eta);
    v.output("Reflect", Reflect);
    v.output("Refract", Refract);
    v.output("gl_Position", gl_Position);
  }
};

extern template struct MethodDirections<double>;
extern template struct MethodDirections<float>;
extern template struct MethodDirections<Interval>;

inline constexpr const char* kMethodDirectionsName = "snell_method_directions";
std::unique_ptr<VertexOracle> makeMethodDirectionsOracle();

}  // namespace snell::listings
