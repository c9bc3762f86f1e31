#pragma once
// The bound on a sum of three or four closed products over every order and
// tree shape an implementation may add them in: sumOfProducts()'s
// tightening of a dot product, shared with refract's shorter road
// (point_builtins.cpp). Inline: both call it once per dot product.
// Internal to the oracle library.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>

#include "oracle/interval_float_sets.h"

namespace snell {

// One product of closed factors: its ideal range and the error it carries
// from its operands.
struct ClosedProduct {
  double idealLo;
  double idealHi;
  double propagated;
};

namespace tree_sum_detail {

// The sum of n <= 4 closed products in every order: the roundings of the
// sum before the last one happen at partial sums of subsets of the terms;
// the largest total over every tree shape bounds them all. `partial[mask]`
// bounds |partial sum| over the terms in the mask.
inline double worstTreeRounding(const double* partial, std::size_t n) {
  const auto err = [&](unsigned mask) {
    return float_sets::roundingError(-partial[mask], partial[mask]);
  };
  if (n <= 2) return 0.0;
  if (n == 3) return std::max({err(0b011), err(0b101), err(0b110)});
  // n == 4: a pair inside a triple, or two disjoint pairs.
  double worst = 0.0;
  // The masks of two terms out of four, in increasing order.
  constexpr unsigned kPairs[] = {0b0011u, 0b0101u, 0b0110u, 0b1001u, 0b1010u, 0b1100u};
  for (unsigned triple : {0b0111u, 0b1011u, 0b1101u, 0b1110u})
    for (unsigned pair : kPairs)
      if ((pair & triple) == pair) worst = std::max(worst, err(pair) + err(triple));
  for (unsigned pair : {0b0011u, 0b0101u, 0b1001u})
    worst = std::max(worst, err(pair) + err(0b1111u ^ pair));
  return worst;
}

}  // namespace tree_sum_detail

// The bound on |the sum before its last rounding - its ideal value| for
// n = 3 or 4 products: each product's own error and rounding (or none,
// fused), then the worst tree of the sum's roundings.
inline double treeSumPending(const ClosedProduct* products, std::size_t n) {
  using float_sets::up;
  std::array<double, 4> termError{};
  for (std::size_t i = 0; i < n; ++i) {
    const ClosedProduct& p = products[i];
    // Its operands' errors, then its one rounding (or none, fused).
    termError[i] = up(p.propagated + float_sets::roundingError(p.idealLo - p.propagated,
                                                               p.idealHi + p.propagated));
  }
  // Only the masks of the partial sums before the last are read: two
  // terms or more, not all of them.
  std::array<double, 16> partial;
  const unsigned all = (1u << n) - 1;
  for (unsigned mask = 3; mask < all; ++mask) {
    if (std::popcount(mask) < 2) continue;
    double lo = 0.0, hi = 0.0, error = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (!(mask & (1u << i))) continue;
      lo += products[i].idealLo;
      hi += products[i].idealHi;
      error += termError[i];
    }
    // (1 + 4u) for the roundings of smaller partial sums inside this one.
    partial[mask] = up((std::max(std::fabs(lo), std::fabs(hi)) + error) * (1.0 + 0x1p-21));
  }
  double pending = 0.0;
  for (std::size_t i = 0; i < n; ++i) pending += termError[i];
  return up(pending + tree_sum_detail::worstTreeRounding(partial.data(), n));
}

}  // namespace snell
