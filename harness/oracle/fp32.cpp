#include "oracle/fp32.h"

#include "oracle/fp32_bits.h"

namespace snell {

// The bodies are in fp32_bits.h, inline for the oracle's own hot paths.
double gapAbove(double x) { return fp32_bits::gapAbove(x); }

double ulp(double x) { return fp32_bits::ulp(x); }

double floatAtOrBelow(double x) { return fp32_bits::floatAtOrBelow(x); }

double floatAtOrAbove(double x) { return fp32_bits::floatAtOrAbove(x); }

bool isFloat(double x) { return x != x || fp32_bits::floatAtOrBelow(x) == x; }

float nearestFloat(double x) { return static_cast<float>(x); }

}  // namespace snell
