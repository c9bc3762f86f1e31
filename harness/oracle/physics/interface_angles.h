#pragma once
// The two special angles of an interface from index n1 into index n2, in
// degrees from the normal. Bad input throws UsageError.
namespace snell::physics {

// Past this angle light from the denser side is totally reflected:
// asin(n2 / n1). Exists only for n1 > n2.
double criticalAngleDegrees(double n1, double n2);

// At this angle the reflected light is purely s-polarised (Rp = 0):
// atan(n2 / n1).
double brewsterAngleDegrees(double n1, double n2);

}  // namespace snell::physics
