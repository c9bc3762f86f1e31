#include "cli/commands.h"

namespace snell::cli {

std::string defaultShadersDir() { return SNELL_SOURCE_ROOT "/shaders"; }
std::string defaultGoldenDir() { return SNELL_SOURCE_ROOT "/golden"; }
std::string defaultMethodsDir() { return SNELL_SOURCE_ROOT "/shaders/methods"; }
std::string defaultBenchDir() { return "snell-bench"; }

}  // namespace snell::cli
