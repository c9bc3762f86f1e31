#pragma once
// A number type that keeps an expression's open sums and product chains
// apart until something else consumes them, so that every grouping the
// rules allow can be evaluated: GLSL 4.60 section 4.9 and the Vulkan spec
// let an expression not marked `precise` be reassociated, commuted and have
// a*b+c fused. A sum of n terms is evaluated over every binary tree of its
// terms (subset by subset), with every product term of a tree node offered
// fused into that node's addition; a product chain over every tree of its
// factors. The `Arith` policy says what a value is and how alternatives
// combine: DeqpArith (deqp_interval.h) takes the union, the sampler
// (conforming_sampler.h) picks one.
//
// Distributivity (Vulkan only) is not enumerated. Past kMaxTerms terms or
// kMaxFactors factors a chain is closed and a new one starts.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace snell::widths {

inline constexpr std::size_t kMaxTerms = 6;
inline constexpr std::size_t kMaxFactors = 4;

template <class Arith>
struct Chain {
  using Value = typename Arith::Value;
  Value value{};               // the whole expression, evaluated
  std::vector<Value> factors;  // an open product chain: two or more closed factors
  std::vector<Chain> terms;    // an open sum: two or more terms, each closed or a product chain

  Chain() = default;
  explicit Chain(float x) : value(Arith::point(x)) {}
  static Chain leaf(Value v) {
    Chain c;
    c.value = v;
    return c;
  }
  bool isProduct() const { return !factors.empty(); }
  bool isSum() const { return !terms.empty(); }
};

namespace chain_detail {

// Evaluates `combine(a, b)` for every split of every subset of `items`
// (bit masks), memoised: value(all) covers every binary tree.
template <class Arith, class Leaf, class Combine, class Extra>
typename Arith::Value overTrees(std::size_t count, Leaf leafValue, Combine combine, Extra extra) {
  using Value = typename Arith::Value;
  const std::uint32_t all = (1u << count) - 1;
  std::vector<Value> memo(all + 1);
  for (std::uint32_t set = 1; set <= all; ++set) {
    if ((set & (set - 1)) == 0) {
      memo[set] = leafValue(static_cast<std::size_t>(__builtin_ctz(set)));
      continue;
    }
    std::vector<Value> ways;
    const std::uint32_t lowest = set & (~set + 1);
    // Subsets holding the lowest member, so that each unordered split counts once.
    for (std::uint32_t part = (set - 1) & set; part != 0; part = (part - 1) & set) {
      if ((part & lowest) == 0) continue;
      const std::uint32_t rest = set & ~part;
      ways.push_back(combine(memo[part], memo[rest]));
      extra(part, rest, memo, ways);
      extra(rest, part, memo, ways);
    }
    memo[set] = Arith::choose(ways);
  }
  return memo[all];
}

template <class Arith>
typename Arith::Value productOf(const std::vector<typename Arith::Value>& factors) {
  using Value = typename Arith::Value;
  return overTrees<Arith>(
      factors.size(), [&](std::size_t i) { return factors[i]; },
      [](const Value& a, const Value& b) { return Arith::mul(a, b); },
      [](std::uint32_t, std::uint32_t, const std::vector<Value>&, std::vector<Value>&) {});
}

// Every last multiplication of a product chain as a pair of sub-products:
// what a fused multiply-add may take as its a and b.
template <class Arith>
std::vector<std::pair<typename Arith::Value, typename Arith::Value>> lastProducts(
    const std::vector<typename Arith::Value>& factors) {
  using Value = typename Arith::Value;
  std::vector<std::pair<Value, Value>> pairs;
  const std::uint32_t all = (1u << factors.size()) - 1;
  const auto subset = [&](std::uint32_t mask) {
    std::vector<Value> chosen;
    for (std::size_t i = 0; i < factors.size(); ++i)
      if (mask & (1u << i)) chosen.push_back(factors[i]);
    return productOf<Arith>(chosen);
  };
  for (std::uint32_t part = (all - 1) & all; part != 0; part = (part - 1) & all) {
    if ((part & 1u) == 0) continue;
    pairs.emplace_back(subset(part), subset(all & ~part));
  }
  return pairs;
}

template <class Arith>
typename Arith::Value sumOf(const std::vector<Chain<Arith>>& terms) {
  using Value = typename Arith::Value;
  std::vector<std::vector<std::pair<Value, Value>>> fusable(terms.size());
  for (std::size_t i = 0; i < terms.size(); ++i)
    if (terms[i].isProduct()) fusable[i] = lastProducts<Arith>(terms[i].factors);
  const auto fused = [&](std::uint32_t part, std::uint32_t single, const std::vector<Value>& memo,
                         std::vector<Value>& ways) {
    if ((single & (single - 1)) != 0) return;
    for (const auto& [a, b] : fusable[static_cast<std::size_t>(__builtin_ctz(single))])
      ways.push_back(Arith::fma(a, b, memo[part]));
  };
  return overTrees<Arith>(
      terms.size(), [&](std::size_t i) { return terms[i].value; },
      [](const Value& a, const Value& b) { return Arith::add(a, b); }, fused);
}

template <class Arith>
std::vector<Chain<Arith>> termsOf(const Chain<Arith>& c) {
  if (c.isSum()) return c.terms;
  return {c};
}

template <class Arith>
std::vector<typename Arith::Value> factorsOf(const Chain<Arith>& c) {
  if (c.isProduct()) return c.factors;
  return {c.value};
}

}  // namespace chain_detail

template <class Arith>
Chain<Arith> operator-(const Chain<Arith>& c) {
  Chain<Arith> r = c;
  r.value = Arith::neg(c.value);
  if (r.isProduct()) r.factors[0] = Arith::neg(r.factors[0]);
  for (Chain<Arith>& term : r.terms) term = -term;
  return r;
}

template <class Arith>
Chain<Arith> operator+(const Chain<Arith>& a, const Chain<Arith>& b) {
  std::vector<Chain<Arith>> terms = chain_detail::termsOf(a);
  const std::vector<Chain<Arith>> more = chain_detail::termsOf(b);
  terms.insert(terms.end(), more.begin(), more.end());
  if (terms.size() > kMaxTerms) terms = {Chain<Arith>::leaf(a.value), Chain<Arith>::leaf(b.value)};
  Chain<Arith> r;
  r.value = chain_detail::sumOf<Arith>(terms);
  r.terms = std::move(terms);
  return r;
}

template <class Arith>
Chain<Arith> operator-(const Chain<Arith>& a, const Chain<Arith>& b) {
  return a + (-b);
}

template <class Arith>
Chain<Arith> operator*(const Chain<Arith>& a, const Chain<Arith>& b) {
  std::vector<typename Arith::Value> factors = chain_detail::factorsOf(a);
  const std::vector<typename Arith::Value> more = chain_detail::factorsOf(b);
  factors.insert(factors.end(), more.begin(), more.end());
  if (factors.size() > kMaxFactors) factors = {a.value, b.value};
  Chain<Arith> r;
  r.value = chain_detail::productOf<Arith>(factors);
  r.factors = std::move(factors);
  return r;
}

}  // namespace snell::widths
