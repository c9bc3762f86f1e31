#pragma once
// deqp-runner's results.csv: `name,status,duration` per line, so Mesa CI's
// tooling reads a snell run. The name is `backend/case`; the status is the
// baseline outcome where it says more than the status (ExpectedFail, Flake,
// KnownFlake, UnexpectedPass), else snell's status.
#include <string>

#include "baseline/baseline_judgement.h"

namespace snell {

std::string toResultsCsv(const BaselineReport& report);

}  // namespace snell
