#pragma once
// Section 14.2 of the OpenGL Shading Language ("Orange Book"): the vertex
// shader of the diffraction effect (Stam's grating), line by line, over the
// number type T. The listing, corrected to GLSL 1.40 core from the legacy
// copy the sources print, is
// shaders/orange-book/14.2-diffraction/diffraction.vert.
#include <cmath>
#include <concepts>
#include <memory>

#include "oracle/glsl/glsl.h"
#include "oracle/vertex_oracle.h"

namespace snell::listings {

namespace diffraction {

// GLSL's max(vec3, float): exact, component by component.
template <class T>
glsl::vec3<T> max(const glsl::vec3<T>& x, const T& y) {
  using snell::glsl::max;
  using snell::max;
  glsl::vec3<T> r;
  for (int k = 0; k < 3; ++k) r[k] = max(x[k], y);
  return r;
}

// vec3 * vec3: component by component.
template <class T>
glsl::vec3<T> times(const glsl::vec3<T>& a, const glsl::vec3<T>& b) {
  return glsl::componentwise(a, b, [](const T& x, const T& y) { return x * y; });
}

}  // namespace diffraction

template <class T>
struct OrangeBookDiffraction {
  // uniform mat4 MVMatrix;
  // uniform mat4 MVPMatrix;
  // uniform mat3 NormalMatrix;
  // uniform vec3 EyePosition;
  // uniform vec3 LightPosition;
  glsl::mat4<T> MVMatrix;
  glsl::mat4<T> MVPMatrix;
  glsl::mat3<T> NormalMatrix;
  glsl::vec3<T> EyePosition;
  glsl::vec3<T> LightPosition;
  // vec4 HighlightColor = vec4(1.0, 1.0, 1.0, 1.0);  (in main below)
  // out vec4 Color;
  glsl::vec4<T> Color;
  glsl::vec4<T> gl_Position;
  // in vec4 MCVertex;
  // in vec3 MCNormal;
  // in vec3 Tangent;
  glsl::vec4<T> MCVertex;
  glsl::vec3<T> MCNormal;
  glsl::vec3<T> Tangent;

  // The `const float` lines; the values come from the manifest's
  // `constants`.
  T ultraviolet;
  T infrared;
  T c;
  T diffAtten;

  // vec3 lambda2rgb(float lambda)
  static glsl::vec3<T> lambda2rgb(const T& lambda, const T& ultraviolet, const T& infrared,
                                  const T& c) {
    using namespace glsl;
    // const float ultraviolet = 400.0;
    // const float infrared = 700.0;
    // // map visible wavelengths to 0..1
    // float a = (lambda - ultraviolet) / (infrared - ultraviolet);
    T a = (lambda - ultraviolet) / (infrared - ultraviolet);
    // const float c = 10.0; // width of the bumps
    // vec3 b = vec3(a) - vec3(0.75, 0.5, 0.25);
    vec3<T> b = splat<T, 3>(a) - vec3<T>(lit<T>(0.75), lit<T>(0.5), lit<T>(0.25));
    // return max((1.0 - c * b * b), 0.0);
    return diffraction::max(
        (splat<T, 3>(lit<T>(1.0)) - diffraction::times(c * b, b)), lit<T>(0.0));
  }
  glsl::vec3<T> lambda2rgb(const T& lambda) const {
    return lambda2rgb(lambda, ultraviolet, infrared, c);
  }

  void main() {
    using namespace glsl;
    using glsl::abs;
    using snell::abs;
    const vec4<T> HighlightColor(lit<T>(1.0), lit<T>(1.0), lit<T>(1.0), lit<T>(1.0));

    vec3<T> objPosition = vec3<T>(MVMatrix * MCVertex);
    vec3<T> Normal = normalize(NormalMatrix * MCNormal);
    vec3<T> LightDir = normalize(LightPosition - objPosition);
    vec3<T> EyeDir = normalize(EyePosition - objPosition);
    vec3<T> HalfVec = normalize(LightDir + EyeDir);

    vec3<T> T_ = normalize(NormalMatrix * Tangent);  // `vec3 T` in the listing
    T u = abs(dot(T_, HalfVec));

    vec3<T> diffColor = splat<T, 3>(lit<T>(0.0));

    const int numspectralorders = 3;
    for (int m = 1; m <= numspectralorders; ++m) {
      T lambda = lit<T>(660.0) * u / lit<T>(static_cast<double>(m));
      diffColor = diffColor + lambda2rgb(lambda);
    }

    T w = dot(Normal, HalfVec);
    T e = lit<T>(2.0) * u / w;
    vec3<T> hilight = exp(-e * e) * HighlightColor.xyz();  // .rgb

    // const float diffAtten = 0.8;
    Color = vec4<T>(diffAtten * diffColor + hilight, lit<T>(1.0));

    gl_Position = MVPMatrix * MCVertex;
  }

  template <class Visitor>
  void visit(Visitor& v) {
    v.input("MCVertex", MCVertex);
    v.input("MCNormal", MCNormal);
    v.input("Tangent", Tangent);
    v.uniform("MVMatrix", MVMatrix);
    v.uniform("MVPMatrix", MVPMatrix);
    v.uniform("NormalMatrix", NormalMatrix);
    v.uniform("EyePosition", EyePosition);
    v.uniform("LightPosition", LightPosition);
    v.constant("ultraviolet", ultraviolet);
    v.constant("infrared", infrared);
    v.constant("c", c);
    v.constant("diffAtten", diffAtten);
    v.output("Color", Color);
    v.output("gl_Position", gl_Position);
  }
};

extern template struct OrangeBookDiffraction<double>;
extern template struct OrangeBookDiffraction<float>;
extern template struct OrangeBookDiffraction<Interval>;

inline constexpr const char* kOrangeBookDiffractionName = "orange_book_diffraction";
std::unique_ptr<VertexOracle> makeOrangeBookDiffractionOracle();

}  // namespace snell::listings
