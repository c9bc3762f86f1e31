#pragma once
// The chromatic variant of the blog's Fresnel vertex shader
// (shared/sources/003_08c70542091d50e3.txt, part 1): the post prints only
// the lines that change; shaders/blog/chromatic/chromatic.vert completes
// them into the Fresnel shader, and this mirrors that file line by line,
// over the number type T.
#include <memory>

#include "oracle/glsl/glsl.h"
#include "oracle/vertex_oracle.h"

namespace snell::listings {

template <class T>
struct BlogChromatic {
  // The fixed-function state it reads: gl_Vertex, gl_Normal,
  // gl_ModelViewMatrix, gl_NormalMatrix, gl_TextureMatrix[0] and [1], and
  // through ftransform() gl_ModelViewProjectionMatrix.
  glsl::vec4<T> gl_Vertex;
  glsl::vec3<T> gl_Normal;
  glsl::mat4<T> gl_ModelViewMatrix;
  glsl::mat3<T> gl_NormalMatrix;
  glsl::mat4<T> gl_TextureMatrix0;
  glsl::mat4<T> gl_TextureMatrix1;
  glsl::mat4<T> gl_ModelViewProjectionMatrix;

  // const float Eta=0.6;
  // const float EtaR=0.3;
  // const float EtaG=0.67;
  // const float EtaB=0.9;
  // const float FresnelPower=5.0;
  // (the values come from the manifest's `constants`)
  T Eta;
  T EtaR;
  T EtaG;
  T EtaB;
  T FresnelPower;

  // varying vec3 Reflect;
  // varying vec3 RefractR;
  // varying vec3 RefractG;
  // varying vec3 RefractB;
  // varying float Ratio;
  glsl::vec3<T> Reflect;
  glsl::vec3<T> RefractR;
  glsl::vec3<T> RefractG;
  glsl::vec3<T> RefractB;
  T Ratio;
  glsl::vec4<T> gl_Position;

  void main() {
    using namespace glsl;
    const T one = lit<T>(1.0);

    // const float F=((1.0-Eta)*(1.0-Eta))/((1.0+Eta)*(1.0+Eta));
    const T F = ((one - Eta) * (one - Eta)) / ((one + Eta) * (one + Eta));

    // vec4 ecposition = gl_ModelViewMatrix* gl_Vertex;
    vec4<T> ecposition = gl_ModelViewMatrix * gl_Vertex;
    // vec3 ecposition3 = ecposition.xyz/ecposition.w;
    vec3<T> ecposition3 = ecposition.xyz() / ecposition.w();
    // vec3 i = normalize(ecposition3);
    vec3<T> i = normalize(ecposition3);
    // vec3 n = normalize(gl_NormalMatrix*gl_Normal);
    vec3<T> n = normalize(gl_NormalMatrix * gl_Normal);
    // Ratio = F + (1.0-F) * pow(1.0 - dot(i, n),FresnelPower);
    Ratio = F + (one - F) * pow(one - dot(i, n), FresnelPower);

    // RefractR = refract(i,n,EtaR);
    RefractR = refract(i, n, EtaR);
    // RefractR = vec3(gl_TextureMatrix[0] * vec4(RefractR,1.0));
    RefractR = vec3<T>(gl_TextureMatrix0 * vec4<T>(RefractR, one));

    // RefractG = refract(i,n,EtaG);
    RefractG = refract(i, n, EtaG);
    // RefractG = vec3(gl_TextureMatrix[0] * vec4(RefractG,1.0));
    RefractG = vec3<T>(gl_TextureMatrix0 * vec4<T>(RefractG, one));

    // RefractB = refract(i,n,EtaB);
    RefractB = refract(i, n, EtaB);
    // RefractB = vec3(gl_TextureMatrix[0] * vec4(RefractB,1.0));
    RefractB = vec3<T>(gl_TextureMatrix0 * vec4<T>(RefractB, one));

    // Reflect = reflect(i,n);
    Reflect = reflect(i, n);
    // Reflect = vec3(gl_TextureMatrix[1] * vec4(Reflect,1.0));
    Reflect = vec3<T>(gl_TextureMatrix1 * vec4<T>(Reflect, one));

    // gl_Position = ftransform();
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
  }

  template <class Visitor>
  void visit(Visitor& v) {
    v.input("gl_Vertex", gl_Vertex);
    v.input("gl_Normal", gl_Normal);
    v.uniform("gl_ModelViewMatrix", gl_ModelViewMatrix);
    v.uniform("gl_NormalMatrix", gl_NormalMatrix);
    v.uniform("gl_TextureMatrix[0]", gl_TextureMatrix0);
    v.uniform("gl_TextureMatrix[1]", gl_TextureMatrix1);
    v.uniform("gl_ModelViewProjectionMatrix", gl_ModelViewProjectionMatrix);
    v.constant("Eta", Eta);
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

extern template struct BlogChromatic<double>;
extern template struct BlogChromatic<float>;
extern template struct BlogChromatic<Interval>;

inline constexpr const char* kBlogChromaticName = "blog_chromatic";
std::unique_ptr<VertexOracle> makeBlogChromaticOracle();

}  // namespace snell::listings
