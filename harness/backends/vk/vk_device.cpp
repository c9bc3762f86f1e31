#include "backends/vk/vk_device.h"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "backends/vk/vk_check.h"
#include "backends/vk/vk_driver_selection.h"
#include "core/errors.h"

namespace snell::vk {

namespace {

bool hasExtension(VkPhysicalDevice device, const char* name) {
  std::uint32_t count = 0;
  if (vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr) != VK_SUCCESS)
    return false;
  std::vector<VkExtensionProperties> extensions(count);
  if (vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data()) !=
      VK_SUCCESS)
    return false;
  for (std::uint32_t i = 0; i < count; ++i) {
    if (std::strcmp(extensions[i].extensionName, name) == 0) return true;
  }
  return false;
}

std::optional<std::uint32_t> graphicsQueueFamily(VkPhysicalDevice device) {
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
  for (std::uint32_t i = 0; i < count; ++i) {
    if (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) return i;
  }
  return std::nullopt;
}

bool hasTransformFeedbackFeature(VkPhysicalDevice device) {
  VkPhysicalDeviceTransformFeedbackFeaturesEXT xfb{};
  xfb.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TRANSFORM_FEEDBACK_FEATURES_EXT;
  VkPhysicalDeviceFeatures2 features{};
  features.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
  features.pNext = &xfb;
  vkGetPhysicalDeviceFeatures2(device, &features);
  return xfb.transformFeedback == VK_TRUE;
}

// Empty when the device can run snell's captures, else what it lacks.
std::string whatIsMissing(VkPhysicalDevice device) {
  VkPhysicalDeviceProperties properties{};
  vkGetPhysicalDeviceProperties(device, &properties);
  if (properties.apiVersion < VK_API_VERSION_1_1) return "Vulkan 1.1";
  if (!hasExtension(device, VK_EXT_TRANSFORM_FEEDBACK_EXTENSION_NAME))
    return VK_EXT_TRANSFORM_FEEDBACK_EXTENSION_NAME;
  if (!hasTransformFeedbackFeature(device)) return "the transformFeedback feature";
  if (!graphicsQueueFamily(device)) return "a graphics queue";
  return {};
}

std::string versionString(std::uint32_t version) {
  return std::to_string(VK_API_VERSION_MAJOR(version)) + "." +
         std::to_string(VK_API_VERSION_MINOR(version)) + "." +
         std::to_string(VK_API_VERSION_PATCH(version));
}

const char* deviceTypeName(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return "integrated-gpu";
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return "discrete-gpu";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return "virtual-gpu";
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return "cpu";
    default:
      return "other";
  }
}

DriverInfo describe(VkPhysicalDevice device,
                    VkPhysicalDeviceTransformFeedbackPropertiesEXT& xfbProperties) {
  const bool hasDriverProperties = [&] {
    VkPhysicalDeviceProperties properties{};
    vkGetPhysicalDeviceProperties(device, &properties);
    return properties.apiVersion >= VK_API_VERSION_1_2 ||
           hasExtension(device, VK_KHR_DRIVER_PROPERTIES_EXTENSION_NAME);
  }();
  VkPhysicalDeviceDriverProperties driver{};
  driver.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES;
  xfbProperties = {};
  xfbProperties.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TRANSFORM_FEEDBACK_PROPERTIES_EXT;
  xfbProperties.pNext = hasDriverProperties ? &driver : nullptr;
  VkPhysicalDeviceProperties2 properties{};
  properties.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2;
  properties.pNext = &xfbProperties;
  vkGetPhysicalDeviceProperties2(device, &properties);

  DriverInfo info;
  info.api = "Vulkan";
  info.apiVersion = versionString(properties.properties.apiVersion);
  info.renderer = properties.properties.deviceName;
  info.deviceType = deviceTypeName(properties.properties.deviceType);
  if (hasDriverProperties) {
    info.driverVersion = std::string(driver.driverName) + " " + driver.driverInfo;
  } else {
    // Without driver properties the only clue is the vendor-encoded number.
    info.driverVersion = "driverVersion " + std::to_string(properties.properties.driverVersion);
  }
  return info;
}

