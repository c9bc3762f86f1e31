#include "backends/vk/vertex_streams.h"

#include <array>

#include "core/errors.h"

namespace snell::vk {

namespace {
constexpr std::array<float, 4> kUnsetAttribute = {0.0f, 0.0f, 0.0f, 1.0f};
}

VertexStreams matchVertexStreams(const std::vector<VertexInput>& inputs,
                                 const AttributeMap& attributes, std::size_t vertexCount) {
  VertexStreams result;
  for (const VertexInput& input : inputs) {
    if (input.components == 0) {
      throw UsageError("vertex input '" + input.name + "' is " + input.declaredType +
                       "; only float scalar and vector inputs can be fed");
    }
    auto found = attributes.find(input.name);
    if (found == attributes.end()) {
      result.formats.push_back({input.location, 4, true});
      result.streams.push_back({kUnsetAttribute, 4, true});
      continue;
    }
    const AttributeStream& attribute = found->second;
    if (attribute.components < 1 || attribute.components > 4) {
      throw UsageError("attribute '" + input.name + "' has " +
                       std::to_string(attribute.components) +
                       " components per vertex; 1 to 4 are allowed");
    }
    const auto components = static_cast<std::size_t>(attribute.components);
    if (attribute.data.size() % components != 0) {
      throw UsageError("attribute '" + input.name + "' has " +
                       std::to_string(attribute.data.size()) + " floats, not a multiple of its " +
                       std::to_string(components) + " components");
    }
    if (attribute.vertexCount() < vertexCount) {
      throw UsageError("attribute '" + input.name + "' has " +
                       std::to_string(attribute.vertexCount()) + " vertices; the job needs " +
                       std::to_string(vertexCount));
    }
    const auto count = static_cast<std::uint32_t>(components);
    result.formats.push_back({input.location, count, false});
    result.streams.push_back(
        {std::span<const float>(attribute.data).first(vertexCount * components), count, false});
  }
  return result;
}

}  // namespace snell::vk
