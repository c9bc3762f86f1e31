#include "core/shared_library.h"

#include <dlfcn.h>

#include "core/errors.h"

namespace snell {

SharedLibrary SharedLibrary::open(const std::vector<std::string>& fileNames,
                                  const std::string& installHint) {
  std::string errors;
  for (const std::string& name : fileNames) {
    if (void* handle = dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL)) return {handle, name};
    const char* error = dlerror();
    errors += std::string(errors.empty() ? "" : "; ") + (error ? error : name);
  }
  throw SetupError("cannot load " + fileNames.front() + " (" + errors + "). " + installHint);
}

void* SharedLibrary::symbol(const char* name) const { return dlsym(handle_, name); }

}  // namespace snell
