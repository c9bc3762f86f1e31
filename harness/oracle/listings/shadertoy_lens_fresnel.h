#pragma once
// The Shadertoy post "Reflections and Refractions": the lens with a
// reflected ray, the two colours mixed by the post's Fresnel term (after
// GPU Gems 2, its constants hand tweaked), line by line over the number
// type T. The completed shader is shaders/shadertoy/lens-fresnel/
// lens_fresnel.frag; uv and point_normal are inputs as in shadertoy_lens.h.
// At normal incidence the pow() base 1.0 + dot(ray_dir, point_normal) is 0
// up to rounding and may be negative: mix_coef is undefined there.
#include <memory>

#include "oracle/glsl/glsl.h"
#include "oracle/listings/shadertoy_ray.h"
#include "oracle/vertex_oracle.h"

namespace snell::listings {

template <class T>
struct ShadertoyLensFresnel {
  // vec2 uv = ...;                the pixel (completion)
  // vec3 point_normal = ...;      the sphere's normal where the ray hit (completion)
  glsl::vec2<T> uv;
  glsl::vec3<T> point_normal;

  // "refract_koef is 1.02"
  // float fresnelBias = 0.00;
  // float fresnelScale = 0.25;
  // float fresnelPower = 1.97;
  // (the values come from the manifest's `constants`)
  T refract_koef;
  T fresnelBias;
  T fresnelScale;
  T fresnelPower;

  // The locals the manifest captures.
  glsl::vec3<T> ray_dir;
  glsl::vec3<T> refracted_ray;
  glsl::vec3<T> reflected_ray;
  T mix_coef;

  void main() {
    using namespace glsl;
    ray_dir = shadertoyRayDir(uv);
    // vec3 refracted_ray = refract(ray_dir, -point_normal, refract_koef);
    refracted_ray = refract(ray_dir, -point_normal, refract_koef);
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
    v.constant("refract_koef", refract_koef);
    v.constant("fresnelBias", fresnelBias);
    v.constant("fresnelScale", fresnelScale);
    v.constant("fresnelPower", fresnelPower);
    v.output("ray_dir", ray_dir);
    v.output("refracted_ray", refracted_ray);
    v.output("reflected_ray", reflected_ray);
    v.output("mix_coef", mix_coef);
  }
};

extern template struct ShadertoyLensFresnel<double>;
extern template struct ShadertoyLensFresnel<float>;
extern template struct ShadertoyLensFresnel<Interval>;

inline constexpr const char* kShadertoyLensFresnelName = "shadertoy_lens_fresnel";
std::unique_ptr<VertexOracle> makeShadertoyLensFresnelOracle();

}  // namespace snell::listings
