#include "compare/image_library.h"

#include <fmt/format.h>
#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>

#include "core/build_id.h"
#include "core/errors.h"
#include "core/shared_library.h"

namespace snell {
namespace {

constexpr const char* kFileName = "libsnell_image_library.so";

}  // namespace

const SnellImageLibraryFunctions& openImageLibrary(const std::vector<std::string>& candidates) {
  // A module that is there but does not load (a library it needs is
  // missing, or memory is short: ulimit -v) is not fixed by building it.
  bool present = false;
  for (const std::string& candidate : candidates)
    present = present || std::filesystem::is_regular_file(candidate);
  const SharedLibrary library = SharedLibrary::open(
      candidates,
      present ? "snell reads, writes and compares images through this module, which is there but "
                "does not load: `ldd` on it names a library it lacks; a memory limit (ulimit -v) "
                "can also keep its libraries from mapping."
              : "snell reads, writes and compares images through this module: build it (cmake "
                "--build build --target snell_image_library), or set SNELL_IMAGE_LIBRARY to its "
                "path.");
  const auto entry = reinterpret_cast<SnellImageLibraryEntryPoint>(
      library.symbol(SNELL_IMAGE_LIBRARY_ENTRY_POINT));
  if (!entry)
    throw SetupError(fmt::format("{} has no {}() entry point: it is not snell's image module",
                                 library.fileName(), SNELL_IMAGE_LIBRARY_ENTRY_POINT));
  const SnellImageLibraryFunctions* functions = entry();
  if (!functions || functions->abi != SNELL_IMAGE_LIBRARY_ABI)
    throw SetupError(fmt::format(
        "{} speaks image module interface {}, this snell needs {}: rebuild snell_image_library",
        library.fileName(), functions ? functions->abi : 0, SNELL_IMAGE_LIBRARY_ABI));
  return *functions;
}

std::vector<std::string> imageLibraryCandidates() {
  const char* override = std::getenv("SNELL_IMAGE_LIBRARY");
  if (override && *override) return {override};
  std::vector<std::string> candidates = {SNELL_IMAGE_LIBRARY_PATH};
  std::error_code error;
  const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) candidates.push_back((executable.parent_path() / kFileName).string());
  return candidates;
}

void requireImageLibraryFile() {
  const std::vector<std::string> candidates = imageLibraryCandidates();
  for (const std::string& candidate : candidates)
    if (std::filesystem::is_regular_file(candidate)) return;
  std::string tried;
  for (const std::string& candidate : candidates) tried += "\n  " + candidate;
  throw SetupError(fmt::format(
      "the image cases need snell's image module, and none of these files exists:{}\n"
      "build it (cmake --build build --target snell_image_library), set SNELL_IMAGE_LIBRARY "
      "to its path, or leave the image cases out (--filter, or a skip list given with "
      "--expectations)",
      tried));
}

const std::string& imageWriterIdentity() {
  static const std::string identity = [] {
    std::string text = "snell " + buildIdContaining(reinterpret_cast<const void*>(&imageLibrary));
    for (const std::string& candidate : imageLibraryCandidates()) {
      struct stat info {};
      if (::stat(candidate.c_str(), &info) != 0) continue;
      return fmt::format("{} module {} {} {}.{}", text, candidate, info.st_size,
                         info.st_mtim.tv_sec, info.st_mtim.tv_nsec);
    }
    return text + " no module";
  }();
  return identity;
}

const SnellImageLibraryFunctions& imageLibrary() {
  // A function-local static is initialised once, under a lock, and again on
  // the next call if opening threw.
  static const SnellImageLibraryFunctions& functions = openImageLibrary(imageLibraryCandidates());
  return functions;
}

}  // namespace snell
