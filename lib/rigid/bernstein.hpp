// Root isolation of a polynomial with interval coefficients in the Bernstein basis, for any
// degree (the rigid volume has degree 5): the coefficients on [0, 1] times L = lcm C(D, i) (a
// positive factor, the same signs; small integer multipliers, so dyadic input stays exact), de
// Casteljau halving (exact divisions by 2), Descartes' rule of signs per cell: a cell whose
// coefficients have certain signs without a change holds no root; with exactly one change and
// nonzero end coefficients it holds one simple root. An exact [0, 0] is a certain zero. As
// filter/interval_isolation.hpp for degree <= 4 (docs/design.md, 5.2). Needs upward rounding.
#pragma once

#include <CGAL/Interval_nt.h>
#include <boost/container/small_vector.hpp>

#include <array>

#include "contact/polynomial.hpp"

namespace exactccd::rigid {

/// C(n, k) for n <= 10.
constexpr int binomial(int n, int k) {
  if (k < 0 || k > n) return 0;
  int r = 1;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}
constexpr int gcd_of(int a, int b) { return b == 0 ? a : gcd_of(b, a % b); }
/// lcm of C(D, 0..D).
constexpr int binomial_lcm(int D) {
  int l = 1;
  for (int i = 0; i <= D; ++i) l = l / gcd_of(l, binomial(D, i)) * binomial(D, i);
  return l;
}

/// Sign class of an interval: exactly [0, 0] is a certain zero.
enum class SignClass { negative, zero, positive, unknown };

inline SignClass classify(const CGAL::Interval_nt<false>& x) {
  if (x.inf() > 0) return SignClass::positive;
  if (x.sup() < 0) return SignClass::negative;
  if (x.inf() == 0 && x.sup() == 0) return SignClass::zero;
  return SignClass::unknown;
}

/// A cell holding exactly one simple root (lo < hi; sign_at_lo its sign at lo), or an exact
/// zero at the dyadic point lo == hi.
struct RootCell {
  double lo, hi;
  int sign_at_lo;
};

template <int D>
class BernsteinIsolation {
 public:
  using I = CGAL::Interval_nt<false>;
  using Coefficients = std::array<I, D + 1>;
  static constexpr int kMaxDepth = 40;
  /// The most cells examined by one isolation: a polynomial within rounding of zero over a long
  /// stretch would otherwise split every cell down to the depth limit (2^40 cells).
  static constexpr int kMaxCells = 4096;

  /// The coefficients of p on [0, 1] times L.
  static Coefficients of(const contact::Poly<I, D>& p) {
    Coefficients b;
    for (int j = 0; j <= D; ++j) {
      I sum(0);
      for (int i = 0; i <= j; ++i) sum = sum + p.c[i] * I(binomial(j, i) * (binomial_lcm(D) / binomial(D, i)));
      b[j] = sum;
    }
    return b;
  }

  /// Appends the roots in (lo, hi), and exact zeros at inner dyadic points, in increasing
  /// order; false when a cell cannot be settled at the depth limit, or after kMaxCells cells.
  /// `first` / `last`: the signs at lo / hi when known from elsewhere (else unknown).
  static bool isolate(const Coefficients& b, double lo, double hi, int depth, boost::container::small_vector<RootCell, 8>& out,
                      SignClass first, SignClass last) {
    int budget = kMaxCells;
    return isolate(b, lo, hi, depth, out, first, last, budget);
  }

 private:
  static bool isolate(const Coefficients& b, double lo, double hi, int depth, boost::container::small_vector<RootCell, 8>& out,
                      SignClass first, SignClass last, int& budget) {
    if (--budget < 0) return false;
    std::array<SignClass, D + 1> s;
    bool certain = true, all_zero = true;
    for (int i = 0; i <= D; ++i) {
      s[i] = classify(b[i]);
      if (i == 0 && s[i] == SignClass::unknown) s[i] = first;
      if (i == D && s[i] == SignClass::unknown) s[i] = last;
      certain = certain && s[i] != SignClass::unknown;
      all_zero = all_zero && s[i] == SignClass::zero;
    }
    if (certain) {
      if (all_zero) return false;  // vanishes identically on the cell
      int changes = 0;
      SignClass previous = SignClass::zero;
      for (const SignClass c : s) {
        if (c == SignClass::zero) continue;
        changes += previous != SignClass::zero && c != previous;
        previous = c;
      }
      if (changes == 0) return true;
      if (changes == 1 && s[0] != SignClass::zero && s[D] != SignClass::zero) {
        out.push_back(RootCell{lo, hi, s[0] == SignClass::positive ? 1 : -1});
        return true;
      }
    }
    if (depth == kMaxDepth) return false;
    Coefficients left, right, work = b;
    left[0] = work[0];
    right[D] = work[D];
    for (int level = 1; level <= D; ++level) {
      for (int i = 0; i <= D - level; ++i) work[i] = (work[i] + work[i + 1]) / 2;
      left[level] = work[0];
      right[D - level] = work[D - level];
    }
    const double mid = lo + (hi - lo) / 2;  // exact: dyadic cells
    if (!isolate(left, lo, mid, depth + 1, out, s[0], SignClass::unknown, budget)) return false;
    if (classify(left[D]) == SignClass::zero) out.push_back(RootCell{mid, mid, 0});
    return isolate(right, mid, hi, depth + 1, out, SignClass::unknown, s[D], budget);
  }
};

}  // namespace exactccd::rigid
