#include "backends/vk/vk_validation_log.h"

#include <utility>

#include "core/errors.h"

namespace snell::vk {

void ValidationLog::record(std::string message) {
  std::lock_guard lock(mutex_);
  messages_.push_back(std::move(message));
}

std::vector<std::string> ValidationLog::take() {
  std::lock_guard lock(mutex_);
  return std::exchange(messages_, {});
}

void ValidationLog::throwIfAny(const std::string& during, const std::string& failure) {
  const std::vector<std::string> messages = take();
  if (messages.empty()) return;
  std::string text = "Vulkan validation reported " + std::to_string(messages.size()) +
                     " message(s) during " + during + ":";
  for (const std::string& message : messages) text += "\n  " + message;
  if (!failure.empty()) text += "\nand the call failed: " + failure;
  throw SetupError(text);
}

}  // namespace snell::vk
