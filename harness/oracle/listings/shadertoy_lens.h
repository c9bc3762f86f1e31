#pragma once
// The Shadertoy post "Reflections and Refractions": the sphere as a lens,
// a refracted ray per pixel, line by line over the number type T. One
// oracle serves the convex lens (refract_koef 1.02) and the concave one
// (0.98): the coefficient is the manifest's constant. The completed shaders
// are shaders/shadertoy/lens/lens.frag and concave-lens/concave_lens.frag.
// uv and point_normal come from the completion (pixel coordinates and the
// sphere tracer): they are inputs, read back per pixel, not checked.
#include <memory>

#include "oracle/glsl/glsl.h"
#include "oracle/listings/shadertoy_ray.h"
#include "oracle/vertex_oracle.h"

namespace snell::listings {

template <class T>
struct ShadertoyLens {
  // vec2 uv = ...;                the pixel (completion)
  // vec3 point_normal = ...;      the sphere's normal where the ray hit (completion)
  glsl::vec2<T> uv;
  glsl::vec3<T> point_normal;

  // "refract_koef is 1.02"; "the concave lens with refract_koef = 0.98;"
  // (the value comes from the manifest's `constants`)
  T refract_koef;

  // The locals the manifest captures.
  glsl::vec3<T> ray_dir;
  glsl::vec3<T> refracted_ray;

  void main() {
    using namespace glsl;
    ray_dir = shadertoyRayDir(uv);
    // vec3 refracted_ray = refract(ray_dir, -point_normal, refract_koef);
    refracted_ray = refract(ray_dir, -point_normal, refract_koef);
  }

  template <class Visitor>
  void visit(Visitor& v) {
    v.input("uv", uv);
    v.input("point_normal", point_normal);
    v.constant("refract_koef", refract_koef);
    v.output("ray_dir", ray_dir);
    v.output("refracted_ray", refracted_ray);
  }
};

extern template struct ShadertoyLens<double>;
extern template struct ShadertoyLens<float>;
extern template struct ShadertoyLens<Interval>;

inline constexpr const char* kShadertoyLensName = "shadertoy_lens";
std::unique_ptr<VertexOracle> makeShadertoyLensOracle();

}  // namespace snell::listings
