#include "backends/vk/vk_driver_selection.h"

#include <cstdlib>
#include <filesystem>
#include <string>

namespace snell::vk {

void selectLavapipeUnlessOverridden() {
  if (std::getenv("VK_DRIVER_FILES") || std::getenv("VK_ICD_FILENAMES")) return;
  std::error_code ignored;
  if (!std::filesystem::exists(kLavapipeManifest, ignored)) return;
  ::setenv("VK_DRIVER_FILES", kLavapipeManifest, 0);
}

std::string describeDriverSelection() {
  if (const char* files = std::getenv("VK_DRIVER_FILES"))
    return std::string("VK_DRIVER_FILES=") + files;
  if (const char* icds = std::getenv("VK_ICD_FILENAMES"))
    return std::string("VK_ICD_FILENAMES=") + icds;
  std::error_code ignored;
  if (std::filesystem::exists(kLavapipeManifest, ignored)) return "every installed ICD";
  return std::string("VK_DRIVER_FILES unset and ") + kLavapipeManifest + " missing";
}

}  // namespace snell::vk
