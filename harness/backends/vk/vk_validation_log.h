#pragma once
// Collects what the validation layer says. Any message at warning level or
// above means snell used Vulkan wrongly (or the driver did), so the backend
// turns the messages gathered during a call into a SetupError at the end of
// that call rather than letting them scroll past on stderr.
#include <mutex>
#include <string>
#include <vector>

namespace snell::vk {

class ValidationLog {
 public:
  // Thread-safe: the layer may call back from any thread that makes Vulkan calls.
  void record(std::string message);
  std::vector<std::string> take();

  // Throws SetupError quoting every message recorded since the last take,
  // saying which backend call they came from and, when that call failed
  // anyway, how (`failure`).
  void throwIfAny(const std::string& during, const std::string& failure = {});

 private:
  std::mutex mutex_;
  std::vector<std::string> messages_;
};

}  // namespace snell::vk
