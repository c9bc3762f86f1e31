// The validation plumbing must be able to fail: these tests provoke a real
// validation error and check that it comes back as a SetupError. Without
// them, "no validation message appeared" in the other tests would prove nothing.
#include <gtest/gtest.h>

#include "backends/vk/vk_device.h"
#include "backends/vk/vk_instance.h"
#include "backends/vk/vk_validation_log.h"
#include "core/errors.h"

namespace snell::vk {
namespace {

TEST(VkValidation, LogQuotesEveryMessageOnceThenEmpties) {
  ValidationLog log;
  EXPECT_NO_THROW(log.throwIfAny("nothing"));
  log.record("error: first");
  log.record("warning: second");
  try {
    log.throwIfAny("the test");
    FAIL() << "recorded messages did not throw";
  } catch (const SetupError& error) {
    const std::string text = error.what();
    EXPECT_NE(text.find("2 message(s) during the test"), std::string::npos) << text;
    EXPECT_NE(text.find("error: first"), std::string::npos) << text;
    EXPECT_NE(text.find("warning: second"), std::string::npos) << text;
  }
  EXPECT_NO_THROW(log.throwIfAny("after"));

  log.record("error: third");
  try {
    log.throwIfAny("a failing call", "vkQueueSubmit failed: VK_ERROR_DEVICE_LOST");
    FAIL() << "a recorded message did not throw";
  } catch (const SetupError& error) {
    const std::string text = error.what();
    EXPECT_NE(text.find("error: third"), std::string::npos) << text;
    EXPECT_NE(text.find("and the call failed: vkQueueSubmit failed: VK_ERROR_DEVICE_LOST"),
              std::string::npos)
        << text;
  }
}

TEST(VkValidation, AnInvalidCallBecomesASetupErrorQuotingTheLayer) {
  VulkanInstance instance(true);
  VulkanDevice device(instance, "");
  ASSERT_NO_THROW(instance.validationLog().throwIfAny("start-up"));

  // A zero-sized buffer breaks VUID-VkBufferCreateInfo-size-00912; the layer
  // reports it and does not pass the call on to the driver.
  VkBufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  info.size = 0;
  info.usage = VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  const VkResult result = vkCreateBuffer(device.handle(), &info, nullptr, &buffer);
  if (result == VK_SUCCESS) vkDestroyBuffer(device.handle(), buffer, nullptr);
  try {
    instance.validationLog().throwIfAny("vkCreateBuffer");
    FAIL() << "the validation layer said nothing about a zero-sized buffer";
  } catch (const SetupError& error) {
    EXPECT_NE(std::string(error.what()).find("VUID-VkBufferCreateInfo-size-00912"),
              std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace snell::vk
