#pragma once
// Mp: a 256-bit MPFR number for the listing templates (oracle/glsl), to
// check the oracle itself: the listing evaluated in (nearly) exact real
// arithmetic from the same fp32 inputs. Every operation rounds to nearest
// at 256 bits; the built-ins are MPFR's correctly rounded ones.
#include <mpfr.h>

#include <span>

#include "oracle/glsl/scalar.h"

namespace snell::test {

class Mp {
 public:
  static constexpr mpfr_prec_t kBits = 256;

  Mp() {
    mpfr_init2(v_, kBits);
    mpfr_set_zero(v_, 1);
  }
  explicit Mp(float value) {
    mpfr_init2(v_, kBits);
    mpfr_set_flt(v_, value, MPFR_RNDN);
  }
  explicit Mp(double value) {
    mpfr_init2(v_, kBits);
    mpfr_set_d(v_, value, MPFR_RNDN);
  }
  Mp(const Mp& other) {
    mpfr_init2(v_, kBits);
    mpfr_set(v_, other.v_, MPFR_RNDN);
  }
  Mp& operator=(const Mp& other) {
    mpfr_set(v_, other.v_, MPFR_RNDN);
    return *this;
  }
  ~Mp() { mpfr_clear(v_); }

  mpfr_ptr get() { return v_; }
  mpfr_srcptr get() const { return v_; }
  double toDouble() const { return mpfr_get_d(v_, MPFR_RNDN); }

 private:
  mpfr_t v_;
};

using Binary = int (*)(mpfr_ptr, mpfr_srcptr, mpfr_srcptr, mpfr_rnd_t);
using Unary = int (*)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t);

inline Mp apply(Binary f, const Mp& a, const Mp& b) {
  Mp r;
  f(r.get(), a.get(), b.get(), MPFR_RNDN);
  return r;
}
inline Mp apply(Unary f, const Mp& a) {
  Mp r;
  f(r.get(), a.get(), MPFR_RNDN);
  return r;
}

inline Mp operator+(const Mp& a, const Mp& b) { return apply(mpfr_add, a, b); }
inline Mp operator-(const Mp& a, const Mp& b) { return apply(mpfr_sub, a, b); }
inline Mp operator*(const Mp& a, const Mp& b) { return apply(mpfr_mul, a, b); }
inline Mp operator/(const Mp& a, const Mp& b) { return apply(mpfr_div, a, b); }
inline Mp operator-(const Mp& a) { return apply(mpfr_neg, a); }
inline bool operator<(const Mp& a, const Mp& b) { return mpfr_less_p(a.get(), b.get()) != 0; }

inline Mp sqrt(const Mp& x) { return apply(mpfr_sqrt, x); }
inline Mp inversesqrt(const Mp& x) { return apply(mpfr_rec_sqrt, x); }
inline Mp exp2(const Mp& x) { return apply(mpfr_exp2, x); }
inline Mp exp(const Mp& x) { return apply(mpfr_exp, x); }
inline Mp log2(const Mp& x) { return apply(mpfr_log2, x); }
inline Mp pow(const Mp& x, const Mp& y) { return apply(mpfr_pow, x, y); }
inline Mp abs(const Mp& x) { return apply(mpfr_abs, x); }
inline Mp max(const Mp& a, const Mp& b) { return b < a ? a : b; }
inline Mp min(const Mp& a, const Mp& b) { return b < a ? b : a; }
inline Mp sumOfProducts(std::span<const Mp> a, std::span<const Mp> b) {
  Mp sum = a[0] * b[0];
  for (std::size_t i = 1; i < a.size(); ++i) sum = sum + a[i] * b[i];
  return sum;
}
inline bool isUndefined(const Mp& x) { return mpfr_nan_p(x.get()) != 0; }

}  // namespace snell::test

template <>
struct snell::glsl::IsNumber<snell::test::Mp> : std::true_type {};
