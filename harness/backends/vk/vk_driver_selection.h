#pragma once
// Which Vulkan driver (ICD) the loader may use. snell's goldens are made on
// lavapipe, so it is the default; a user who sets VK_DRIVER_FILES or the
// older VK_ICD_FILENAMES gets exactly the driver they named.
#include <string>

namespace snell::vk {

inline constexpr const char* kLavapipeManifest = "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json";

// Sets VK_DRIVER_FILES to lavapipe's manifest when neither variable is set
// and the manifest exists. Must run before the instance is created.
void selectLavapipeUnlessOverridden();

// "VK_DRIVER_FILES=..." or similar, for error messages.
std::string describeDriverSelection();

}  // namespace snell::vk
