#pragma once
// The fp32 grid functions of fp32.h, computed on the IEEE 754 encodings
// (std::bit_cast) instead of through libm's nextafter, frexp and ldexp:
// every interval operation calls several of them, and they are most of the
// oracle's time when they are calls into libm. Each gives bit for bit what
// its libm formulation gives (tests/oracle/fp32_bits_test.cpp checks them
// against it on random and edge inputs).
//
// Internal to the oracle library: included by its .cpp files only, which
// are compiled without GCC's SLP vectorizer (floatAtOrBelow/Above round a
// double to float and back, which GCC 12.2's SLP vectorizer can drop; see
// harness/oracle/CMakeLists.txt).
#include <bit>
#include <cstdint>
#include <limits>

#include "oracle/fp32.h"

namespace snell::fp32_bits {

inline constexpr std::uint64_t kDoubleSignBit = std::uint64_t{1} << 63;
inline constexpr std::uint64_t kDoubleMantissa = (std::uint64_t{1} << 52) - 1;

inline std::uint64_t bitsOf(double x) { return std::bit_cast<std::uint64_t>(x); }
inline double doubleOf(std::uint64_t bits) { return std::bit_cast<double>(bits); }

// The biased exponent field: 0 for zeros and denormals, 2047 for inf/NaN.
inline int biasedExponent(double x) { return static_cast<int>((bitsOf(x) >> 52) & 0x7ff); }

// std::nextafter(x, +inf) and std::nextafter(x, -inf) for doubles (glibc's
// results, -0 included: the step up from the smallest negative denormal is
// -0).
// A finite x other than 0 (nearly every one the oracle steps) is one
// compare: its step away from 0 is +1 on the encoding, toward 0 is -1.
inline constexpr std::uint64_t kDoubleInfinityBits = 0x7ff0000000000000;
inline bool finiteNonZero(std::uint64_t bits) {
  return (bits & ~kDoubleSignBit) - 1 < kDoubleInfinityBits - 1;
}
// +1 for a positive encoding, -1 (all ones) for a negative one.
inline std::uint64_t awayFromZero(std::uint64_t bits) {
  return (0 - (bits >> 63)) | 1;
}
inline double nextUp(double x) {
  const std::uint64_t bits = bitsOf(x);
  if (finiteNonZero(bits)) return doubleOf(bits + awayFromZero(bits));
  if (x != x || x == std::numeric_limits<double>::infinity()) return x;
  if (x == 0.0) return std::numeric_limits<double>::denorm_min();
  return doubleOf(bits - 1);  // -inf
}
inline double nextDown(double x) {
  const std::uint64_t bits = bitsOf(x);
  if (finiteNonZero(bits)) return doubleOf(bits - awayFromZero(bits));
  if (x != x || x == -std::numeric_limits<double>::infinity()) return x;
  if (x == 0.0) return -std::numeric_limits<double>::denorm_min();
  return doubleOf(bits - 1);  // +inf
}

// The same for a float that is not NaN (what std::nextafter(f, +-inf) gives).
inline float nextUpFloat(float f) {
  if (f == std::numeric_limits<float>::infinity()) return f;
  if (f == 0.0f) return std::numeric_limits<float>::denorm_min();
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(f);
  return std::bit_cast<float>(f > 0.0f ? bits + 1 : bits - 1);
}
inline float nextDownFloat(float f) {
  if (f == -std::numeric_limits<float>::infinity()) return f;
  if (f == 0.0f) return -std::numeric_limits<float>::denorm_min();
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(f);
  return std::bit_cast<float>(f > 0.0f ? bits - 1 : bits + 1);
}

// x > 0 and an exact power of two (denormal doubles included), as
// `std::frexp(x, &e) == 0.5`.
inline bool isPositivePowerOfTwo(double x) {
  if (!(x > 0.0) || x == std::numeric_limits<double>::infinity()) return false;
  const std::uint64_t mantissa = bitsOf(x) & kDoubleMantissa;
  if (biasedExponent(x) != 0) return mantissa == 0;
  return (mantissa & (mantissa - 1)) == 0;
}

// 2^(e + 1) for the binade [2^e, 2^(e + 1)) holding a normal x > 0: the
// first power of two above x, as std::ldexp(1.0, exponent) after
// std::frexp(x, &exponent) (infinity past the double range).
inline double powerOfTwoAbove(double x) {
  return doubleOf(static_cast<std::uint64_t>(biasedExponent(x) + 1) << 52);
}

// Whether |x| is a normal float's magnitude or between two of them:
// [2^-126, kFp32Max]. There the fp32 grid is the double grid with the low
// 29 mantissa bits cleared, so a directed rounding to float is integer
// arithmetic on the encoding, with no conversion in its dependency chain
// (the conversions made these two a fifth of an interval operation). One
// unsigned compare: NaN, infinities, denormals and 0 fall outside.
inline constexpr std::uint64_t kFloatDropBits = 29;
inline constexpr std::uint64_t kFloatDropMask = (std::uint64_t{1} << kFloatDropBits) - 1;
inline bool inNormalFloatRange(std::uint64_t bits) {
  constexpr std::uint64_t kLowest = std::bit_cast<std::uint64_t>(kFp32MinNormal);
  constexpr std::uint64_t kHighest = std::bit_cast<std::uint64_t>(kFp32Max);
  return (bits & ~kDoubleSignBit) - kLowest <= kHighest - kLowest;
}

// The float gap in |x|'s binade: 2^-149 below the normal floats, 2^104
// past them.
inline double gapAbove(double x) {
  // a = 1.m * 2^(E - 1023), and the float gap in that binade is
  // 2^(E - 1023 - 23): the exponent field E - 23 with a zero mantissa.
  const std::uint64_t bits = bitsOf(x);
  if (inNormalFloatRange(bits)) return doubleOf((((bits >> 52) & 0x7ff) - 23) << 52);
  const double a = x < 0.0 ? -x : x;
  if (a != a) return a;
  if (a < kFp32MinNormal) return kFp32MinDenormal;
  return 0x1p104;  // past the largest float
}

inline double ulp(double x) {
  const double gap = gapAbove(x);
  const double a = x < 0.0 ? -x : x;
  const bool powerOfTwo = a > kFp32MinNormal && a <= kFp32Max && (bitsOf(a) & kDoubleMantissa) == 0;
  return powerOfTwo ? gap * 0.5 : gap;
}

// Whether x is a normal float or a zero of either sign (its low 29
// mantissa bits clear, its exponent in the float range).
inline bool isZeroOrNormalFloat(double x) {
  const std::uint64_t bits = bitsOf(x);
  return (bits & kFloatDropMask) == 0 && (inNormalFloatRange(bits) || (bits << 1) == 0);
}

// Rounds the magnitude toward zero, then one float step away from zero
// where bits were dropped and `away` asks for it: the carry out of the
// mantissa moves to the next binade, whose first float it is.
inline double dropToFloatGrid(std::uint64_t bits, bool away) {
  const std::uint64_t dropped = bits & kFloatDropMask;
  const std::uint64_t step = static_cast<std::uint64_t>(away && dropped != 0) << kFloatDropBits;
  return doubleOf(bits - dropped + step);
}

inline double floatAtOrBelow(double x) {
  // Below x is toward zero for a positive x and away from it for a negative one.
  const std::uint64_t xBits = bitsOf(x);
  if (inNormalFloatRange(xBits)) return dropToFloatGrid(xBits, (xBits >> 63) != 0);
  if (x != x || x == std::numeric_limits<double>::infinity() ||
      x == -std::numeric_limits<double>::infinity())
    return x;
  // Outside the float range the cast is not defined by the language.
  if (x > kFp32Max) return kFp32Max;
  if (x < -kFp32Max) return -std::numeric_limits<double>::infinity();
  // The cast rounds to nearest: at most one float away from the answer.
  // Which side it lands on is data (a branch on it is mispredicted half
  // the time), so the step down is taken by arithmetic on the encoding:
  // nextDownFloat(nearest), which is -1 on a positive encoding and +1 on a
  // negative one. nearest is neither +0 nor -inf when it lies above x.
  const float nearest = static_cast<float>(x);
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(nearest);
  const std::uint32_t above = static_cast<double>(nearest) > x ? 1u : 0u;
  const std::uint32_t step = (bits >> 31) * 2u - 1u;
  return std::bit_cast<float>(bits + above * step);
}

inline double floatAtOrAbove(double x) {
  const std::uint64_t xBits = bitsOf(x);
  if (inNormalFloatRange(xBits)) return dropToFloatGrid(xBits, (xBits >> 63) == 0);
  if (x != x || x == std::numeric_limits<double>::infinity() ||
      x == -std::numeric_limits<double>::infinity())
    return x;
  if (x > kFp32Max) return std::numeric_limits<double>::infinity();
  if (x < -kFp32Max) return -kFp32Max;
  // The same step up (nextUpFloat(nearest)): nearest is neither -0 nor
  // +inf when it lies below x.
  const float nearest = static_cast<float>(x);
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(nearest);
  const std::uint32_t below = static_cast<double>(nearest) < x ? 1u : 0u;
  const std::uint32_t step = 1u - (bits >> 31) * 2u;
  return std::bit_cast<float>(bits + below * step);
}

}  // namespace snell::fp32_bits
