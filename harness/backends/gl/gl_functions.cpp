#include <string>

#include "backends/gl/gl_api.h"
#include "core/errors.h"

namespace snell {

const GlFunctions* currentGlFunctions = nullptr;

GlFunctions loadGlFunctions(GlProcLookup lookup, void* userData, const char* providerName) {
  GlFunctions table;
#define SNELL_GL_LOAD(name)                                                                 \
  table.name##_ = reinterpret_cast<decltype(table.name##_)>(lookup(#name, userData));       \
  if (!table.name##_)                                                                       \
    throw SetupError(std::string(providerName) +                                            \
                     " has no GL entry point " #name                                        \
                     ": the driver offers less than OpenGL 3.3 core, or the wrong library " \
                     "was loaded.");
  SNELL_GL_FUNCTIONS(SNELL_GL_LOAD)
#undef SNELL_GL_LOAD
  return table;
}

}  // namespace snell
