#include "core/legacy_builtins.h"

#include <fmt/format.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>

#include "core/camera_math.h"

namespace snell {
namespace {

struct Fixed {
  const char* name;
  LegacyBuiltinKind kind;
  ValueType type;
};

constexpr std::array kFixed = {
    Fixed{"gl_ModelViewMatrix", LegacyBuiltinKind::Matrix, ValueType::Mat4},
    Fixed{"gl_ProjectionMatrix", LegacyBuiltinKind::Matrix, ValueType::Mat4},
    Fixed{"gl_ModelViewProjectionMatrix", LegacyBuiltinKind::DerivedMatrix, ValueType::Mat4},
    Fixed{"gl_NormalMatrix", LegacyBuiltinKind::DerivedMatrix, ValueType::Mat3},
    Fixed{"gl_Vertex", LegacyBuiltinKind::Attribute, ValueType::Vec4},
    Fixed{"gl_Normal", LegacyBuiltinKind::Attribute, ValueType::Vec3},
};

// "gl_TextureMatrix[3]" with prefix "gl_TextureMatrix[" and suffix "]": 3.
std::optional<int> unitOf(const std::string& name, std::string_view prefix,
                          std::string_view suffix) {
  if (name.size() <= prefix.size() + suffix.size() || name.rfind(prefix, 0) != 0 ||
      name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
    return std::nullopt;
  const char* first = name.data() + prefix.size();
  const char* last = name.data() + name.size() - suffix.size();
  int unit = -1;
  const auto [end, error] = std::from_chars(first, last, unit);
  // One digit: "gl_TextureMatrix[01]" is no name GL knows.
  if (error != std::errc() || end != last || last - first != 1) return std::nullopt;
  if (unit < 0 || unit >= kLegacyTextureUnits) return std::nullopt;
  return unit;
}

Mat4d toMat4d(const Value& value) {
  Mat4d m{};
  for (int k = 0; k < 16; ++k) m[k] = value.data[k];
  return m;
}

// Whether the upper 3x3's columns are orthonormal to fp32 rounding: then
// the matrix is its own inverse transpose.
bool orthonormal(const Mat4d& m) {
  for (std::size_t a = 0; a < 3; ++a)
    for (std::size_t b = 0; b < 3; ++b) {
      const double dot =
          m[a * 4] * m[b * 4] + m[a * 4 + 1] * m[b * 4 + 1] + m[a * 4 + 2] * m[b * 4 + 2];
      if (std::fabs(dot - (a == b ? 1.0 : 0.0)) > 1e-6) return false;
    }
  return true;
}

Value upperLeft3x3(const Value& mat4) {
  Value out{ValueType::Mat3, {}};
  for (int column = 0; column < 3; ++column)
    for (int row = 0; row < 3; ++row) out.data.push_back(mat4.data[column * 4 + row]);
  return out;
}

bool isMat4(const UniformMap& uniforms, const char* name) {
  const auto found = uniforms.find(name);
  return found != uniforms.end() && found->second.type == ValueType::Mat4 &&
         found->second.data.size() == 16;
}

}  // namespace

std::optional<LegacyBuiltin> findLegacyBuiltin(const std::string& name) {
  for (const Fixed& fixed : kFixed)
    if (name == fixed.name) return LegacyBuiltin{name, fixed.kind, fixed.type, -1};
  if (const auto unit = unitOf(name, "gl_TextureMatrix[", "]"))
    return LegacyBuiltin{name, LegacyBuiltinKind::Matrix, ValueType::Mat4, *unit};
  if (const auto unit = unitOf(name, "gl_MultiTexCoord", ""))
    return LegacyBuiltin{name, LegacyBuiltinKind::Attribute, ValueType::Vec4, *unit};
  return std::nullopt;
}

std::string legacyBindableNames() {
  const int last = kLegacyTextureUnits - 1;
  return fmt::format(
      "uniforms gl_ModelViewMatrix, gl_ProjectionMatrix, gl_TextureMatrix[0..{}]; inputs "
      "gl_Vertex, gl_Normal, gl_MultiTexCoord0..{}",
      last, last);
}

UniformMap withDerivedLegacyState(const UniformMap& uniforms) {
  UniformMap out = uniforms;
  if (!isMat4(uniforms, "gl_ModelViewMatrix")) return out;
  // camera_math works in double; the fp32 inputs convert exactly, and each
  // result is rounded to fp32 once at the end.
  const Mat4d modelview = toMat4d(uniforms.at("gl_ModelViewMatrix"));
  // A rigid modelview (every scene's camera) is its own inverse transpose
  // to fp32 rounding, and GL implementations take it as is (Mesa inverts
  // a matrix it recognises as a rotation by transposing it): so does snell,
  // which keeps their bits rather than rounding the exact inverse of the
  // not quite orthonormal fp32 matrix, an ulp away.
  out["gl_NormalMatrix"] = orthonormal(modelview) ? upperLeft3x3(uniforms.at("gl_ModelViewMatrix"))
                                                  : normalMatrixValue(modelview);
  if (isMat4(uniforms, "gl_ProjectionMatrix"))
    out["gl_ModelViewProjectionMatrix"] =
        toMat4Value(multiply(toMat4d(uniforms.at("gl_ProjectionMatrix")), modelview));
  return out;
}

}  // namespace snell
