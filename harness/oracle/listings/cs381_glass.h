#pragma once
// CS 381 (Fall 2012) lecture notes of November 13, "Simulating Glass":
// reflection mapping mixed with the dispersive refraction. The notes give
// no code for it; shaders/cs381/glass/glass.frag is the chromatic
// aberration fragment with one reflected direction and a fixed mix added
// (its manifest says what was chosen). Line by line over the number type T;
// the mix weighs colours only, so the oracle stops at the directions.
#include <memory>

#include "oracle/glsl/glsl.h"
#include "oracle/vertex_oracle.h"

namespace snell::listings {

template <class T>
struct Cs381Glass {
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
  glsl::vec3<T> reflectview;

  void main() {
    using namespace glsl;
    const T one = lit<T>(1.0);
    // vec3 viewdir = normalize(myvert);   // Viewing direction
    viewdir = normalize(myvert);

    // vec3 refractview_r = refract(viewdir, mynorm, 1./index_r);
    refractview_r = refract(viewdir, mynorm, one / index_r);
    // vec3 refractview_g = refract(viewdir, mynorm, 1./index_g);
    refractview_g = refract(viewdir, mynorm, one / index_g);
    // vec3 refractview_b = refract(viewdir, mynorm, 1./index_b);
    refractview_b = refract(viewdir, mynorm, one / index_b);

    // vec3 reflectview = reflect(viewdir, mynorm);   (the completion)
    reflectview = reflect(viewdir, mynorm);
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
    v.output("reflectview", reflectview);
  }
};

extern template struct Cs381Glass<double>;
extern template struct Cs381Glass<float>;
extern template struct Cs381Glass<Interval>;

inline constexpr const char* kCs381GlassName = "cs381_glass";
std::unique_ptr<VertexOracle> makeCs381GlassOracle();

}  // namespace snell::listings
