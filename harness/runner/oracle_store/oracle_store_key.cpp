#include "runner/oracle_store/oracle_store_key.h"

#include <cstdint>

#include "runner/oracle_store/stored_result_format.h"

namespace snell {
namespace {

template <typename T>
void addArray(ContentHash& hash, const std::vector<T>& values) {
  hash.add(static_cast<std::uint64_t>(values.size()));
  hash.addBytes(values.data(), values.size() * sizeof(T));
}

// What an oracle reads: uniforms, constants and per-invocation inputs.
void addValues(ContentHash& hash, const UniformMap& uniforms, const ConstantMap& constants,
               const AttributeMap& attributes, std::size_t count) {
  hash.add(static_cast<std::uint64_t>(count));
  hash.add(static_cast<std::uint64_t>(uniforms.size()));
  for (const auto& [name, value] : uniforms) {
    hash.add(name);
    hash.add(value.type);
    addArray(hash, value.data);
  }
  hash.add(static_cast<std::uint64_t>(constants.size()));
  for (const auto& [name, value] : constants) {
    hash.add(name);
    hash.add(value);
  }
  hash.add(static_cast<std::uint64_t>(attributes.size()));
  for (const auto& [name, stream] : attributes) {
    hash.add(name);
    hash.add(stream.name);
    hash.add(stream.components);
    addArray(hash, stream.data);
  }
}

// Named images (cube maps, 2D textures), any of them possibly missing: the
// count, then each name, whether it is there, and its own fields.
template <class Map, class AddImage>
void addNamedImages(ContentHash& hash, const Map& images, AddImage addImage) {
  hash.add(static_cast<std::uint64_t>(images.size()));
  for (const auto& [name, image] : images) {
    hash.add(name);
    hash.add(image != nullptr);
    if (image) addImage(*image);
  }
}

}  // namespace

Digest oracleResultKey(std::string_view identity, const OracleInput& input) {
  ContentHash hash;
  hash.add(std::string_view("snell oracle result"));
  hash.add(kStoredResultFormat);
  hash.add(identity);
  hash.add(input.rules);
  addValues(hash, input.uniforms, input.constants, input.attributes, input.vertexCount);
  return hash.finish();
}

Digest referenceImageKey(std::string_view identity, const ReferenceInput& input) {
  ContentHash hash;
  hash.add(std::string_view("snell reference image"));
  hash.add(kStoredResultFormat);
  hash.add(identity);
  hash.add(std::string_view(input.oracle));
  addValues(hash, input.uniforms, input.constants, input.attributes, input.vertexCount);
  addArray(hash, input.indices);
  addNamedImages(hash, input.cubeMaps, [&](const auto& cube) {
    hash.add(cube.size);
    hash.add(cube.filter);
    hash.add(cube.seamless);
    for (const std::vector<float>& face : cube.faces) addArray(hash, face);
  });
  hash.add(input.width);
  hash.add(input.height);
  for (float c : input.clearColor) hash.add(c);
  hash.add(input.cullBackFaces);
  addNamedImages(hash, input.textures2D, [&](const auto& image) {
    hash.add(image.width);
    hash.add(image.height);
    addArray(hash, image.pixels);
  });
  return hash.finish();
}

}  // namespace snell
