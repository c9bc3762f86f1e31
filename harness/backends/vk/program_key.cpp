#include "backends/vk/program_key.h"

namespace snell::vk {

void appendKeyField(std::string& key, const std::string& field) {
  key += std::to_string(field.size());
  key += ':';
  key += field;
}

std::string programKey(const ProgramSource& source) {
  std::string key;
  key.reserve(source.vertex.size() + source.fragment.size() + 128);
  key += source.profile == Profile::Core ? "core;" : "compatibility;";
  appendKeyField(key, source.vertex);
  appendKeyField(key, source.fragment);
  // Paths appear in the compile log, so they belong in the key too.
  appendKeyField(key, source.vertexPath);
  appendKeyField(key, source.fragmentPath);
  return key;
}

}  // namespace snell::vk
