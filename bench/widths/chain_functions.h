#pragma once
// The GLSL built-ins and operators the listings call, for any Chain number
// type: each closes its operands' chains and asks the policy.
#include <span>

#include "oracle/glsl/glsl.h"
#include "widths/chain.h"

namespace snell::widths {

template <class A>
Chain<A> operator/(const Chain<A>& a, const Chain<A>& b) {
  return Chain<A>::leaf(A::div(a.value, b.value));
}
template <class A>
auto operator<(const Chain<A>& a, const Chain<A>& b) {
  return A::less(a.value, b.value);
}
template <class A>
auto operator>(const Chain<A>& a, const Chain<A>& b) {
  return A::less(b.value, a.value);
}
template <class A>
Chain<A> sqrt(const Chain<A>& x) {
  return Chain<A>::leaf(A::sqrt(x.value));
}
template <class A>
Chain<A> inversesqrt(const Chain<A>& x) {
  return Chain<A>::leaf(A::inversesqrt(x.value));
}
template <class A>
Chain<A> exp2(const Chain<A>& x) {
  return Chain<A>::leaf(A::exp2(x.value));
}
template <class A>
Chain<A> exp(const Chain<A>& x) {
  return Chain<A>::leaf(A::exp(x.value));
}
template <class A>
Chain<A> log2(const Chain<A>& x) {
  return Chain<A>::leaf(A::log2(x.value));
}
template <class A>
Chain<A> pow(const Chain<A>& x, const Chain<A>& y) {
  return Chain<A>::leaf(A::pow(x.value, y.value));
}
template <class A>
Chain<A> max(const Chain<A>& a, const Chain<A>& b) {
  return Chain<A>::leaf(A::max(a.value, b.value));
}
template <class A>
Chain<A> min(const Chain<A>& a, const Chain<A>& b) {
  return Chain<A>::leaf(A::min(a.value, b.value));
}
template <class A>
Chain<A> abs(const Chain<A>& x) {
  return Chain<A>::leaf(A::abs(x.value));
}
// dot() and matrix rows: one open sum of product terms, so every order,
// tree shape and fusion is taken.
template <class A>
Chain<A> sumOfProducts(std::span<const Chain<A>> a, std::span<const Chain<A>> b) {
  Chain<A> sum = a[0] * b[0];
  for (std::size_t i = 1; i < a.size(); ++i) sum = sum + a[i] * b[i];
  return sum;
}
template <class A>
Chain<A> hull(const Chain<A>& a, const Chain<A>& b) {
  const typename A::Value both[] = {a.value, b.value};
  return Chain<A>::leaf(A::choose(both));
}
template <class A, int N>
glsl::vec<Chain<A>, N> hull(const glsl::vec<Chain<A>, N>& a, const glsl::vec<Chain<A>, N>& b) {
  glsl::vec<Chain<A>, N> r;
  for (int k = 0; k < N; ++k) r[k] = hull(a[k], b[k]);
  return r;
}
template <class A>
bool isUndefined(const Chain<A>& x) {
  return A::isUndefined(x.value);
}

}  // namespace snell::widths
