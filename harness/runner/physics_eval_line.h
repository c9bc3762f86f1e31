#pragma once
// The physics lines of `snell eval`, answered by the physics reference
// (oracle/physics) in double:
//   {"fn":"fresnel","model":"exact"|"schlick"|"schlick_dense_side","cos_i":..,"n1":..,"n2":..}
//   {"fn":"ior","glass":"N-BK7"|"water","lambda_nm":..}
//   {"fn":"critical_angle","n1":..,"n2":..}    (degrees)
//   {"fn":"brewster_angle","n1":..,"n2":..}    (degrees)
#include <nlohmann/json.hpp>

namespace snell {

// Whether the line names one of the functions above.
bool isPhysicsCall(const nlohmann::json& object);

// The answer's fields ("fn", "value" and what was asked); UsageError for a
// missing or bad field, an unknown glass or model, a wavelength outside the
// fit or a critical angle asked for with n1 <= n2.
nlohmann::json evaluatePhysicsCall(const nlohmann::json& object);

}  // namespace snell
