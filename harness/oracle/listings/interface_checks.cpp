#include "oracle/listings/interface_checks.h"

#include <fmt/format.h>

#include "core/errors.h"

namespace snell::listings {
namespace {

void checkUniform(const std::string& oracle, const InterfaceEntry& entry,
                  const UniformMap& uniforms) {
  const auto found = uniforms.find(entry.name);
  if (found == uniforms.end()) {
    throw UsageError(fmt::format("oracle '{}': uniform {} {} is not set", oracle,
                                 glslTypeName(entry.type), entry.name));
  }
  const Value& value = found->second;
  if (value.type != entry.type) {
    throw UsageError(fmt::format("oracle '{}': uniform {} is a {}, the listing declares {} {}",
                                 oracle, entry.name, glslTypeName(value.type),
                                 glslTypeName(entry.type), entry.name));
  }
  const auto expected = static_cast<std::size_t>(componentCount(entry.type));
  if (value.data.size() != expected) {
    throw UsageError(fmt::format("oracle '{}': uniform {} {} has {} floats, expected {}", oracle,
                                 glslTypeName(entry.type), entry.name, value.data.size(),
                                 expected));
  }
}

void checkConstant(const std::string& oracle, const InterfaceEntry& entry,
                   const ConstantMap& constants) {
  if (!constants.contains(entry.name)) {
    throw UsageError(fmt::format(
        "oracle '{}': constant {} is not given (the manifest's `constants`)", oracle, entry.name));
  }
}

void checkAttribute(const std::string& oracle, const InterfaceEntry& entry,
                    const AttributeMap& attributes, std::size_t vertexCount) {
  const auto found = attributes.find(entry.name);
  if (found == attributes.end()) {
    throw UsageError(fmt::format("oracle '{}': input {} {} is not bound", oracle,
                                 glslTypeName(entry.type), entry.name));
  }
  const AttributeStream& stream = found->second;
  if (stream.components != componentCount(entry.type)) {
    throw UsageError(fmt::format(
        "oracle '{}': input {} has {} components per vertex, the listing declares {} {}", oracle,
        entry.name, stream.components, glslTypeName(entry.type), entry.name));
  }
  if (stream.vertexCount() < vertexCount) {
    throw UsageError(fmt::format("oracle '{}': input {} has {} vertices, the draw has {}", oracle,
                                 entry.name, stream.vertexCount(), vertexCount));
  }
}

}  // namespace

void checkOracleInput(const std::string& oracle, const std::vector<InterfaceEntry>& interface,
                      const OracleInput& input) {
  for (const InterfaceEntry& entry : interface) {
    switch (entry.kind) {
      case InterfaceEntry::Kind::Uniform:
        checkUniform(oracle, entry, input.uniforms);
        break;
      case InterfaceEntry::Kind::Constant:
        checkConstant(oracle, entry, input.constants);
        break;
      case InterfaceEntry::Kind::Input:
        checkAttribute(oracle, entry, input.attributes, input.vertexCount);
        break;
      case InterfaceEntry::Kind::Output:
        break;
    }
  }
}

}  // namespace snell::listings
