#pragma once
// The Shadertoy post "Reflections and Refractions": the bubble, the lens
// with reflection and Fresnel mix whose refraction is split into red, green
// and blue with a coefficient each, line by line over the number type T.
// The completed shader is shaders/shadertoy/bubble/bubble.frag; uv and
// point_normal are inputs as in shadertoy_lens.h, and mix_coef is undefined
// at normal incidence as in shadertoy_lens_fresnel.h.
#include <memory>

#include "oracle/glsl/glsl.h"
#include "oracle/listings/shadertoy_ray.h"
#include "oracle/vertex_oracle.h"

namespace snell::listings {

template <class T>
struct ShadertoyBubble {
  // vec2 uv = ...;                the pixel (completion)
  // vec3 point_normal = ...;      the sphere's normal where the ray hit (completion)
  glsl::vec2<T> uv;
  glsl::vec3<T> point_normal;

  // vec3 etaRatioRGB = vec3(1.03, 1.06, 1.09);
  // float fresnelBias = 0.00;
  // float fresnelScale = 0.25;
  // float fresnelPower = 1.97;
  // (the values come from the manifest's `constants`, etaRatioRGB's by
  // component: "etaRatioRGB.r" and so on)
  T etaRatioR;
  T etaRatioG;
  T etaRatioB;
  T fresnelBias;
  T fresnelScale;
  T fresnelPower;

  // The locals the manifest captures.
  glsl::vec3<T> ray_dir;
  glsl::vec3<T> TRed;
  glsl::vec3<T> TGreen;
  glsl::vec3<T> TBlue;
  glsl::vec3<T> reflected_ray;
  T mix_coef;

  void main() {
    using namespace glsl;
    ray_dir = shadertoyRayDir(uv);
    // vec3 etaRatioRGB = vec3(1.03, 1.06, 1.09);
    const vec3<T> etaRatioRGB(etaRatioR, etaRatioG, etaRatioB);

    // vec3 TRed = refract(ray_dir, -point_normal, etaRatioRGB.r);
    TRed = refract(ray_dir, -point_normal, etaRatioRGB.r());
    // vec3 TGreen = refract(ray_dir, -point_normal, etaRatioRGB.g);
    TGreen = refract(ray_dir, -point_normal, etaRatioRGB.g());
    // vec3 TBlue = refract(ray_dir, -point_normal, etaRatioRGB.b);
    TBlue = refract(ray_dir, -point_normal, etaRatioRGB.b());

    // vec3 reflected_ray = reflect(ray_dir, point_normal);
    reflected_ray = reflect(ray_dir, point_normal);
    // float mix_coef = fresnelBias + fresnelScale*pow(1.0 + dot(ray_dir, point_normal),
    // fresnelPower);
    mix_coef =
        fresnelBias + fresnelScale * pow(lit<T>(1.0) + dot(ray_dir, point_normal), fresnelPower);
  }

  template <class Visitor>
  void visit(Visitor& v) {
    v.input("uv", uv);
    v.input("point_normal", point_normal);
    v.constant("etaRatioRGB.r", etaRatioR);
    v.constant("etaRatioRGB.g", etaRatioG);
    v.constant("etaRatioRGB.b", etaRatioB);
    v.constant("fresnelBias", fresnelBias);
    v.constant("fresnelScale", fresnelScale);
    v.constant("fresnelPower", fresnelPower);
    v.output("ray_dir", ray_dir);
    v.output("TRed", TRed);
    v.output("TGreen", TGreen);
    v.output("TBlue", TBlue);
    v.output("reflected_ray", reflected_ray);
    v.output("mix_coef", mix_coef);
  }
};

extern template struct ShadertoyBubble<double>;
extern template struct ShadertoyBubble<float>;
extern template struct ShadertoyBubble<Interval>;

inline constexpr const char* kShadertoyBubbleName = "shadertoy_bubble";
std::unique_ptr<VertexOracle> makeShadertoyBubbleOracle();

}  // namespace snell::listings
