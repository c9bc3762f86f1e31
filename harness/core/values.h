#pragma once
// Values that flow between manifests, scenes, oracles and backends.
// Plain floats only: every value a shader sees is an fp32 value, and the
// oracle starts from exactly those values.
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace snell {

enum class ValueType { Float, Vec2, Vec3, Vec4, Mat3, Mat4 };

int componentCount(ValueType type);          // Float 1, Vec3 3, Mat3 9, ...
const char* glslTypeName(ValueType type);    // "float", "vec3", "mat3", ...

// One uniform value. Matrices are column-major, as GLSL stores them.
struct Value {
  ValueType type = ValueType::Float;
  std::vector<float> data;
};

// A per-vertex input: `components` floats per vertex, vertices packed.
struct AttributeStream {
  std::string name;
  int components = 4;
  std::vector<float> data;
  std::size_t vertexCount() const { return components ? data.size() / components : 0; }
};

// A per-vertex output read back from a backend: same packing as the input.
struct CapturedVarying {
  std::string name;
  int components = 1;
  std::vector<float> data;
};

using UniformMap = std::map<std::string, Value>;
using AttributeMap = std::map<std::string, AttributeStream>;
using ConstantMap = std::map<std::string, double>;

}  // namespace snell
