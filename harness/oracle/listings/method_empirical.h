#pragma once
// The Fresnel method ladder's vertex stage, line by line over the number
// type T: the Shadertoy post's empirical reflectance per vertex (rung 2). The
// listing is shaders/methods/fresnel/2-empirical/empirical.vert.
#include <memory>

#include "oracle/glsl/glsl.h"
#include "oracle/vertex_oracle.h"

namespace snell::listings {

template <class T>
struct MethodEmpirical {
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
  // const float Bias = 0.0;
  // const float Scale = 0.25;
  // const float Power = 1.97;
  // (the values come from the manifest's `constants`)
  T Eta;
  T Bias;
  T Scale;
  T Power;

  // out vec3 Reflect;
  // out vec3 Refract;
  // out float Ratio;
  glsl::vec3<T> Reflect;
  glsl::vec3<T> Refract;
  T Ratio;
  glsl::vec4<T> gl_Position;

  void main() {
    using namespace glsl;
    const T one = lit<T>(1.0);

    vec4<T> ecPosition = MVMatrix * MCvertex;
    vec3<T> ecPosition3 = ecPosition.xyz() / ecPosition.w();

    vec3<T> i = normalize(ecPosition3);
    vec3<T> n = normalize(NormalMatrix * MCnormal);

    Ratio = Bias + Scale * pow(one + dot(i, n), Power);

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
    v.constant("Bias", Bias);
    v.constant("Scale", Scale);
    v.constant("Power", Power);
    v.output("Reflect", Reflect);
    v.output("Refract", Refract);
    v.output("Ratio", Ratio);
    v.output("gl_Position", gl_Position);
  }
};

extern template struct MethodEmpirical<double>;
extern template struct MethodEmpirical<float>;
extern template struct MethodEmpirical<Interval>;

inline constexpr const char* kMethodEmpiricalName = "snell_method_empirical";
std::unique_ptr<VertexOracle> makeMethodEmpiricalOracle();

}  // namespace snell::listings
