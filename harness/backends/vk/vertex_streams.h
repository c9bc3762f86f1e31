#pragma once
// Pairs a program's live vertex inputs (from reflection) with the job's
// attribute streams, by name, one vertex buffer binding per input.
#include <cstddef>
#include <vector>

#include "backends/vk/glsl_to_spirv.h"
#include "backends/vk/vk_vertex_input.h"
#include "core/values.h"

namespace snell::vk {

struct VertexStreams {
  std::vector<VertexInputFormat> formats;  // what the pipeline is built for
  std::vector<VertexStream> streams;       // what gets copied into the vertex buffer; same order
};

// Attributes the program lacks are ignored. An input with no attribute gets
// the constant (0, 0, 0, 1), as an OpenGL generic attribute nobody set does.
// Throws UsageError for a stream that is too short or malformed, or an input
// snell cannot feed (integer, matrix, array). The streams point into
// `attributes`, which must outlive them.
VertexStreams matchVertexStreams(const std::vector<VertexInput>& inputs,
                                 const AttributeMap& attributes, std::size_t vertexCount);

}  // namespace snell::vk
