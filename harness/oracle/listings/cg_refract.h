#pragma once
// The sample implementation of Cg's refract() printed in The Cg Tutorial,
// section 7.3.2, over the number type T, as ported to GLSL in
// shaders/cg-tutorial/c7e3v-refraction/c7e3v_refraction.vert (cgRefract).
// It is GLSL's refract() rearranged, with two differences that matter: it
// takes sqrt(abs(cosT2)) unconditionally, and it returns zero when
// cosT2 == 0 exactly, where GLSL's returns the grazing ray.
#include "oracle/glsl/glsl.h"
#include "oracle/listings/cg_glsl.h"

namespace snell::listings {

template <class T>
glsl::vec3<T> cgRefract(const glsl::vec3<T>& I, const glsl::vec3<T>& N, const T& etaRatio) {
  using namespace glsl;
  // float cosI = dot(-I, N);
  const T cosI = dot(-I, N);
  // float cosT2 = 1.0f - etaRatio * etaRatio * (1.0f - cosI * cosI);
  const T cosT2 = lit<T>(1.0) - etaRatio * etaRatio * (lit<T>(1.0) - cosI * cosI);
  // vec3 T = etaRatio * I + ((etaRatio * cosI - sqrt(abs(cosT2))) * N);
  const vec3<T> T_ = etaRatio * I + ((etaRatio * cosI - sqrt(abs(cosT2))) * N);
  // return T * vec3(cosT2 > 0.0);
  // vec3(bool) is 1.0 or 0.0; where the comparison may go either way
  // (Interval), an implementation may return either product.
  const auto times = [&](double factor) {
    return componentwise(T_, splat<T, 3>(lit<T>(factor)),
                         [](const T& a, const T& b) { return a * b; });
  };
  return branch(lit<T>(0.0) < cosT2, [&] { return times(1.0); }, [&] { return times(0.0); });
}

}  // namespace snell::listings
