#pragma once
// The diffraction vertex shader of the blog post
// (shared/sources/003_08c70542091d50e3.txt, part 2), corrected to compile
// as legacy GLSL (shaders/blog/diffraction/diffraction.vert), line by line,
// over the number type T. The Orange Book folder holds a GLSL 1.40 rewrite
// of the same shader (orange_book_diffraction.h); this one reads OpenGL's
// fixed-function state and keeps the blog's names.
#include <memory>

#include "oracle/glsl/glsl.h"
#include "oracle/listings/orange_book_diffraction.h"
#include "oracle/vertex_oracle.h"

namespace snell::listings {

template <class T>
struct BlogDiffraction {
  // The fixed-function state it reads: gl_Vertex, gl_Normal,
  // gl_ModelViewMatrix, gl_NormalMatrix, and through ftransform()
  // gl_ModelViewProjectionMatrix.
  glsl::vec4<T> gl_Vertex;
  glsl::vec3<T> gl_Normal;
  glsl::mat4<T> gl_ModelViewMatrix;
  glsl::mat3<T> gl_NormalMatrix;
  glsl::mat4<T> gl_ModelViewProjectionMatrix;

  // uniform vec3 eyeposition;
  // uniform vec3 lightposition;
  glsl::vec3<T> eyeposition;
  glsl::vec3<T> lightposition;
  // vec4 HighlightColor=vec4(1.0,1.0,1.0,1.0);  (in main below)
  // varying vec4 Color;
  glsl::vec4<T> Color;
  glsl::vec4<T> gl_Position;
  // attribute vec3 Tangent;
  glsl::vec3<T> Tangent;

  // The `const float` lines; the values come from the manifest's
  // `constants`.
  T ultraviolet;
  T infrared;
  T c;
  T diffAtten;

  // vec3 lambda2rgb(float lambda)
  glsl::vec3<T> lambda2rgb(const T& lambda) const {
    using namespace glsl;
    // const float ultraviolet =400.0;
    // const float infrared =700.0;
    // //(a comment: maps visible wavelengths to 0..1)
    // float a = (lambda - ultraviolet)/(infrared - ultraviolet);
    T a = (lambda - ultraviolet) / (infrared - ultraviolet);
    // const float c = 10.0; //(a comment: the width of the bumps)
    // vec3 b = vec3(a) - vec3(0.75,0.5,0.25);
    vec3<T> b = splat<T, 3>(a) - vec3<T>(lit<T>(0.75), lit<T>(0.5), lit<T>(0.25));
    // return max((1.0 - c*b*b), 0.0);
    return diffraction::max((splat<T, 3>(lit<T>(1.0)) - diffraction::times(c * b, b)), lit<T>(0.0));
  }

  void main() {
    using namespace glsl;
    using glsl::abs;
    using snell::abs;
    const vec4<T> HighlightColor(lit<T>(1.0), lit<T>(1.0), lit<T>(1.0), lit<T>(1.0));

    // vec3 objPosition = vec3 (gl_ModelViewMatrix * gl_Vertex);
    vec3<T> objPosition = vec3<T>(gl_ModelViewMatrix * gl_Vertex);
    // vec3 Normal = normalize (gl_NormalMatrix * gl_Normal);
    vec3<T> Normal = normalize(gl_NormalMatrix * gl_Normal);
    // vec3 LightDir = normalize (lightposition - objPosition);
    vec3<T> LightDir = normalize(lightposition - objPosition);
    // vec3 EyeDir = normalize (eyeposition - objPosition);
    vec3<T> EyeDir = normalize(eyeposition - objPosition);
    // vec3 HalfVec = normalize (LightDir + EyeDir);
    vec3<T> HalfVec = normalize(LightDir + EyeDir);

    // vec3 T=normalize(gl_NormalMatrix * Tangent);
    vec3<T> T_ = normalize(gl_NormalMatrix * Tangent);
    // float u = abs(dot(T, HalfVec));
    T u = abs(dot(T_, HalfVec));

    // vec3 diffColor=vec3(0.0);
    vec3<T> diffColor = splat<T, 3>(lit<T>(0.0));

    // const int numspectralorders=3;
    const int numspectralorders = 3;
    // for(int m=1; m<=numspectralorders;++m)
    for (int m = 1; m <= numspectralorders; ++m) {
      // float lambda =660.0 * u / float(m);
      T lambda = lit<T>(660.0) * u / lit<T>(static_cast<double>(m));
      // diffColor += lambda2rgb(lambda);
      diffColor = diffColor + lambda2rgb(lambda);
    }

    // float w = dot(Normal , HalfVec);
    T w = dot(Normal, HalfVec);
    // float e = 2.0 * u / w;
    T e = lit<T>(2.0) * u / w;
    // vec3 hilight = exp(-e * e) * HighlightColor.rgb;
    vec3<T> hilight = exp(-e * e) * HighlightColor.xyz();

    // const float diffAtten = 0.8;
    // Color = vec4(diffAtten * diffColor + hilight, 1.0);
    Color = vec4<T>(diffAtten * diffColor + hilight, lit<T>(1.0));

    // gl_Position = ftransform();
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
  }

  template <class Visitor>
  void visit(Visitor& v) {
    v.input("gl_Vertex", gl_Vertex);
    v.input("gl_Normal", gl_Normal);
    v.input("Tangent", Tangent);
    v.uniform("gl_ModelViewMatrix", gl_ModelViewMatrix);
    v.uniform("gl_NormalMatrix", gl_NormalMatrix);
    v.uniform("gl_ModelViewProjectionMatrix", gl_ModelViewProjectionMatrix);
    v.uniform("eyeposition", eyeposition);
    v.uniform("lightposition", lightposition);
    v.constant("ultraviolet", ultraviolet);
    v.constant("infrared", infrared);
    v.constant("c", c);
    v.constant("diffAtten", diffAtten);
    v.output("Color", Color);
    v.output("gl_Position", gl_Position);
  }
};

extern template struct BlogDiffraction<double>;
extern template struct BlogDiffraction<float>;
extern template struct BlogDiffraction<Interval>;

inline constexpr const char* kBlogDiffractionName = "blog_diffraction";
std::unique_ptr<VertexOracle> makeBlogDiffractionOracle();

}  // namespace snell::listings
