#include "oracle/builtin_probe.h"

#include <fmt/format.h>

#include "core/errors.h"
#include "oracle/glsl/glsl.h"

namespace snell {
namespace {

enum class Builtin { Reflect, Refract };

template <class T, int Size>
glsl::vec<T, Size> toVec(const std::vector<float>& values) {
  glsl::vec<T, Size> v;
  for (int k = 0; k < Size; ++k) v[k] = glsl::fromFloat<T>(values[k]);
  return v;
}

template <class T, int Size>
glsl::vec<T, Size> evaluate(Builtin fn, const BuiltinCall& call) {
  const glsl::vec<T, Size> I = toVec<T, Size>(call.I);
  const glsl::vec<T, Size> N = toVec<T, Size>(call.N);
  if (fn == Builtin::Reflect) return glsl::reflect(I, N);
  return glsl::refract(I, N, glsl::fromFloat<T>(call.eta));
}

template <int Size>
BuiltinResult evaluateSized(Builtin fn, const BuiltinCall& call) {
  const auto value = evaluate<double, Size>(fn, call);
  const auto strict = evaluate<float, Size>(fn, call);
  const auto allowed = evaluate<Interval, Size>(fn, call);
  BuiltinResult result;
  for (int k = 0; k < Size; ++k) {
    result.value.push_back(value[k]);
    result.strict.push_back(strict[k]);
    result.lo.push_back(allowed[k].lo);
    result.hi.push_back(allowed[k].hi);
  }
  return result;
}

Builtin parseBuiltin(const std::string& fn) {
  if (fn == "reflect") return Builtin::Reflect;
  if (fn == "refract") return Builtin::Refract;
  throw UsageError(fmt::format("unknown built-in '{}'; known: reflect, refract", fn));
}

}  // namespace

BuiltinResult evaluateBuiltin(const BuiltinCall& call) {
  const Builtin fn = parseBuiltin(call.fn);
  if (call.I.size() != call.N.size()) {
    throw UsageError(fmt::format("{}: I has {} components and N has {}; they must match", call.fn,
                                 call.I.size(), call.N.size()));
  }
  switch (call.I.size()) {
    case 1:
      return evaluateSized<1>(fn, call);
    case 2:
      return evaluateSized<2>(fn, call);
    case 3:
      return evaluateSized<3>(fn, call);
    case 4:
      return evaluateSized<4>(fn, call);
    default:
      throw UsageError(fmt::format("{}: I and N have {} components; GLSL allows 1 to 4", call.fn,
                                   call.I.size()));
  }
}

}  // namespace snell
