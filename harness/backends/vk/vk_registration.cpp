// The Vulkan backends: lavapipe (the default, whose goldens are blessed)
// and whatever other ICD the loader finds.
#include "backends/backend_registry.h"
#include "backends/vk/vk_backend.h"
#include "backends/vk/vk_device.h"

namespace snell {

namespace {
BackendCapabilities vulkan() {
  BackendCapabilities can;
  can.api = "Vulkan";
  can.coreVersion = 11;             // VK_EXT_transform_feedback on Vulkan 1.1 is what captures need
  can.glslVersion = 0;              // glslang compiles any version the listing states
  can.compatibilityProfile = true;  // through the legacy adapter (core/legacy_adapter.h)
  can.captures = {"transform-feedback", "fragment-probes"};
  return can;
}
}  // namespace

std::vector<BackendEntry> vkBackendEntries() {
  BackendEntry lavapipe;
  lavapipe.name = "vk";
  lavapipe.description = "Vulkan on lavapipe (or the ICD VK_DRIVER_FILES names)";
  lavapipe.family = "vk";
  lavapipe.capabilities = vulkan();
  lavapipe.goldenKey = "vk";
  lavapipe.takesDevice = true;
  lavapipe.make = [](const BackendEntry& entry, const BackendOptions& options) {
    return makeVkBackend(entry.name, true, options.device, options);
  };

  BackendEntry gpu = lavapipe;
  gpu.name = "vk:gpu";
  gpu.description = "Vulkan on the first GPU any installed ICD offers (or --device)";
  gpu.goldenKey = "vk-gpu";
  gpu.make = [](const BackendEntry& entry, const BackendOptions& options) {
    return makeVkBackend(entry.name, false, options.device.empty() ? "gpu" : options.device,
                         options);
  };
  return {lavapipe, gpu};
}

}  // namespace snell

namespace snell {

std::vector<DeviceListing> vkDeviceListing() {
  std::vector<DeviceListing> out;
  try {
    for (const vk::PhysicalDeviceSummary& d : vk::listPhysicalDevices())
      out.push_back({"Vulkan", d.index, d.name, d.detail});
  } catch (const std::exception& error) {
    out.push_back({"Vulkan", -1, "(none)", error.what()});
  }
  return out;
}

}  // namespace snell
