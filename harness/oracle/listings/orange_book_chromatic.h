#pragma once
// Listing 14.3 of the OpenGL Shading Language ("Orange Book"): the vertex
// shader for the chromatic aberration effect, line by line, over the number
// type T. The listing as published is
// shaders/orange-book/14.3-chromatic/chromatic.vert.
#include <memory>

#include "oracle/glsl/glsl.h"
#include "oracle/vertex_oracle.h"

namespace snell::listings {

template <class T>
struct OrangeBookChromatic {
  // uniform mat4 MVMatrix;
  // uniform mat4 MVPMatrix;
  // uniform mat3 NormalMatrix;
  // uniform mat4 TextureMatrix;
  glsl::mat4<T> MVMatrix;
  glsl::mat4<T> MVPMatrix;
  glsl::mat3<T> NormalMatrix;
  glsl::mat4<T> TextureMatrix;

  // in vec4      MCVertex;
  // in vec3      MCNormal;
  glsl::vec4<T> MCVertex;
  glsl::vec3<T> MCNormal;

  // const float EtaR = 0.65;
  // const float EtaG = 0.67; // Ratio of indices of refraction
  // const float EtaB = 0.69;
  // const float FresnelPower = 5.0;
  // (the values come from the manifest's `constants`)
  T EtaR;
  T EtaG;
  T EtaB;
  T FresnelPower;

  // out vec3 Reflect;
  // out vec3 RefractR;
  // out vec3 RefractG;
  // out vec3 RefractB;
  // out float Ratio;
  glsl::vec3<T> Reflect;
  glsl::vec3<T> RefractR;
  glsl::vec3<T> RefractG;
  glsl::vec3<T> RefractB;
  T Ratio;
  glsl::vec4<T> gl_Position;

  void main() {
    using namespace glsl;
    const T one = lit<T>(1.0);

    // const float F = ((1.0-EtaG) * (1.0-EtaG)) / ((1.0+EtaG) * (1.0+EtaG));
    const T F = ((one - EtaG) * (one - EtaG)) / ((one + EtaG) * (one + EtaG));

    vec4<T> ecPosition = MVMatrix * MCVertex;
    vec3<T> ecPosition3 = ecPosition.xyz() / ecPosition.w();

    vec3<T> i = normalize(ecPosition3);
    vec3<T> n = normalize(NormalMatrix * MCNormal);

    Ratio = F + (one - F) * pow((one - dot(-i, n)), FresnelPower);

    RefractR = refract(i, n, EtaR);
    RefractR = vec3<T>(TextureMatrix * vec4<T>(RefractR, one));

    RefractG = refract(i, n, EtaG);
    RefractG = vec3<T>(TextureMatrix * vec4<T>(RefractG, one));

    RefractB = refract(i, n, EtaB);
    RefractB = vec3<T>(TextureMatrix * vec4<T>(RefractB, one));

    Reflect = reflect(i, n);
    Reflect = vec3<T>(TextureMatrix * vec4<T>(Reflect, one));

    gl_Position = MVPMatrix * MCVertex;
  }

  // The interface by GLSL name. gl_Position is an output for the reference
  // renderer; a manifest captures only the listing's own `out` variables.
  template <class Visitor>
  void visit(Visitor& v) {
    v.input("MCVertex", MCVertex);
    v.input("MCNormal", MCNormal);
    v.uniform("MVMatrix", MVMatrix);
    v.uniform("MVPMatrix", MVPMatrix);
    v.uniform("NormalMatrix", NormalMatrix);
    v.uniform("TextureMatrix", TextureMatrix);
    v.constant("EtaR", EtaR);
    v.constant("EtaG", EtaG);
    v.constant("EtaB", EtaB);
    v.constant("FresnelPower", FresnelPower);
    v.output("Reflect", Reflect);
    v.output("RefractR", RefractR);
    v.output("RefractG", RefractG);
    v.output("RefractB", RefractB);
    v.output("Ratio", Ratio);
    v.output("gl_Position", gl_Position);
  }
};

extern template struct OrangeBookChromatic<double>;
extern template struct OrangeBookChromatic<float>;
extern template struct OrangeBookChromatic<Interval>;

inline constexpr const char* kOrangeBookChromaticName = "orange_book_chromatic";
std::unique_ptr<VertexOracle> makeOrangeBookChromaticOracle();

}  // namespace snell::listings
