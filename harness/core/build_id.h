#pragma once
// The GNU build ID (NT_GNU_BUILD_ID, the linker's hash of an executable's
// or a shared library's contents) of loaded code: the same for two builds
// of the same code, different after any change. Files that only that code
// may read back (stored oracle results) are keyed by it.
#include <string>

namespace snell {

// The build ID of the loaded object (the executable or a shared library)
// whose segments hold `address`, as lowercase hex; empty when that object
// carries none (linked without --build-id) or no object holds the address.
std::string buildIdContaining(const void* address);

}  // namespace snell
