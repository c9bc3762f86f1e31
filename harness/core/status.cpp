#include "core/status.h"

namespace snell {

const char* statusName(Status status) {
  switch (status) {
    case Status::Pass: return "Pass";
    case Status::NotSupported: return "NotSupported";
    case Status::CompatibilityWarning: return "CompatibilityWarning";
    case Status::QualityWarning: return "QualityWarning";
    case Status::ExpectedCompileError: return "ExpectedCompileError";
    case Status::Fail: return "Fail";
    case Status::CompileError: return "CompileError";
    case Status::Timeout: return "Timeout";
    case Status::Crash: return "Crash";
  }
  return "?";
}

std::optional<Status> statusFromName(const std::string& name) {
  for (int k = 0; k <= static_cast<int>(Status::Crash); ++k)
    if (name == statusName(static_cast<Status>(k))) return static_cast<Status>(k);
  return std::nullopt;
}

Status worstOf(Status a, Status b) { return static_cast<int>(a) >= static_cast<int>(b) ? a : b; }

bool isFailure(Status status) { return static_cast<int>(status) >= static_cast<int>(Status::Fail); }

}  // namespace snell
