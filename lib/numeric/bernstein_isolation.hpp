// Real-root isolation on [0, 1] of a polynomial of any degree D with interval coefficients, in
// the Bernstein basis (docs/design.md, 5.2), for every interval stage: the contact filter's
// polynomials (degree <= 4, filter/interval/isolation.hpp) and the rigid walks' (degree 5 and
// 10, lib/rigid).
//  - The coefficients on [0, 1] are taken times L = lcm C(D, 0..D), a positive factor (the same
//    signs): L b_j = sum_{i <= j} C(j, i) (L / C(D, i)) c_i. Every multiplier is a small integer,
//    so exactly known (dyadic) coefficients give exact results; dividing by C(D, i) instead
//    would round 1/3, 1/6, ... and hide exact zeros (a double root at t = 1/2).
//  - de Casteljau halving at the middle of a dyadic cell divides by 2 only: exact.
//  - Descartes' rule of signs in the Bernstein basis: a cell whose coefficients have certain
//    signs without a change holds no root; with exactly one change and nonzero end
//    coefficients, exactly one simple root. An exact [0, 0] is a certain zero (classify).
// Soundness rests on the inclusion property of interval arithmetic: every interval contains
// the exact value it stands for. Interval needs the upward rounding of the caller's
// CGAL::Protect_FPU_rounding (numeric/interval.hpp).
#pragma once

#include <array>
#include <limits>

#include "numeric/interval.hpp"

