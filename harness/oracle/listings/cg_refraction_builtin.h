#pragma once
// The Cg Tutorial's vertex program C7E3v_refraction (Example 7-3) calling
// GLSL's built-in refract(), line by line over the number type T. The GLSL
// is shaders/cg-tutorial/c7e3v-refraction-builtin/c7e3v_refraction_builtin.vert.
#include <memory>

#include "oracle/glsl/glsl.h"
#include "oracle/listings/cg_glsl.h"
#include "oracle/vertex_oracle.h"

namespace snell::listings {

template <class T>
struct CgRefractionBuiltin {
  // in vec4 position;
  // in vec3 normal;
  glsl::vec4<T> position;
  glsl::vec3<T> normal;

  // out vec3 T;   (T_ here: T names the number type)
  glsl::vec3<T> T_;
  glsl::vec4<T> gl_Position;

  // uniform float etaRatio;
  // uniform vec3 eyePositionW;
  // uniform mat4 modelViewProj;
  // uniform mat4 modelToWorld;
  T etaRatio;
  glsl::vec3<T> eyePositionW;
  glsl::mat4<T> modelViewProj;
  glsl::mat4<T> modelToWorld;

  void main() {
    using namespace glsl;
    gl_Position = modelViewProj * position;

    // Compute position and normal in world space
    vec3<T> positionW = (modelToWorld * position).xyz();
    vec3<T> N = mat3Of(modelToWorld) * normal;
    N = normalize(N);

    // Compute the incident and refracted vectors
    vec3<T> I = positionW - eyePositionW;
    T_ = refract(I, N, etaRatio);
  }

  // gl_Position is an output for the reference renderer; the manifest
  // captures T only.
  template <class Visitor>
  void visit(Visitor& v) {
    v.input("position", position);
    v.input("normal", normal);
    v.uniform("etaRatio", etaRatio);
    v.uniform("eyePositionW", eyePositionW);
    v.uniform("modelViewProj", modelViewProj);
    v.uniform("modelToWorld", modelToWorld);
    v.output("T", T_);
    v.output("gl_Position", gl_Position);
  }
};

extern template struct CgRefractionBuiltin<double>;
extern template struct CgRefractionBuiltin<float>;
extern template struct CgRefractionBuiltin<Interval>;

inline constexpr const char* kCgRefractionBuiltinName = "cg_refraction_builtin";
std::unique_ptr<VertexOracle> makeCgRefractionBuiltinOracle();

}  // namespace snell::listings
