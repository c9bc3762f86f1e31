#pragma once
// Which API's precision rules the oracle applies. A backend is judged by its
// own API's rules where they differ (GLSL 4.60 section 4.7.1 for OpenGL, the
// Vulkan environment for SPIR-V, "Precision and Operation of SPIR-V
// Instructions", for Vulkan):
// - normalize is inherited from x / length(x) in GLSL and from
//   x * inversesqrt(dot(x, x)) in Vulkan;
// - Vulkan lets every expression not decorated NoContraction be rearranged
//   with associativity, commutativity and distributivity ("Evaluation of
//   Expressions") and states an inherited built-in's bound as [x - E, x + E];
//   GLSL allows "optimizations that effectively modify the order or number
//   of operations" without `precise` (section 4.9): reassociation,
//   commutation and fused multiply-add, which is what the GLSL rules model,
//   and no distributivity (only ESSL's section 5 names that).
// The rules are a thread-local setting, so a listing's oracle, written once
// as a template, is evaluated under either without a parameter on every
// call.
namespace snell {

enum class PrecisionRules { Glsl, Vulkan };

const char* precisionRulesName(PrecisionRules rules);  // "glsl" / "vulkan"

PrecisionRules currentPrecisionRules();

// Applies `rules` on this thread for the scope's lifetime.
class UsePrecisionRules {
 public:
  explicit UsePrecisionRules(PrecisionRules rules);
  ~UsePrecisionRules();
  UsePrecisionRules(const UsePrecisionRules&) = delete;
  UsePrecisionRules& operator=(const UsePrecisionRules&) = delete;

 private:
  PrecisionRules previous_;
};

}  // namespace snell
