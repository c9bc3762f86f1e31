#pragma once
// The Cg Tutorial's vertex program C7E3v_refraction (Example 7-3) with its
// texture coordinate kept, line by line over the number type T: the vertex
// part of the decal-and-refraction listing whose fragment part is
// cg_refraction_fragment.h. The GLSL port is
// shaders/cg-tutorial/c7e4f-refraction/c7e3v_refraction.vert; without
// texCoord it is CgRefraction (cg_refraction.h).
#include <memory>

#include "oracle/glsl/glsl.h"
#include "oracle/listings/cg_glsl.h"
#include "oracle/listings/cg_refract.h"
#include "oracle/vertex_oracle.h"

namespace snell::listings {

template <class T>
struct CgRefractionDecal {
  // in vec4 position;
  // in vec2 texCoord;
  // in vec3 normal;
  glsl::vec4<T> position;
  glsl::vec2<T> texCoord;
  glsl::vec3<T> normal;

  // out vec2 oTexCoord;
  // out vec3 T;   (T_ here: T names the number type)
  glsl::vec2<T> oTexCoord;
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
    oTexCoord = texCoord;

    // Compute position and normal in world space
    vec3<T> positionW = (modelToWorld * position).xyz();
    vec3<T> N = mat3Of(modelToWorld) * normal;
    N = normalize(N);

    // Compute the incident and refracted vectors
    vec3<T> I = positionW - eyePositionW;
    T_ = cgRefract(I, N, etaRatio);
  }

  // oTexCoord and gl_Position are outputs for the reference renderer; the
  // manifest captures T.
  template <class Visitor>
  void visit(Visitor& v) {
    v.input("position", position);
    v.input("texCoord", texCoord);
    v.input("normal", normal);
    v.uniform("etaRatio", etaRatio);
    v.uniform("eyePositionW", eyePositionW);
    v.uniform("modelViewProj", modelViewProj);
    v.uniform("modelToWorld", modelToWorld);
    v.output("T", T_);
    v.output("oTexCoord", oTexCoord);
    v.output("gl_Position", gl_Position);
  }
};

extern template struct CgRefractionDecal<double>;
extern template struct CgRefractionDecal<float>;
extern template struct CgRefractionDecal<Interval>;

inline constexpr const char* kCgRefractionDecalName = "cg_refraction_decal";
std::unique_ptr<VertexOracle> makeCgRefractionDecalOracle();

}  // namespace snell::listings