std::string hexFlags(std::uint32_t flags) {
  char text[9];
  std::snprintf(text, sizeof text, "%x", flags);
  return text;
}

// Whether `wanted` (see the constructor) names the device at `index`.
bool matches(const std::string& wanted, std::uint32_t index, const VkPhysicalDeviceProperties& p) {
  if (wanted.empty()) return true;
  if (wanted == "gpu") return p.deviceType != VK_PHYSICAL_DEVICE_TYPE_CPU;
  if (wanted.find_first_not_of("0123456789") == std::string::npos) {
    // A number past any index matches no device (stoul threw on it).
    unsigned long long number = 0;
    const auto parsed = std::from_chars(wanted.data(), wanted.data() + wanted.size(), number);
    return parsed.ec == std::errc() && number == index;
  }
  unsigned vendor = 0, device = 0;
  char rest = 0;
  if (std::sscanf(wanted.c_str(), "%x:%x%c", &vendor, &device, &rest) == 2)
    return vendor == p.vendorID && device == p.deviceID;
  std::string name = p.deviceName, lowerWanted = wanted;
  for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (char& c : lowerWanted) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return name.find(lowerWanted) != std::string::npos;
}

}  // namespace

std::vector<PhysicalDeviceSummary> listPhysicalDevices() {
  const VulkanInstance instance(false, false);
  std::uint32_t count = 0;
  check(vkEnumeratePhysicalDevices(instance.handle(), &count, nullptr),
        "vkEnumeratePhysicalDevices");
  std::vector<VkPhysicalDevice> devices(count);
  check(vkEnumeratePhysicalDevices(instance.handle(), &count, devices.data()),
        "vkEnumeratePhysicalDevices");
  std::vector<PhysicalDeviceSummary> out;
  for (std::uint32_t i = 0; i < count; ++i) {
    VkPhysicalDeviceTransformFeedbackPropertiesEXT xfb{};
    const DriverInfo info = describe(devices[i], xfb);
    VkPhysicalDeviceProperties properties{};
    vkGetPhysicalDeviceProperties(devices[i], &properties);
    const std::string missing = whatIsMissing(devices[i]);
    out.push_back(
        {static_cast<int>(i), info.renderer,
         fmt::format("{}, {}, Vulkan {}, id {:04x}:{:04x}{}", info.deviceType, info.driverVersion,
                     info.apiVersion, properties.vendorID, properties.deviceID,
                     missing.empty() ? "" : ", cannot capture: lacks " + missing)});
  }
  return out;
}

