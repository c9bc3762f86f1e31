#pragma once
// Case statuses after dEQP. A case's status is the worst of its checks.
#include <optional>
#include <string>

namespace snell {

// Declared from best to worst: worstOf() relies on the order.
enum class Status {
  Pass,
  NotSupported,
  CompatibilityWarning,
  QualityWarning,
  ExpectedCompileError,  // a listing that must not compile, and did not
  Fail,
  CompileError,          // a listing that should compile, and did not
  Timeout,
  Crash,
};

const char* statusName(Status status);
// The inverse of statusName; nullopt for a name that is no status.
std::optional<Status> statusFromName(const std::string& name);
Status worstOf(Status a, Status b);
// Whether a status makes `snell run` exit 1.
bool isFailure(Status status);

}  // namespace snell
