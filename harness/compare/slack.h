#pragma once
// Slack: how much of the allowed error a result used. 0 means the result
// equals the exact value, 1 means it sits on the edge of what the spec
// allows, above 1 means it is outside. Measured on the side the result
// fell, because the allowed interval is rarely symmetric.
namespace snell {

double slack(double observed, double reference, double lo, double hi);
bool withinSpec(double observed, double lo, double hi);

}  // namespace snell
