#include "baseline/driver_build.h"

#include <fmt/format.h>

namespace snell {
bool namesDriver(const DriverInfo& d) {
  return !d.renderer.empty() || !d.apiVersion.empty() || !d.driverVersion.empty();
}

bool sameDriverBuild(const DriverInfo& a, const DriverInfo& b) {
  if (!namesDriver(a) || !namesDriver(b)) return true;
  return a.renderer == b.renderer && a.apiVersion == b.apiVersion &&
         a.driverVersion == b.driverVersion;
}

std::string driverBuildName(const DriverInfo& driver) {
  return fmt::format("{}, {}, {} {}", driver.driverVersion.empty() ? "?" : driver.driverVersion,
                     driver.renderer.empty() ? "?" : driver.renderer, driver.api,
                     driver.apiVersion);
}

}  // namespace snell
