#pragma once
// GLSL's `if (condition) ... else ...` for a value-returning branch. With
// double and float the condition is a bool; with Interval it is a Truth,
// and when it is Unknown an implementation may take either branch, so the
// result is the union of both.
#include "oracle/interval.h"

namespace snell::glsl {

template <class Then, class Else>
auto branch(bool condition, Then then, Else otherwise) {
  return condition ? then() : otherwise();
}

template <class Then, class Else>
auto branch(Truth condition, Then then, Else otherwise) {
  switch (condition) {
    case Truth::True:
      return then();
    case Truth::False:
      return otherwise();
    case Truth::Unknown:
      break;
  }
  return hull(then(), otherwise());
}

}  // namespace snell::glsl
