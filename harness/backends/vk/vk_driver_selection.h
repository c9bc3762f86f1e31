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

// Why `backend` does not come up on `renderer` when the environment sets
// LP_NATIVE_VECTOR_WIDTH (`vectorWidth`, null when unset): lavapipe at
// another width is another driver than the one vk's goldens were blessed
// on, as llvmpipe's is for gl. "" when it may.
std::string whyNotLavapipeAtItsNativeWidth(const std::string& backend, const std::string& renderer,
                                           const char* vectorWidth);

}  // namespace snell::vk
