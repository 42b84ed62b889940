// A floating-point number of Bits significand bits on MPFR, round-to-nearest, for the
// precision ladder: the naive algorithm run at 24, 53, 113 and 256 bits (does more precision,
// without exactness, help?). The precision is a template argument: no global precision state.
#pragma once

#include <mpfr.h>

#include <utility>

namespace exactccd::baseline {

template <int Bits>
class Mpfr {
 public:
  Mpfr() {
    mpfr_init2(v_, Bits);
    mpfr_set_zero(v_, 1);
  }
  Mpfr(double d) {  // NOLINT: implicit, like a built-in floating-point type (rounds to Bits)
    mpfr_init2(v_, Bits);
    mpfr_set_d(v_, d, MPFR_RNDN);
  }
  Mpfr(int i) {  // NOLINT
    mpfr_init2(v_, Bits);
    mpfr_set_si(v_, i, MPFR_RNDN);
  }
  Mpfr(const Mpfr& o) {
    mpfr_init2(v_, Bits);
    mpfr_set(v_, o.v_, MPFR_RNDN);
  }
  Mpfr(Mpfr&& o) noexcept {
    mpfr_init2(v_, Bits);
    mpfr_swap(v_, o.v_);
  }
  Mpfr& operator=(const Mpfr& o) {
    mpfr_set(v_, o.v_, MPFR_RNDN);
    return *this;
  }
  Mpfr& operator=(Mpfr&& o) noexcept {
    mpfr_swap(v_, o.v_);
    return *this;
  }
  ~Mpfr() { mpfr_clear(v_); }

  double to_double() const { return mpfr_get_d(v_, MPFR_RNDN); }

#define EXACTCCD_MPFR_BINARY(op, fn)                          \
  friend Mpfr operator op(const Mpfr& a, const Mpfr& b) {     \
    Mpfr r;                                                   \
    fn(r.v_, a.v_, b.v_, MPFR_RNDN);                          \
    return r;                                                 \
  }
  EXACTCCD_MPFR_BINARY(+, mpfr_add)
  EXACTCCD_MPFR_BINARY(-, mpfr_sub)
  EXACTCCD_MPFR_BINARY(*, mpfr_mul)
  EXACTCCD_MPFR_BINARY(/, mpfr_div)
#undef EXACTCCD_MPFR_BINARY

#define EXACTCCD_MPFR_UNARY(name, fn) \
  friend Mpfr name(const Mpfr& a) {   \
    Mpfr r;                           \
    fn(r.v_, a.v_, MPFR_RNDN);        \
    return r;                         \
  }
  EXACTCCD_MPFR_UNARY(sqrt, mpfr_sqrt)
  EXACTCCD_MPFR_UNARY(cbrt, mpfr_cbrt)
  EXACTCCD_MPFR_UNARY(acos, mpfr_acos)
  EXACTCCD_MPFR_UNARY(cos, mpfr_cos)
  EXACTCCD_MPFR_UNARY(fabs, mpfr_abs)
#undef EXACTCCD_MPFR_UNARY

  friend Mpfr operator-(const Mpfr& a) {
    Mpfr r;
    mpfr_neg(r.v_, a.v_, MPFR_RNDN);
    return r;
  }
  friend bool operator<(const Mpfr& a, const Mpfr& b) { return mpfr_less_p(a.v_, b.v_); }
  friend bool operator>(const Mpfr& a, const Mpfr& b) { return mpfr_greater_p(a.v_, b.v_); }
  friend bool operator<=(const Mpfr& a, const Mpfr& b) { return mpfr_lessequal_p(a.v_, b.v_); }
  friend bool operator>=(const Mpfr& a, const Mpfr& b) { return mpfr_greaterequal_p(a.v_, b.v_); }
  friend bool operator==(const Mpfr& a, const Mpfr& b) { return mpfr_equal_p(a.v_, b.v_); }
  friend bool operator!=(const Mpfr& a, const Mpfr& b) { return !mpfr_equal_p(a.v_, b.v_); }

 private:
  mpfr_t v_;
};

}  // namespace exactccd::baseline
