// loadManifest reads a file, so each input is written to one temp file per
// process. Every problem with a manifest must be a UsageError.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>

#include "core/errors.h"
#include "core/manifest.h"

namespace {

struct TempFile {
  std::filesystem::path path = std::filesystem::temp_directory_path() /
                               ("snell-fuzz-manifest-" + std::to_string(getpid()) + ".toml");
  ~TempFile() {
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static TempFile file;
  {
    std::ofstream out(file.path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    snell::loadManifest(file.path);
  } catch (const snell::UsageError&) {
  }
  return 0;
}