VulkanDevice::VulkanDevice(const VulkanInstance& instance, const std::string& wanted) {
  std::uint32_t count = 0;
  check(vkEnumeratePhysicalDevices(instance.handle(), &count, nullptr),
        "vkEnumeratePhysicalDevices");
  std::vector<VkPhysicalDevice> devices(count);
  check(vkEnumeratePhysicalDevices(instance.handle(), &count, devices.data()),
        "vkEnumeratePhysicalDevices");
  if (count == 0) {
    throw SetupError("no Vulkan device found (" + describeDriverSelection() +
                     "): install mesa-vulkan-drivers for lavapipe, or set VK_DRIVER_FILES to your "
                     "driver's ICD JSON file");
  }
  std::string rejected, seen;
  for (std::uint32_t i = 0; i < count && !physical_; ++i) {
    VkPhysicalDeviceProperties properties{};
    vkGetPhysicalDeviceProperties(devices[i], &properties);
    seen += fmt::format("{}{}: {} ({:04x}:{:04x})", seen.empty() ? "" : ", ", i,
                        properties.deviceName, properties.vendorID, properties.deviceID);
    if (!matches(wanted, i, properties)) continue;
    const std::string missing = whatIsMissing(devices[i]);
    if (missing.empty()) {
      physical_ = devices[i];
      continue;
    }
    rejected +=
        std::string(rejected.empty() ? "" : "; ") + properties.deviceName + " lacks " + missing;
  }
  if (!physical_ && rejected.empty())
    throw SetupError(fmt::format(
        "no Vulkan device matches {} among {} ({}): pass --device with an "
        "index, a vendor:device id or part of a name (`snell devices`)",
        wanted == "gpu" ? "a GPU" : "--device " + wanted, seen, describeDriverSelection()));
  if (!physical_) {
    throw SetupError("no Vulkan device can capture vertex outputs (" + rejected +
                     "): install mesa-vulkan-drivers (lavapipe has VK_EXT_transform_feedback) or "
                     "set VK_DRIVER_FILES "
                     "to a driver that has it");
  }

  queueFamily_ = *graphicsQueueFamily(physical_);
  VkPhysicalDeviceTransformFeedbackPropertiesEXT xfbProperties{};
  driverInfo_ = describe(physical_, xfbProperties);
  maxXfbStride_ = xfbProperties.maxTransformFeedbackBufferDataStride;
  vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
  VkPhysicalDeviceProperties properties{};
  vkGetPhysicalDeviceProperties(physical_, &properties);
  limits_ = properties.limits;

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queueInfo{};
  queueInfo.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
  queueInfo.queueFamilyIndex = queueFamily_;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;

  VkPhysicalDeviceTransformFeedbackFeaturesEXT xfbFeatures{};
  xfbFeatures.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TRANSFORM_FEEDBACK_FEATURES_EXT;
  xfbFeatures.transformFeedback = VK_TRUE;
  const char* extensions[] = {VK_EXT_TRANSFORM_FEEDBACK_EXTENSION_NAME};
  VkDeviceCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
  info.pNext = &xfbFeatures;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queueInfo;
  info.enabledExtensionCount = 1;
  info.ppEnabledExtensionNames = extensions;
  check(vkCreateDevice(physical_, &info, nullptr, &device_), "vkCreateDevice");
  vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);

  xfb_.bindBuffers = reinterpret_cast<PFN_vkCmdBindTransformFeedbackBuffersEXT>(
      vkGetDeviceProcAddr(device_, "vkCmdBindTransformFeedbackBuffersEXT"));
  xfb_.begin = reinterpret_cast<PFN_vkCmdBeginTransformFeedbackEXT>(
      vkGetDeviceProcAddr(device_, "vkCmdBeginTransformFeedbackEXT"));
  xfb_.end = reinterpret_cast<PFN_vkCmdEndTransformFeedbackEXT>(
      vkGetDeviceProcAddr(device_, "vkCmdEndTransformFeedbackEXT"));
  if (!xfb_.bindBuffers || !xfb_.begin || !xfb_.end) {
    vkDestroyDevice(device_, nullptr);
    throw SetupError(driverInfo_.renderer +
                     " advertises VK_EXT_transform_feedback but lacks its commands");
  }
}

VulkanDevice::~VulkanDevice() {
  vkDeviceWaitIdle(device_);
  vkDestroyDevice(device_, nullptr);
}

std::uint32_t VulkanDevice::memoryType(std::uint32_t typeBits, VkMemoryPropertyFlags required,
                                       VkMemoryPropertyFlags preferred) const {
  std::optional<std::uint32_t> fallback;
  for (std::uint32_t i = 0; i < memory_.memoryTypeCount; ++i) {
    const VkMemoryPropertyFlags flags = memory_.memoryTypes[i].propertyFlags;
    if (!(typeBits & (1u << i)) || (flags & required) != required) continue;
    if ((flags & preferred) == preferred) return i;
    if (!fallback) fallback = i;
  }
  if (fallback) return *fallback;
  throw SetupError(driverInfo_.renderer + " has no memory type with property flags 0x" +
                   hexFlags(required) + " for a resource that accepts types 0x" +
                   hexFlags(typeBits));
}

}  // namespace snell::vk
