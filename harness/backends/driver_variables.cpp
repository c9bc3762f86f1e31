#include "backends/driver_variables.h"

#include <fmt/format.h>
#include <stdlib.h>

#include <map>
#include <mutex>

namespace snell {
namespace {

std::mutex tSetByMutex;
std::map<std::string, std::string>& setByName() {
  static std::map<std::string, std::string> setBy;
  return setBy;
}

}  // namespace

void setDriverVariable(const std::string& backend, const std::string& name,
                       const std::string& value) {
  const std::lock_guard<std::mutex> lock(tSetByMutex);
  ::setenv(name.c_str(), value.c_str(), 1);
  setByName()[name] = backend;
}

std::string driverVariableSetBy(const std::string& name) {
  const std::lock_guard<std::mutex> lock(tSetByMutex);
  const auto found = setByName().find(name);
  return found == setByName().end() ? "" : found->second;
}

std::string whyNotAtNativeVectorWidth(const std::string& backend, const std::string& driver,
                                      const std::string& renderer, const std::string& width,
                                      const std::string& setBy, const std::string& alternative) {
  const std::string head = fmt::format(
      "{} is {} at its native vector width, and LP_NATIVE_VECTOR_WIDTH={}", backend, driver, width);
  if (!setBy.empty())
    return fmt::format(
        "{}, which {} set for its own driver earlier in this process, reached it ({}): run {} in "
        "a command of its own",
        head, setBy, renderer, backend);
  return fmt::format(
      "{} is set in the environment ({}): unset it{}", head, renderer,
      alternative.empty()
          ? std::string()
          : fmt::format(", or run the backend named for that width ({})", alternative));
}

}  // namespace snell
