#pragma once
// The Fresnel vertex shader of a blog post on reflection and refraction
// (shared/sources/003_08c70542091d50e3.txt, part 1), line by line, over the
// number type T. The listing is legacy GLSL on OpenGL's fixed-function
// state; it is published in shaders/blog/fresnel/fresnel.vert (the same
// text as shaders/blog/fresnel-as-published/fresnel.vert, whose fragment
// shader does not compile).
#include <memory>

#include "oracle/glsl/glsl.h"
#include "oracle/vertex_oracle.h"

namespace snell::listings {

template <class T>
struct BlogFresnel {
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
  // const float FresnelPower=5.0;
  // (the values come from the manifest's `constants`)
  T Eta;
  T FresnelPower;

  // varying vec3 Reflect;
  // varying vec3 Refract;
  // varying float Ratio;
  glsl::vec3<T> Reflect;
  glsl::vec3<T> Refract;
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
    // (dot(i, n), not the Orange Book's dot(-i, n): the listing as printed)
    Ratio = F + (one - F) * pow(one - dot(i, n), FresnelPower);

    // Refract = refract(i,n,Eta);
    Refract = refract(i, n, Eta);
    // Refract = vec3(gl_TextureMatrix[0] * vec4(Refract,1.0));
    Refract = vec3<T>(gl_TextureMatrix0 * vec4<T>(Refract, one));

    // Reflect = reflect(i,n);
    Reflect = reflect(i, n);
    // Reflect = vec3(gl_TextureMatrix[1] * vec4(Reflect,1.0));
    Reflect = vec3<T>(gl_TextureMatrix1 * vec4<T>(Reflect, one));

    // gl_Position = ftransform();
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
  }

  // The interface by the names manifests bind. gl_Position is an output for
  // the reference renderer; a manifest captures only the listing's own
  // varyings.
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
    v.constant("FresnelPower", FresnelPower);
    v.output("Reflect", Reflect);
    v.output("Refract", Refract);
    v.output("Ratio", Ratio);
    v.output("gl_Position", gl_Position);
  }
};

extern template struct BlogFresnel<double>;
extern template struct BlogFresnel<float>;
extern template struct BlogFresnel<Interval>;

inline constexpr const char* kBlogFresnelName = "blog_fresnel";
std::unique_ptr<VertexOracle> makeBlogFresnelOracle();

}  // namespace snell::listings
