#include "core/camera_math.h"

#include <cmath>

namespace snell {

Mat4d identity4() { return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; }

Mat4d multiply(const Mat4d& a, const Mat4d& b) {
  Mat4d out{};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) {
      double sum = 0;
      for (int k = 0; k < 4; ++k) sum += a[k * 4 + r] * b[c * 4 + k];
      out[c * 4 + r] = sum;
    }
  return out;
}

Mat4d perspective(double fovyRadians, double aspect, double zNear, double zFar) {
  const double f = 1.0 / std::tan(fovyRadians / 2);
  Mat4d m{};
  m[0] = f / aspect;
  m[5] = f;
  m[10] = (zFar + zNear) / (zNear - zFar);
  m[11] = -1;
  m[14] = 2 * zFar * zNear / (zNear - zFar);
  return m;
}

Vec3d normalized(const Vec3d& v) {
  const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / length, v[1] / length, v[2] / length};
}

Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Mat4d lookAt(const Vec3d& eye, const Vec3d& center, const Vec3d& up) {
  const Vec3d f = normalized({center[0] - eye[0], center[1] - eye[1], center[2] - eye[2]});
  const Vec3d s = normalized(cross(f, up));
  const Vec3d u = cross(s, f);
  Mat4d m = identity4();
  for (int k = 0; k < 3; ++k) {
    m[k * 4 + 0] = s[k];
    m[k * 4 + 1] = u[k];
    m[k * 4 + 2] = -f[k];
  }
  m[12] = -(s[0] * eye[0] + s[1] * eye[1] + s[2] * eye[2]);
  m[13] = -(u[0] * eye[0] + u[1] * eye[1] + u[2] * eye[2]);
  m[14] = f[0] * eye[0] + f[1] * eye[1] + f[2] * eye[2];
  return m;
}

Mat4d rotation(const Vec3d& axis, double radians) {
  const Vec3d a = normalized(axis);
  const double c = std::cos(radians), s = std::sin(radians), t = 1 - c;
  Mat4d m = identity4();
  m[0] = t * a[0] * a[0] + c;
  m[1] = t * a[0] * a[1] + s * a[2];
  m[2] = t * a[0] * a[2] - s * a[1];
  m[4] = t * a[0] * a[1] - s * a[2];
  m[5] = t * a[1] * a[1] + c;
  m[6] = t * a[1] * a[2] + s * a[0];
  m[8] = t * a[0] * a[2] + s * a[1];
  m[9] = t * a[1] * a[2] - s * a[0];
  m[10] = t * a[2] * a[2] + c;
  return m;
}

Mat4d translation(const Vec3d& offset) {
  Mat4d m = identity4();
  m[12] = offset[0];
  m[13] = offset[1];
  m[14] = offset[2];
  return m;
}

Value toMat4Value(const Mat4d& m) {
  Value v{ValueType::Mat4, {}};
  for (double x : m) v.data.push_back(static_cast<float>(x));
  return v;
}

Value normalMatrixValue(const Mat4d& mv) {
  auto a = [&](int r, int c) { return mv[c * 4 + r]; };
  // cofactor matrix of the upper 3x3 divided by its determinant is the
  // inverse transpose
  double cof[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      const int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
      cof[r][c] = a(r1, c1) * a(r2, c2) - a(r1, c2) * a(r2, c1);
    }
  const double det = a(0, 0) * cof[0][0] + a(0, 1) * cof[0][1] + a(0, 2) * cof[0][2];
  Value v{ValueType::Mat3, {}};
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) v.data.push_back(static_cast<float>(cof[r][c] / det));
  return v;
}

}  // namespace snell
