// Under LeakSanitizer (ci/sanitize), lavapipe's process-lifetime allocations
// are reported as leaks from "<unknown module>" once the loader unloads the
// ICD at vkDestroyInstance: the globals that still point at them are gone,
// and a suppression cannot name a module that is no longer there. Keeping
// the library loaded for the whole test process keeps them reachable. It
// changes nothing else: the loader opens the same, already loaded library.
#include <dlfcn.h>

namespace {

[[maybe_unused]] const void* const kLavapipe = dlopen("libvulkan_lvp.so", RTLD_NOW | RTLD_NODELETE);

}  // namespace
