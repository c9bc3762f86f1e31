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

}  // namespace

Digest oracleResultKey(std::string_view identity, const OracleInput& input) {
  ContentHash hash;
  hash.add(std::string_view("snell oracle result"));
  hash.add(kStoredResultFormat);
  hash.add(identity);
  hash.add(input.rules);
  hash.add(static_cast<std::uint64_t>(input.vertexCount));
  hash.add(static_cast<std::uint64_t>(input.uniforms.size()));
  for (const auto& [name, value] : input.uniforms) {
    hash.add(name);
    hash.add(value.type);
    addArray(hash, value.data);
  }
  hash.add(static_cast<std::uint64_t>(input.constants.size()));
  for (const auto& [name, value] : input.constants) {
    hash.add(name);
    hash.add(value);
  }
  hash.add(static_cast<std::uint64_t>(input.attributes.size()));
  for (const auto& [name, stream] : input.attributes) {
    hash.add(name);
    hash.add(stream.name);
    hash.add(stream.components);
    addArray(hash, stream.data);
  }
  return hash.finish();
}

}  // namespace snell
