#pragma once
// CS 381 (Fall 2012) lecture notes of November 13: the second fragment,
// chromatic aberration with one index of refraction per colour (1.097, 1.1,
// 1.103), line by line over the number type T. The completed shader is
// shaders/cs381/chromatic-aberration/chromatic.frag; as in
// cs381_refraction.h the inputs are the fragment's varyings as read back.
#include <memory>

#include "oracle/glsl/glsl.h"
#include "oracle/vertex_oracle.h"

namespace snell::listings {

template <class T>
struct Cs381ChromaticAberration {
  // varying vec3 myvert;
  // varying vec3 mynorm;
  glsl::vec3<T> myvert;
  glsl::vec3<T> mynorm;

  // float index_r = 1.097;  // Index of refraction for red light
  // float index_g = 1.1;    // For green light
  // float index_b = 1.103;  // For blue light
  // (the values come from the manifest's `constants`)
  T index_r;
  T index_g;
  T index_b;

  // The locals the manifest captures.
  glsl::vec3<T> viewdir;
  glsl::vec3<T> refractview_r;
  glsl::vec3<T> refractview_g;
  glsl::vec3<T> refractview_b;

  void main() {
    using namespace glsl;
    const T one = lit<T>(1.0);
    // vec3 viewdir = normalize(myvert);   // Viewing direction
    viewdir = normalize(myvert);

    // Red refraction computation
    // vec3 refractview_r = refract(viewdir, mynorm, 1./index_r);
    refractview_r = refract(viewdir, mynorm, one / index_r);

    // Green refraction computation
    // vec3 refractview_g = refract(viewdir, mynorm, 1./index_g);
    refractview_g = refract(viewdir, mynorm, one / index_g);

    // Blue refraction computation
    // vec3 refractview_b = refract(viewdir, mynorm, 1./index_b);
    refractview_b = refract(viewdir, mynorm, one / index_b);
  }

  template <class Visitor>
  void visit(Visitor& v) {
    v.input("myvert", myvert);
    v.input("mynorm", mynorm);
    v.constant("index_r", index_r);
    v.constant("index_g", index_g);
    v.constant("index_b", index_b);
    v.output("viewdir", viewdir);
    v.output("refractview_r", refractview_r);
    v.output("refractview_g", refractview_g);
    v.output("refractview_b", refractview_b);
  }
};

extern template struct Cs381ChromaticAberration<double>;
extern template struct Cs381ChromaticAberration<float>;
extern template struct Cs381ChromaticAberration<Interval>;

inline constexpr const char* kCs381ChromaticAberrationName = "cs381_chromatic_aberration";
std::unique_ptr<VertexOracle> makeCs381ChromaticAberrationOracle();

}  // namespace snell::listings
