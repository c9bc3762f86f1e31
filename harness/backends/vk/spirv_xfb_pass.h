#pragma once
// Adds transform feedback capture to a vertex shader's SPIR-V.
//
// glslang rejects xfb_* qualifiers in a `#version 140` shader, and the
// listings must stay as published, so the capture layout is written into the
// SPIR-V after compiling: OpCapability TransformFeedback, OpExecutionMode
// <entry> Xfb, and XfbBuffer 0 / XfbStride / Offset on each captured output.
// Captured outputs are packed tightly, in the order asked for, in buffer 0.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace snell::vk {

struct XfbVarying {
  std::string name;
  int components = 1;        // fp32 components per vertex
  std::uint32_t offset = 0;  // bytes from the start of the vertex's record
};

struct XfbPassResult {
  std::vector<std::uint32_t> spirv;  // the rewritten module; empty on error
  std::vector<XfbVarying> varyings;  // in the order asked for
  std::uint32_t stride = 0;          // bytes per vertex in buffer 0
  std::string error;                 // empty on success
  bool ok() const { return error.empty(); }
};

// Pure function of its inputs; never throws for malformed SPIR-V or bad names.
XfbPassResult addTransformFeedback(std::span<const std::uint32_t> spirv,
                                   std::span<const std::string> varyings);

}  // namespace snell::vk
