// Interval root isolation and signs for the interval stage (docs/design.md, 5.2): the
// Bernstein coefficients of a polynomial with CGAL::Interval_nt<false> coefficients on [0, 1],
// de Casteljau halving, Descartes' rule of signs per cell, and certain signs over a cell.
//
// Soundness rests on the inclusion property of interval arithmetic: every interval computed
// here contains the exact real value of the quantity it stands for. Interval_nt<false> needs
// the FPU rounding towards +infinity: every function here must run under the
// Protect_FPU_rounding of the stage's entry point.
#pragma once

#include <boost/container/small_vector.hpp>

#include <array>
#include <cmath>
#include <limits>

#include "contact/contact_rule.hpp"
#include "numeric/interval.hpp"

namespace exactccd::filter::interval {

using numeric::certain_sign;
using numeric::classify;
using numeric::Interval;  // requires the rounding mode set by the caller
using numeric::next_up_nonnegative;
using numeric::sign_class;
using numeric::SignClass;
template <int D>
using Bernstein = std::array<Interval, D + 1>;

inline constexpr int kMaxSubdivisionDepth = 30;  // cells of width 2^-30; closer roots go to exact
inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr int kBinomial[5][5] = {
    {1, 0, 0, 0, 0}, {1, 1, 0, 0, 0}, {1, 2, 1, 0, 0}, {1, 3, 3, 1, 0}, {1, 4, 6, 4, 1}};

/// lcm of C(D, 0..D): 1, 1, 2, 3, 12.
inline constexpr int kBinomialLcm[5] = {1, 1, 2, 3, 12};

/// Bernstein coefficients on [0, 1] times L = kBinomialLcm[D] (a positive factor: same signs):
/// L b_j = sum_{i <= j} C(j, i) (L / C(D, i)) c_i. Every multiplier is a small integer, so with
/// exactly known coefficients (dyadic input) the result is exact; dividing by C(D, i) instead
/// would round 1/3, 1/4, 1/6 and hide exact zeros (a double root at t = 1/2).
template <int D>
Bernstein<D> to_bernstein(const contact::Poly<Interval, D>& p) {
  Bernstein<D> b;
  for (int j = 0; j <= D; ++j) {
    Interval sum(0);
    for (int i = 0; i <= j; ++i) sum = sum + p.c[i] * (kBinomial[j][i] * (kBinomialLcm[D] / kBinomial[D][i]));
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

/// Root cells of one polynomial: at most its degree (4), so no allocation on this path.
using RootCells = boost::container::small_vector<RootCell, 4>;

/// Appends the roots in the cell [lo, hi] (Bernstein coefficients b) in increasing order; the
/// roots at the cell's ends are the caller's. Descartes' rule in the Bernstein basis counts
/// sign changes among the nonzero coefficients. `first` / `last`, when not unknown, are the
/// exact signs of b[0] / b[D] (the polynomial's values at lo / hi), known from elsewhere.
template <int D>
Isolation isolate(const Bernstein<D>& b, double lo, double hi, int depth, RootCells& out,
                  SignClass first = SignClass::unknown, SignClass last = SignClass::unknown) {
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
    int changes = 0;
    SignClass last = SignClass::zero;
    for (SignClass c : s) {
      if (c == SignClass::zero) continue;
      changes += last != SignClass::zero && c != last;
      last = c;
    }
    if (changes == 0) return Isolation::complete;
    if (changes == 1 && s[0] != SignClass::zero && s[D] != SignClass::zero) {
      out.push_back(RootCell{lo, hi, s[0] == SignClass::positive ? 1 : -1});
      return Isolation::complete;
    }
  }
  if (depth == kMaxSubdivisionDepth) return Isolation::failed;
  Bernstein<D> left, right;
  halve<D>(b, left, right);
  const double mid = lo + (hi - lo) / 2;  // exact: dyadic cells of [0, 1]
  if (isolate<D>(left, lo, mid, depth + 1, out, s[0], SignClass::unknown) == Isolation::failed)
    return Isolation::failed;
  if (classify(left[D]) == SignClass::zero) out.push_back(RootCell{mid, mid, 0});
  return isolate<D>(right, mid, hi, depth + 1, out, SignClass::unknown, s[D]);
}

/// The roots in [0, 1] of a polynomial not identically zero, in increasing order, exact zeros
/// at 0 and 1 included when include_ends. `exact_sign_at_end(e)` (e = 0, 1), called only when
/// the interval value at that end is uncertain, returns the exact sign there or kUnknownSign.
template <int D, class EndSign>
Isolation isolate_roots(const contact::Poly<Interval, D>& p, RootCells& out, bool include_ends,
                        EndSign&& exact_sign_at_end) {
  const Bernstein<D> b = to_bernstein(p);
  SignClass first = classify(b[0]), last = classify(b[D]);
  for (auto [end, s] : {std::pair<int, SignClass*>{0, &first}, {1, &last}})
    if (*s == SignClass::unknown)
      if (const int exact = exact_sign_at_end(end); exact != contact::kUnknownSign) *s = sign_class(exact);
  if (include_ends && first == SignClass::zero) out.push_back(RootCell{0.0, 0.0, 0});
  if (isolate<D>(b, 0.0, 1.0, 0, out, first, last) == Isolation::failed) return Isolation::failed;
  if (include_ends && last == SignClass::zero) out.push_back(RootCell{1.0, 1.0, 0});
  return Isolation::complete;
}

template <int D>
Isolation isolate_roots(const contact::Poly<Interval, D>& p, RootCells& out, bool include_ends = true) {
  return isolate_roots(p, out, include_ends, [](int) { return contact::kUnknownSign; });
}

template <int D>
bool exactly_zero(const contact::Poly<Interval, D>& p) {
  for (const Interval& c : p.c)
    if (classify(c) != SignClass::zero) return false;
  return true;
}

/// Sign oracle over a time interval: certain signs, or kUnknownSign. The polynomial whose root
/// defines the candidate (if any) is zero there by construction.
struct IntervalSignOracle {
  Interval t;
  const void* zero_at_candidate = nullptr;
  template <int D>
  int operator()(const contact::Poly<Interval, D>& p) const {
    if (static_cast<const void*>(&p) == zero_at_candidate) return 0;
    const Interval value = p(t);
    const int s = certain_sign(value);
    if (s != 0) return s;
    if (value.inf() == 0 && value.sup() == 0) return 0;  // p vanishes identically on t
    return contact::kUnknownSign;
  }
};

}  // namespace exactccd::filter::interval
