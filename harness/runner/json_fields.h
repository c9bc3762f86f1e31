#pragma once
// Numbers in result records: JSON has no infinity or NaN, and a record from
// a worker or a file is checked before a count is converted.
#include <cmath>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

namespace snell {

// A document as text. Strings from outside (a driver's compile log, a path,
// quoted shader source) need not be UTF-8, and the library's dump() throws
// on a byte that is not: it is written as U+FFFD instead, so that a record
// is never lost to a byte in its log.
inline std::string jsonText(const nlohmann::json& j, int indent = -1) {
  return j.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

// A non-finite value (a slack past every bound) is written as null.
inline nlohmann::json jsonNumber(double x) {
  return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json();
}

inline double jsonNumberOr(const nlohmann::json& x, double nonFinite) {
  return x.is_null() ? nonFinite : x.get<double>();
}

// nlohmann's get<std::size_t>() on 1e20 or -2.5 is a float-to-integer cast
// with undefined behaviour: the value is checked first.
template <class Integer>
Integer jsonCount(const nlohmann::json& x) {
  if (!x.is_number_integer() && !x.is_number_unsigned())
    throw nlohmann::json::type_error::create(302, "expected an integer, got " + x.dump(), &x);
  if (x.is_number_unsigned()) {
    const auto value = x.get<std::uint64_t>();
    if (value > static_cast<std::uint64_t>(std::numeric_limits<Integer>::max()))
      throw nlohmann::json::type_error::create(302, "integer out of range: " + x.dump(), &x);
    return static_cast<Integer>(value);
  }
  const auto value = x.get<std::int64_t>();
  if (value < static_cast<std::int64_t>(std::numeric_limits<Integer>::min()) ||
      (value > 0 && static_cast<std::uint64_t>(value) >
                        static_cast<std::uint64_t>(std::numeric_limits<Integer>::max())))
    throw nlohmann::json::type_error::create(302, "integer out of range: " + x.dump(), &x);
  return static_cast<Integer>(value);
}

}  // namespace snell
