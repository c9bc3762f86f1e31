#pragma once
// The fp32 grid seen from double: where the floats lie, how far apart they
// are, and which of them bracket a real number. Every bound the oracle hands
// out is a float, so that "contains" means "this fp32 result is allowed".
namespace snell {

inline constexpr double kFp32MinDenormal = 0x1p-149;
inline constexpr double kFp32MinNormal = 0x1p-126;
inline constexpr double kFp32Max = 0x1.fffffep127;

// One fp32 ULP at x, Harrison's, as the Vulkan precision appendix and dEQP
// define it: the smallest gap between floats a <= x <= b, so at an exact
// power of two the gap below it. In the denormal range it is 2^-149, past
// the largest float 2^104.
double ulp(double x);
// The gap between the floats around x in x's binade (at a power of two, the
// gap above): the largest error of one rounding of a value of magnitude
// up to |x|.
double gapAbove(double x);

// The largest float <= x and the smallest float >= x (infinities beyond the
// float range). Both return x itself when x is a float.
double floatAtOrBelow(double x);
double floatAtOrAbove(double x);

bool isFloat(double x);

// The float nearest x, as a `const float` or a float uniform gets it. Out of
// line on purpose: GCC 12.2 at -O2 folds a pair of adjacent inlined
// double -> float -> double round trips into nothing (SLP vectorizer).
float nearestFloat(double x);

}  // namespace snell
