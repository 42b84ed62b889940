// Univariate polynomials in the time t with a degree fixed at compile time.
//
// The contact rule multiplies linear motions into the volume cubic and the quartic
// inclusion polynomials. Carrying the degree in the type keeps the coefficients in a
// std::array (no allocation for double or interval coefficients) and lets the compiler
// check that no product exceeds the degree the proofs in docs/design.md assume.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cstddef>

namespace exactccd::contact {

/// acc += a * b. The overload for GMP integers multiplies in place (mpz_addmul): the exact
/// stages spend most of their time allocating temporaries otherwise.
template <class NT>
void multiply_add(NT& acc, const NT& a, const NT& b) {
  acc = acc + a * b;
}
inline void multiply_add(mpz_class& acc, const mpz_class& a, const mpz_class& b) {
  mpz_addmul(acc.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
}

/// p(t) = c[0] + c[1] t + ... + c[D] t^D over the number type NT.
template <class NT, int D>
struct Poly {
  static_assert(D >= 0, "degree must be non-negative");
  static constexpr int degree = D;
  std::array<NT, D + 1> c;

  /// The zero polynomial. (Some number types, e.g. CGAL::Interval_nt, do not zero
  /// themselves on default construction, so every operator starts from this.)
  static Poly zero() {
    Poly p;
    p.c.fill(NT(0));
    return p;
  }

  /// The polynomial's value at t (Horner's scheme).
  template <class T>
  T operator()(const T& t) const {
    T r = T(c[D]);
    for (int k = D - 1; k >= 0; --k) r = r * t + T(c[k]);
    return r;
  }
};

/// The motion x(t) = x0 + t (x1 - x0) of one coordinate.
template <class NT>
Poly<NT, 1> linear_motion(const NT& x0, const NT& x1) {
  return Poly<NT, 1>{{x0, x1 - x0}};
}

/// True iff every coefficient is zero (the polynomial vanishes for all t).
template <class NT, int D>
bool is_zero(const Poly<NT, D>& p) {
  return std::all_of(p.c.begin(), p.c.end(), [](const NT& x) { return x == 0; });
}

template <class NT, int A, int B>
Poly<NT, (A > B ? A : B)> operator+(const Poly<NT, A>& p, const Poly<NT, B>& q) {
  auto r = Poly<NT, (A > B ? A : B)>::zero();
  for (int k = 0; k <= A; ++k) r.c[k] = p.c[k];
  for (int k = 0; k <= B; ++k) r.c[k] = r.c[k] + q.c[k];
  return r;
}

template <class NT, int A, int B>
Poly<NT, (A > B ? A : B)> operator-(const Poly<NT, A>& p, const Poly<NT, B>& q) {
  auto r = Poly<NT, (A > B ? A : B)>::zero();
  for (int k = 0; k <= A; ++k) r.c[k] = p.c[k];
  for (int k = 0; k <= B; ++k) r.c[k] = r.c[k] - q.c[k];
  return r;
}

template <class NT, int A, int B>
Poly<NT, A + B> operator*(const Poly<NT, A>& p, const Poly<NT, B>& q) {
  auto r = Poly<NT, A + B>::zero();
  for (int i = 0; i <= A; ++i)
    for (int j = 0; j <= B; ++j) multiply_add(r.c[i + j], p.c[i], q.c[j]);
  return r;
}

}  // namespace exactccd::contact
