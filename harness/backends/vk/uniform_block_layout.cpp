#include "backends/vk/uniform_block_layout.h"

#include <cstring>

#include "core/errors.h"
#include "core/legacy_builtins.h"

namespace snell::vk {

namespace {

struct Shape {
  int columns = 1;
  int rows = 1;
};

Shape shapeOf(ValueType type) {
  switch (type) {
    case ValueType::Mat3:
      return {3, 3};
    case ValueType::Mat4:
      return {4, 4};
    default:
      return {1, componentCount(type)};
  }
}

}  // namespace

std::size_t matrixColumnStride(BlockPacking packing, int rows) {
  const std::size_t bytes = static_cast<std::size_t>(rows) * sizeof(float);
  // std140 aligns each column like an array element: to a whole vec4.
  // std430 keeps vec2 columns tight but still gives a vec3 column vec4 alignment.
  if (packing == BlockPacking::Std140) return (bytes + 15) / 16 * 16;
  return rows == 3 ? 16 : bytes;
}

void packUniforms(const UniformBlockLayout& layout, const UniformMap& given,
                  std::span<std::byte> block) {
  const UniformMap derived =
      layout.derivesLegacyState ? withDerivedLegacyState(given) : UniformMap{};
  const UniformMap& values = layout.derivesLegacyState ? derived : given;
  for (const BlockMember& member : layout.members) {
    auto found = values.find(member.name);
    if (found == values.end()) continue;
    const Value& value = found->second;
    if (!member.type || *member.type != value.type) {
      throw UsageError("uniform '" + member.name + "' is declared as " + member.declaredType +
                       " but the value given is a " + glslTypeName(value.type));
    }
    if (value.data.size() != static_cast<std::size_t>(componentCount(value.type))) {
      throw UsageError("uniform '" + member.name + "' (" + member.declaredType + ") needs " +
                       std::to_string(componentCount(value.type)) + " floats, got " +
                       std::to_string(value.data.size()));
    }
    const Shape shape = shapeOf(value.type);
    const std::size_t stride =
        shape.columns > 1 ? matrixColumnStride(layout.packing, shape.rows) : 0;
    const std::size_t columnBytes = static_cast<std::size_t>(shape.rows) * sizeof(float);
    const std::size_t footprint =
        stride * static_cast<std::size_t>(shape.columns - 1) + columnBytes;
    if (member.offset + footprint > block.size()) {
      // Only a reflection that disagrees with its own block size gets here.
      throw SetupError("uniform '" + member.name + "' at offset " + std::to_string(member.offset) +
                       " does not fit in a " + std::to_string(block.size()) +
                       "-byte uniform block");
    }
    for (int column = 0; column < shape.columns; ++column) {
      std::memcpy(block.data() + member.offset + stride * static_cast<std::size_t>(column),
                  value.data.data() + column * shape.rows, columnBytes);
    }
  }
}

}  // namespace snell::vk
