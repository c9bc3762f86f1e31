// A vertex input takes the shape the listing declares: `in vec3 aPos` bound
// to the vec4 scene.position gets x, y, z of each vertex (LearnOpenGL's and
// three.js's position), so backends and oracles read the same values.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/case.h"
#include "core/manifest.h"

namespace snell {
namespace {

namespace fs = std::filesystem;

class InputShape : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("snell-input-shape-" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    std::ofstream(dir_ / "a.vert") << R"(#version 330 core
layout (location = 0) in vec3 aPos;
in vec4 full;
attribute vec2 flat2;
in float first;
in vec3 aNormal;
out vec3 P;
void main() { P = aPos + full.xyz + vec3(flat2, first) + aNormal; gl_Position = vec4(P, 1.0); }
)";
    std::ofstream(dir_ / "manifest.toml") << R"(id = "x/shape"
title = "t"
source = { file = "f.txt", where = "here" }
stages = { vertex = "a.vert" }
[inputs]
aPos = "scene.position"
full = "scene.position"
flat2 = "scene.position"
first = "scene.position"
aNormal = "scene.normal"
[capture]
vertex = ["P"]
[[case]]
scene = "sphere"
)";
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(InputShape, TheDeclaredTypeDecidesTheComponents) {
  const Scene scene = makeScene("sphere");
  const ResolvedBindings b = resolveBindings(loadManifest(dir_ / "manifest.toml"), scene);
  const AttributeStream& position = scene.attributes.at("position");
  ASSERT_EQ(position.components, 4);
  const struct {
    const char* name;
    int components;
  } expected[] = {{"aPos", 3}, {"full", 4}, {"flat2", 2}, {"first", 1}};
  for (const auto& e : expected) {
    const AttributeStream& s = b.attributes.at(e.name);
    ASSERT_EQ(s.components, e.components) << e.name;
    ASSERT_EQ(s.vertexCount(), scene.vertexCount) << e.name;
    for (std::size_t v = 0; v < scene.vertexCount; ++v)
      for (int c = 0; c < e.components; ++c)
        ASSERT_EQ(s.data[v * e.components + c], position.data[v * 4 + c])
            << e.name << " vertex " << v << " component " << c;
  }
  // A stream already of the declared shape is passed as it is.
  EXPECT_EQ(b.attributes.at("aNormal").data, scene.attributes.at("normal").data);
}

}  // namespace
}  // namespace snell
