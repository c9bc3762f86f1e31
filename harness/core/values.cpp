#include "core/values.h"

namespace snell {

int componentCount(ValueType type) {
  switch (type) {
    case ValueType::Float: return 1;
    case ValueType::Vec2: return 2;
    case ValueType::Vec3: return 3;
    case ValueType::Vec4: return 4;
    case ValueType::Mat3: return 9;
    case ValueType::Mat4: return 16;
  }
  return 0;
}

const char* glslTypeName(ValueType type) {
  switch (type) {
    case ValueType::Float: return "float";
    case ValueType::Vec2: return "vec2";
    case ValueType::Vec3: return "vec3";
    case ValueType::Vec4: return "vec4";
    case ValueType::Mat3: return "mat3";
    case ValueType::Mat4: return "mat4";
  }
  return "?";
}

}  // namespace snell
