#pragma once
// The few double-precision transforms a scene needs to place a camera and
// an object. Column-major like GLSL; scenes round the results to float
// once, and oracle and backends start from those same floats.
#include <array>

#include "core/values.h"

namespace snell {

using Vec3d = std::array<double, 3>;
using Mat4d = std::array<double, 16>;  // column-major: element (row r, column c) at [c * 4 + r]

Mat4d identity4();
Mat4d multiply(const Mat4d& a, const Mat4d& b);
Mat4d perspective(double fovyRadians, double aspect, double zNear, double zFar);
Mat4d lookAt(const Vec3d& eye, const Vec3d& center, const Vec3d& up);
Mat4d rotation(const Vec3d& axis, double radians);
Mat4d translation(const Vec3d& offset);
Vec3d normalized(const Vec3d& v);
Vec3d cross(const Vec3d& a, const Vec3d& b);

Value toMat4Value(const Mat4d& m);
// The inverse transpose of the upper-left 3x3, as glNormalMatrix would be.
Value normalMatrixValue(const Mat4d& modelview);

}  // namespace snell
