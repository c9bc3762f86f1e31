#include "oracle/builtin_probe.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/errors.h"
#include "oracle/branch_paths.h"
#include "oracle/glsl/glsl.h"
#include "oracle/point_builtins.h"

namespace snell {
namespace {

enum class Builtin { Reflect, Refract };

template <class T, int Size>
glsl::vec<T, Size> toVec(const std::vector<float>& values) {
  return glsl::vec<T, Size>(typename glsl::vec<T, Size>::FromEach{},
                            [&](int k) { return glsl::fromFloat<T>(values[k]); });
}

template <class T, int Size>
glsl::vec<T, Size> evaluate(Builtin fn, const BuiltinCall& call) {
  const glsl::vec<T, Size> I = toVec<T, Size>(call.I);
  const glsl::vec<T, Size> N = toVec<T, Size>(call.N);
  if (fn == Builtin::Reflect) return glsl::reflect(I, N);
  return glsl::refract(I, N, glsl::fromFloat<T>(call.eta));
}

// The call's one way from oracle/point_builtins.h, where it answers.
template <int Size>
bool onPoints(Builtin fn, const BuiltinCall& call, const std::vector<bool>& ownPath,
              OracleBuild build, BuiltinResult& result) {
  PointBounds bounds;
  if (fn == Builtin::Reflect) {
    if (!ownPath.empty() ||
        !reflectOnPoints(call.I, call.N, currentPrecisionRules(), bounds, build))
      return false;
  } else {
    PointRefract refract;
    if (ownPath.size() != 1 || !refractOnPoints(call.I, call.N, call.eta, ownPath[0],
                                                currentPrecisionRules(), refract, build))
      return false;
    bounds = refract;
  }
  BuiltinWay way;
  way.value = result.value;
  for (int k = 0; k < Size; ++k) {
    way.lo.push_back(bounds.lo[k]);
    way.hi.push_back(bounds.hi[k]);
    way.undefined.push_back(false);
  }
  result.lo = way.lo;
  result.hi = way.hi;
  result.undefined = way.undefined;
  result.ways.push_back(way);
  return true;
}

// The exact value along the path the double evaluation takes itself (its
// branches recorded in ownPath), and the fp32 evaluation of the formula:
// flattened once per build (oracle/fma_build.h), as the double-double
// steps of the exact value are error-free products.
template <int Size>
struct PointValues {
  glsl::vec<double, Size> value;
  glsl::vec<float, Size> strict;
};
template <int Size>
PointValues<Size> pointValues(Builtin fn, const BuiltinCall& call, std::vector<bool>& ownPath) {
  PointValues<Size> values;
  {
    const RecordBranches recording(ownPath);
    values.value = evaluate<double, Size>(fn, call);
  }
  values.strict = evaluate<float, Size>(fn, call);
  return values;
}
template <int Size>
[[gnu::flatten]] PointValues<Size> pointValuesPortable(Builtin fn, const BuiltinCall& call,
                                                       std::vector<bool>& ownPath) {
  return pointValues<Size>(fn, call, ownPath);
}
#if SNELL_ORACLE_FMA_BUILD
template <int Size>
[[gnu::flatten, gnu::target("fma")]] PointValues<Size> pointValuesFma(Builtin fn,
                                                                      const BuiltinCall& call,
                                                                      std::vector<bool>& ownPath) {
  return pointValues<Size>(fn, call, ownPath);
}
#endif

template <int Size>
BuiltinResult evaluateSized(Builtin fn, const BuiltinCall& call, OracleRoad road,
                            OracleBuild build) {
  thread_local std::vector<bool> ownPath;
  ownPath.clear();
#if SNELL_ORACLE_FMA_BUILD
  const PointValues<Size> values = build == OracleBuild::Fma
                                       ? pointValuesFma<Size>(fn, call, ownPath)
                                       : pointValuesPortable<Size>(fn, call, ownPath);
#else
  const PointValues<Size> values = pointValuesPortable<Size>(fn, call, ownPath);
#endif
  const glsl::vec<double, Size>& value = values.value;
  const glsl::vec<float, Size>& strict = values.strict;
  BuiltinResult result;
  for (int k = 0; k < Size; ++k) {
    result.value.push_back(value[k]);
    result.strict.push_back(strict[k]);
  }
  // Exact inputs: the same bounds by the shorter road where it answers
  // (one way, the exact evaluation's own).
  if (road == OracleRoad::Shortest && onPoints<Size>(fn, call, ownPath, build, result))
    return result;
  // Every way an undecidable branch may go, each with the exact value along
  // it. The explorer is kept per thread: its outcome lists keep their
  // memory from one call to the next. refract's one branch makes at most
  // two ways, far under kMaxBranchPaths: the explorer never merges them
  // into a hull here (and `ways` holds two; a third would throw).
  thread_local BranchPaths paths;
  const UseBranchPaths active(&paths);
  paths.explore([&] {
    const auto allowed = evaluate<Interval, Size>(fn, call);
    // Along the same outcomes the double evaluation is the one made
    // above; along others it is made again, replaying them.
    const auto exact = [&] {
      if (paths.trace() == ownPath) return value;
      BranchReplay replay(paths.trace());
      const UseBranchReplay replaying(&replay);
      return evaluate<double, Size>(fn, call);
    }();
    BuiltinWay way;
    for (int k = 0; k < Size; ++k) {
      way.value.push_back(exact[k]);
      way.lo.push_back(allowed[k].lo);
      way.hi.push_back(allowed[k].hi);
      way.undefined.push_back(allowed[k].undefined);
    }
    result.ways.push_back(way);
  });
  result.lo = result.ways[0].lo;
  result.hi = result.ways[0].hi;
  result.undefined = result.ways[0].undefined;
  for (const BuiltinWay& way : result.ways)
    for (int k = 0; k < Size; ++k) {
      result.lo[k] = std::min(result.lo[k], way.lo[k]);
      result.hi[k] = std::max(result.hi[k], way.hi[k]);
      result.undefined[k] = result.undefined[k] || way.undefined[k];
    }
  return result;
}

bool fits(const BuiltinWay& way, std::span<const float> vector) {
  for (std::size_t k = 0; k < vector.size(); ++k) {
    if (way.undefined[k]) continue;
    if (!(way.lo[k] <= vector[k] && vector[k] <= way.hi[k])) return false;
  }
  return true;
}

// How far outside a way the vector lies, summed over components (0 inside).
double distanceOutside(const BuiltinWay& way, std::span<const float> vector) {
  double distance = 0.0;
  for (std::size_t k = 0; k < vector.size(); ++k) {
    if (way.undefined[k]) continue;
    const double x = vector[k];
    if (std::isnan(x)) return std::numeric_limits<double>::infinity();
    distance += std::max({0.0, way.lo[k] - x, x - way.hi[k]});
  }
  return distance;
}

Builtin parseBuiltin(const std::string& fn) {
  if (fn == "reflect") return Builtin::Reflect;
  if (fn == "refract") return Builtin::Refract;
  throw UsageError(fmt::format("unknown built-in '{}'; known: reflect, refract", fn));
}

}  // namespace

bool BuiltinResult::allows(std::span<const float> vector) const {
  return std::any_of(ways.begin(), ways.end(),
                     [&](const BuiltinWay& way) { return fits(way, vector); });
}

const BuiltinWay& BuiltinResult::nearestWay(std::span<const float> vector) const {
  return *std::min_element(ways.begin(), ways.end(), [&](const BuiltinWay& a, const BuiltinWay& b) {
    return distanceOutside(a, vector) < distanceOutside(b, vector);
  });
}

BuiltinResult evaluateBuiltin(const BuiltinCall& call, PrecisionRules rules, OracleRoad road,
                              OracleBuild build) {
  const UsePrecisionRules applied(rules);
  const Builtin fn = parseBuiltin(call.fn);
  if (call.I.size() != call.N.size()) {
    throw UsageError(fmt::format("{}: I has {} components and N has {}; they must match", call.fn,
                                 call.I.size(), call.N.size()));
  }
  switch (call.I.size()) {
    case 1:
      return evaluateSized<1>(fn, call, road, build);
    case 2:
      return evaluateSized<2>(fn, call, road, build);
    case 3:
      return evaluateSized<3>(fn, call, road, build);
    case 4:
      return evaluateSized<4>(fn, call, road, build);
    default:
      throw UsageError(fmt::format("{}: I and N have {} components; GLSL allows 1 to 4", call.fn,
                                   call.I.size()));
  }
}

}  // namespace snell
