#pragma once
// CS 381 (Fall 2012) lecture notes of November 13, "Refraction & Rendering":
// the first fragment, refraction mapping with index 1.1, line by line over
// the number type T. The notes print statements only; the completed shader
// is shaders/cs381/refraction/refraction.frag. The computation runs in the
// fragment stage, so the inputs are the interpolated varyings as the driver
// gave them to the fragment (read back with the captures of the same name)
// and the outputs are the locals the manifest captures.
#include <memory>

#include "oracle/glsl/glsl.h"
#include "oracle/vertex_oracle.h"

namespace snell::listings {

template <class T>
struct Cs381Refraction {
  // varying vec3 myvert;
  // varying vec3 mynorm;
  glsl::vec3<T> myvert;
  glsl::vec3<T> mynorm;

  // float index = 1.1;                 // Index of refraction for object
  // (the value comes from the manifest's `constants`)
  T index;

  // The locals the manifest captures.
  glsl::vec3<T> viewdir;
  glsl::vec3<T> refractview;

  void main() {
    using namespace glsl;
    // vec3 viewdir = normalize(myvert);  // Viewing direction
    viewdir = normalize(myvert);
    // vec3 refractview = refract(viewdir, mynorm, 1./index);
    refractview = refract(viewdir, mynorm, lit<T>(1.0) / index);
  }

  template <class Visitor>
  void visit(Visitor& v) {
    v.input("myvert", myvert);
    v.input("mynorm", mynorm);
    v.constant("index", index);
    v.output("viewdir", viewdir);
    v.output("refractview", refractview);
  }
};

extern template struct Cs381Refraction<double>;
extern template struct Cs381Refraction<float>;
extern template struct Cs381Refraction<Interval>;

inline constexpr const char* kCs381RefractionName = "cs381_refraction";
std::unique_ptr<VertexOracle> makeCs381RefractionOracle();

}  // namespace snell::listings
