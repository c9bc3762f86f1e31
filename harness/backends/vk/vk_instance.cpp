#include "backends/vk/vk_instance.h"

#include <algorithm>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "backends/vk/vk_check.h"
#include "backends/vk/vk_driver_selection.h"
#include "core/errors.h"

namespace snell::vk {

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

VKAPI_ATTR VkBool32 VKAPI_CALL onDebugMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                              VkDebugUtilsMessageTypeFlagsEXT,
                                              const VkDebugUtilsMessengerCallbackDataEXT* data,
                                              void* log) {
  const char* level =
      severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error" : "warning";
  static_cast<ValidationLog*>(log)->record(std::string(level) + ": " +
                                           (data && data->pMessage ? data->pMessage : "(no text)"));
  return VK_FALSE;  // the call itself goes on; the backend reports at the end of it
}

VkDebugUtilsMessengerCreateInfoEXT messengerInfo(ValidationLog& log) {
  VkDebugUtilsMessengerCreateInfoEXT info{};
  info.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
  info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                         VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  info.pfnUserCallback = onDebugMessage;
  info.pUserData = &log;
  return info;
}

bool hasLayer(const char* name) {
  std::uint32_t count = 0;
  if (vkEnumerateInstanceLayerProperties(&count, nullptr) != VK_SUCCESS) return false;
  std::vector<VkLayerProperties> layers(count);
  if (vkEnumerateInstanceLayerProperties(&count, layers.data()) != VK_SUCCESS) return false;
  return std::any_of(layers.begin(), layers.begin() + count, [&](const VkLayerProperties& layer) {
    return std::strcmp(layer.layerName, name) == 0;
  });
}

std::string noDriverHint() {
  return "no usable Vulkan driver (" + describeDriverSelection() +
         "): install mesa-vulkan-drivers for lavapipe, or set VK_DRIVER_FILES to your driver's ICD "
         "JSON file";
}

}  // namespace

VulkanInstance::VulkanInstance(bool validation, bool lavapipeByDefault) {
  if (lavapipeByDefault) selectLavapipeUnlessOverridden();

  std::uint32_t loaderVersion = VK_API_VERSION_1_0;
  if (vkEnumerateInstanceVersion(&loaderVersion) != VK_SUCCESS ||
      loaderVersion < VK_API_VERSION_1_1) {
    throw SetupError("the Vulkan loader is older than 1.1: install a newer libvulkan1");
  }
  apiVersion_ = std::min<std::uint32_t>(loaderVersion, VK_API_VERSION_1_3);

  std::vector<const char*> layers;
  std::vector<const char*> extensions;
  if (validation) {
    if (!hasLayer(kValidationLayer)) {
      throw SetupError(
          std::string("Vulkan validation was asked for but ") + kValidationLayer +
          " is not installed: install vulkan-validationlayers (or run without validation)");
    }
    layers.push_back(kValidationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  }

  VkApplicationInfo app{};
  app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
  app.pApplicationName = "snell";
  app.pEngineName = "snell";
  app.apiVersion = apiVersion_;

  // Chained into the create info so that instance creation itself is validated too.
  const VkDebugUtilsMessengerCreateInfoEXT debugInfo = messengerInfo(log_);
  VkInstanceCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
  info.pNext = validation ? &debugInfo : nullptr;
  info.pApplicationInfo = &app;
  info.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();

  const VkResult created = vkCreateInstance(&info, nullptr, &instance_);
  if (created == VK_ERROR_INCOMPATIBLE_DRIVER)
    throw SetupError("vkCreateInstance: " + noDriverHint());
  if (created == VK_ERROR_EXTENSION_NOT_PRESENT) {
    throw SetupError(
        "vkCreateInstance: VK_EXT_debug_utils is missing: install vulkan-validationlayers");
  }
  if (created != VK_SUCCESS) {
    throw SetupError("vkCreateInstance failed (" + resultName(created) + "): " + noDriverHint());
  }

  if (validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
    const VkResult made = create ? create(instance_, &debugInfo, nullptr, &messenger_)
                                 : VK_ERROR_EXTENSION_NOT_PRESENT;
    if (made != VK_SUCCESS) {
      vkDestroyInstance(instance_, nullptr);
      throw SetupError("cannot create the Vulkan debug messenger (" + resultName(made) +
                       "): install vulkan-validationlayers");
    }
  }
}

VulkanInstance::~VulkanInstance() {
  // Messages from tearing down (leaked objects, say) have no call to be
  // thrown from; stderr is the only place left to say them.
  for (const std::string& message : log_.take()) {
    std::cerr << "snell: Vulkan validation at shutdown: " << message << "\n";
  }
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance_, messenger_, nullptr);
  }
  vkDestroyInstance(instance_, nullptr);
}

}  // namespace snell::vk
