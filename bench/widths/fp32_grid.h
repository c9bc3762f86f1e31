#pragma once
// The fp32 grid seen from double, for the width measurement: its own small
// copy, so that the tool measures the oracle without sharing its helpers.
namespace snell::widths {

enum class Rounding { Nearest, Up, Down, TowardZero };

inline constexpr double kMinNormal = 0x1p-126;
inline constexpr double kMaxFloat = 0x1.fffffep127;

// The largest float <= x, the smallest float >= x (infinities past the range).
double floatDown(double x);
double floatUp(double x);
// Harrison's ULP, as the Vulkan spec and dEQP define it: the gap between the
// floats around x, the gap below at an exact power of two; 2^-149 for the
// denormals.
double ulpOf(double x);
// The exact value head + tail (|tail| far below one fp32 ULP of head, as an
// error-free sum gives) rounded to a float in the given mode.
float roundTo(double head, double tail, Rounding mode);
// Error-free transformations: a + b = sum + *error, a * b = product + *error.
double twoSum(double a, double b, double* error);
double twoProduct(double a, double b, double* error);
// a + b, a * b rounded in double towards -inf or +inf (an enclosure).
double addDown(double a, double b);
double addUp(double a, double b);
double mulDown(double a, double b);
double mulUp(double a, double b);
// How many float steps of ulpOf(reference) `distance` is: the width unit.
double inUlps(double distance, double reference);

}  // namespace snell::widths