namespace exactccd::numeric {

/// C(n, k), 0 outside 0 <= k <= n (exact for the degrees used, n <= 10).
constexpr int binomial(int n, int k) {
  if (k < 0 || k > n) return 0;
  int r = 1;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

/// gcd(a, b) for a, b >= 0.
constexpr int gcd_of(int a, int b) { return b == 0 ? a : gcd_of(b, a % b); }

/// lcm of C(D, 0..D): 1, 1, 2, 3, 12, 30, ... 2520 for D = 10.
constexpr int binomial_lcm(int D) {
  int l = 1;
  for (int i = 0; i <= D; ++i) l = l / gcd_of(l, binomial(D, i)) * binomial(D, i);
  return l;
}

/// Bernstein coefficients of a degree-D polynomial on a cell (times binomial_lcm(D)).
template <int D>
using Bernstein = std::array<Interval, D + 1>;

/// The Bernstein coefficients on [0, 1], times L = binomial_lcm(D), of the polynomial with
/// power-basis coefficients c (c[i] the coefficient of t^i).
template <int D>
Bernstein<D> to_bernstein(const std::array<Interval, D + 1>& c) {
  Bernstein<D> b;
  for (int j = 0; j <= D; ++j) {
    Interval sum(0);
    for (int i = 0; i <= j; ++i) sum = sum + c[i] * (binomial(j, i) * (binomial_lcm(D) / binomial(D, i)));
    b[j] = sum;
  }
  return b;
}

/// de Casteljau at 1/2 (divisions by 2 are exact): the coefficients on the two halves.
template <int D>
void halve(const Bernstein<D>& b, Bernstein<D>& left, Bernstein<D>& right) {
  Bernstein<D> work = b;
  left[0] = work[0];
  right[D] = work[D];
  for (int level = 1; level <= D; ++level) {
    for (int i = 0; i <= D - level; ++i) work[i] = (work[i] + work[i + 1]) / 2;
    left[level] = work[0];
    right[D - level] = work[D - level];
  }
}

/// Where a polynomial vanishes: exactly at the double lo == hi (an exact zero at a dyadic
/// point), or at exactly one simple root in the open interval (lo, hi), with its sign at lo.
struct RootCell {
  double lo, hi;
  int sign_at_lo;
  bool is_point() const { return lo == hi; }
};

enum class Isolation { complete, failed };

/// How far an isolation may subdivide before it gives up (Isolation::failed, the caller's
/// exact path takes over): cells no narrower than 2^-max_depth, and at most max_cells cells
/// examined in all (a polynomial within rounding of zero over a long stretch would otherwise
/// split every cell down to the depth limit).
struct IsolationLimits {
  int max_depth;
  int max_cells = std::numeric_limits<int>::max();
};

namespace isolation_detail {

/// Sign changes among the nonzero certain signs s (Descartes' rule in the Bernstein basis).
template <std::size_t N>
int sign_changes(const std::array<SignClass, N>& s) {
  int changes = 0;
  SignClass previous = SignClass::zero;
  for (const SignClass c : s) {
    if (c == SignClass::zero) continue;
    changes += previous != SignClass::zero && c != previous;
    previous = c;
  }
  return changes;
}

/// isolate() on the cell [lo, hi] at `depth`, `cells_left` counting down the cells examined.
template <int D, class Cells>
Isolation isolate_cell(const Bernstein<D>& b, double lo, double hi, int depth, Cells& out, SignClass first,
                       SignClass last, const IsolationLimits& limits, int& cells_left) {
  if (--cells_left < 0) return Isolation::failed;
  std::array<SignClass, D + 1> s{};
  bool certain = true, all_zero = true;
  for (int i = 0; i <= D; ++i) {
    s[i] = classify(b[i]);
    if (i == 0 && s[i] == SignClass::unknown) s[i] = first;
    if (i == D && s[i] == SignClass::unknown) s[i] = last;
    certain = certain && s[i] != SignClass::unknown;
    all_zero = all_zero && s[i] == SignClass::zero;
  }
  if (certain) {
    if (all_zero) return Isolation::failed;  // vanishes identically on the cell
    const int changes = sign_changes(s);
    if (changes == 0) return Isolation::complete;
    if (changes == 1 && s[0] != SignClass::zero && s[D] != SignClass::zero) {
      out.push_back(RootCell{lo, hi, s[0] == SignClass::positive ? 1 : -1});
      return Isolation::complete;
    }
  }
  if (depth == limits.max_depth) return Isolation::failed;
  Bernstein<D> left, right;
  halve<D>(b, left, right);
  const double mid = lo + (hi - lo) / 2;  // exact: dyadic cells of [0, 1]
  if (isolate_cell<D>(left, lo, mid, depth + 1, out, s[0], SignClass::unknown, limits, cells_left) == Isolation::failed)
    return Isolation::failed;
  if (classify(left[D]) == SignClass::zero) out.push_back(RootCell{mid, mid, 0});
  return isolate_cell<D>(right, mid, hi, depth + 1, out, SignClass::unknown, s[D], limits, cells_left);
}

}  // namespace isolation_detail

/// Appends the roots in the open cell (lo, hi) (Bernstein coefficients b on it, at subdivision
/// `depth`), and exact zeros at inner dyadic points, in increasing order; the roots at the
/// cell's ends are the caller's. `first` / `last`, when not unknown, are the exact signs of
/// b[0] / b[D] (the polynomial's values at lo / hi), known from elsewhere. Failed when a cell
/// cannot be settled within `limits` or the polynomial vanishes on a whole cell.
template <int D, class Cells>
Isolation isolate(const Bernstein<D>& b, double lo, double hi, int depth, Cells& out, SignClass first, SignClass last,
                  const IsolationLimits& limits) {
  int cells_left = limits.max_cells;
  return isolation_detail::isolate_cell<D>(b, lo, hi, depth, out, first, last, limits, cells_left);
}

/// The roots in [0, 1] of the polynomial with power-basis coefficients c (not identically
/// zero), in increasing order, exact zeros at 0 and 1 included when include_ends.
/// `exact_sign_at_end(e)` (e = 0, 1), called only when the interval value at that end is
/// uncertain, returns the exact sign class there, or SignClass::unknown.
template <int D, class Cells, class EndSign>
Isolation isolate_roots(const std::array<Interval, D + 1>& c, Cells& out, bool include_ends,
                        const IsolationLimits& limits, EndSign&& exact_sign_at_end) {
  const Bernstein<D> b = to_bernstein<D>(c);
  SignClass first = classify(b[0]), last = classify(b[D]);
  if (first == SignClass::unknown) first = exact_sign_at_end(0);
  if (last == SignClass::unknown) last = exact_sign_at_end(1);
  if (include_ends && first == SignClass::zero) out.push_back(RootCell{0.0, 0.0, 0});
  if (isolate<D>(b, 0.0, 1.0, 0, out, first, last, limits) == Isolation::failed) return Isolation::failed;
  if (include_ends && last == SignClass::zero) out.push_back(RootCell{1.0, 1.0, 0});
  return Isolation::complete;
}

}  // namespace exactccd::numeric
