#pragma once
// Cache keys for compiled programs and what is built from them.
#include <string>

#include "backends/backend.h"

namespace snell::vk {

// Appends `field` so that no two different sequences of fields give one key.
void appendKeyField(std::string& key, const std::string& field);

// Differs whenever two sources could compile, or log, differently.
std::string programKey(const ProgramSource& source);

}  // namespace snell::vk
