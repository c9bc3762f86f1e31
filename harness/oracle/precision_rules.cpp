#include "oracle/precision_rules.h"

namespace snell {
namespace {

thread_local PrecisionRules tCurrent = PrecisionRules::Glsl;

}  // namespace

const char* precisionRulesName(PrecisionRules rules) {
  return rules == PrecisionRules::Vulkan ? "vulkan" : "glsl";
}

PrecisionRules currentPrecisionRules() { return tCurrent; }

UsePrecisionRules::UsePrecisionRules(PrecisionRules rules) : previous_(tCurrent) {
  tCurrent = rules;
}

UsePrecisionRules::~UsePrecisionRules() { tCurrent = previous_; }

}  // namespace snell
