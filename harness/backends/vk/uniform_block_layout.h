#pragma once
// Where each loose uniform of a `#version 140` listing lives inside
// gl_DefaultUniformBlock, and how to write a UniformMap into that block's
// bytes. The offsets come from glslang's reflection (see glsl_to_spirv.h);
// nothing here assumes an order or an offset.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/values.h"

namespace snell::vk {

enum class BlockPacking { Std140, Std430 };

struct BlockMember {
  std::string name;
  std::size_t offset = 0;
  std::optional<ValueType> type;  // nullopt: a type snell cannot bind (int, bool, array, struct)
  std::string declaredType;       // as the program declares it, for messages
};

struct UniformBlockLayout {
  BlockPacking packing = BlockPacking::Std140;
  std::size_t size = 0;  // bytes, as reflected
  std::vector<BlockMember> members;
  // A legacy listing's block (core/legacy_adapter.h): members named
  // gl_NormalMatrix and gl_ModelViewProjectionMatrix are computed from the
  // given gl_ModelViewMatrix and gl_ProjectionMatrix as GL derives them
  // (core/legacy_builtins.h), never taken from the values.
  bool derivesLegacyState = false;
};

// Bytes between consecutive columns of a float matrix whose columns hold `rows` floats.
std::size_t matrixColumnStride(BlockPacking packing, int rows);

// Writes every value whose name the block has into `block` (block.size()
// must be layout.size); members without a value are left as they are, and
// values the block lacks are ignored (a legacy block first adds GL's
// derived state, see derivesLegacyState). Throws UsageError naming the uniform
// when a value's type or length does not match the declaration.
void packUniforms(const UniformBlockLayout& layout, const UniformMap& values,
                  std::span<std::byte> block);

}  // namespace snell::vk
