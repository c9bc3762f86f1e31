#include "backends/vk/uniform_block_layout.h"

#include <gtest/gtest.h>

#include <cstring>

#include "core/errors.h"

namespace snell::vk {
namespace {

std::vector<float> asFloats(const std::vector<std::byte>& bytes) {
  std::vector<float> floats(bytes.size() / sizeof(float));
  std::memcpy(floats.data(), bytes.data(), floats.size() * sizeof(float));
  return floats;
}

Value make(ValueType type, float first) {
  Value value{type, {}};
  for (int i = 0; i < componentCount(type); ++i)
    value.data.push_back(first + static_cast<float>(i));
  return value;
}

// A layout as glslang reflects `uniform mat3 M; uniform float S; uniform vec3 V;` under std140.
UniformBlockLayout mat3Layout() {
  UniformBlockLayout layout;
  layout.size = 80;
  layout.members = {{"M", 0, ValueType::Mat3, "mat3"},
                    {"S", 48, ValueType::Float, "float"},
                    {"V", 64, ValueType::Vec3, "vec3"}};
  return layout;
}

TEST(VkUniformBlockLayout, Std140Mat3ColumnsAreSixteenBytesApart) {
  EXPECT_EQ(matrixColumnStride(BlockPacking::Std140, 3), 16u);
  EXPECT_EQ(matrixColumnStride(BlockPacking::Std140, 4), 16u);
  EXPECT_EQ(matrixColumnStride(BlockPacking::Std140, 2), 16u);
  EXPECT_EQ(matrixColumnStride(BlockPacking::Std430, 3), 16u);
  EXPECT_EQ(matrixColumnStride(BlockPacking::Std430, 2), 8u);
}

TEST(VkUniformBlockLayout, PacksMatrixColumnsAtTheirStride) {
  const UniformBlockLayout layout = mat3Layout();
  std::vector<std::byte> block(layout.size, std::byte{0});
  packUniforms(layout,
               {{"M", make(ValueType::Mat3, 1)},
                {"S", make(ValueType::Float, 10)},
                {"V", make(ValueType::Vec3, 20)}},
               block);
  const std::vector<float> expected = {1, 2, 3,  0, 4, 5, 6,  0,  7,  8,
                                       9, 0, 10, 0, 0, 0, 20, 21, 22, 0};
  EXPECT_EQ(asFloats(block), expected);
}

TEST(VkUniformBlockLayout, LeavesUnsetMembersAndIgnoresUnknownNames) {
  const UniformBlockLayout layout = mat3Layout();
  std::vector<std::byte> block(layout.size, std::byte{0x7f});
  const std::vector<std::byte> before = block;
  packUniforms(layout, {{"NotInTheProgram", make(ValueType::Mat4, 1)}}, block);
  EXPECT_EQ(block, before);
  packUniforms(layout, {{"S", make(ValueType::Float, 5)}}, block);
  EXPECT_NE(block, before);
  EXPECT_EQ(asFloats(block)[12], 5.0f);
}

TEST(VkUniformBlockLayout, TypeMismatchIsAUsageErrorNamingTheUniform) {
  const UniformBlockLayout layout = mat3Layout();
  std::vector<std::byte> block(layout.size);
  try {
    packUniforms(layout, {{"M", make(ValueType::Mat4, 1)}}, block);
    FAIL() << "a mat4 value for a mat3 uniform was accepted";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("'M'"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("mat3"), std::string::npos) << error.what();
  }
}

TEST(VkUniformBlockLayout, WrongLengthIsAUsageErrorNamingTheUniform) {
  const UniformBlockLayout layout = mat3Layout();
  std::vector<std::byte> block(layout.size);
  Value shortVector{ValueType::Vec3, {1, 2}};
  EXPECT_THROW(packUniforms(layout, {{"V", shortVector}}, block), UsageError);
}

TEST(VkUniformBlockLayout, UnbindableDeclarationsRejectValues) {
  UniformBlockLayout layout;
  layout.size = 16;
  layout.members = {{"Count", 0, std::nullopt, "int"}};
  std::vector<std::byte> block(layout.size);
  try {
    packUniforms(layout, {{"Count", make(ValueType::Float, 1)}}, block);
    FAIL() << "a float value for an int uniform was accepted";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("'Count' is declared as int"), std::string::npos)
        << error.what();
  }
  EXPECT_NO_THROW(packUniforms(layout, {}, block));
}

}  // namespace
}  // namespace snell::vk
