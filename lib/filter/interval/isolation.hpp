// Interval root isolation for the interval stage (docs/design.md, 5.2): the roots of the
// contact polynomials (numeric/bernstein_isolation.hpp, at most 2^-30 apart); the certain signs
// over a cell are contact/interval_oracle.hpp's.
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
#include "contact/interval_oracle.hpp"
#include "numeric/bernstein_isolation.hpp"
#include "numeric/interval.hpp"

namespace exactccd::filter::interval {

using contact::exactly_zero;
using contact::IntervalSignOracle;
using numeric::certain_sign;
using numeric::classify;
using numeric::Interval;  // requires the rounding mode set by the caller
using numeric::Isolation;
using numeric::next_up_nonnegative;
using numeric::RootCell;
using numeric::sign_class;
using numeric::SignClass;

inline constexpr double kInf = std::numeric_limits<double>::infinity();

/// Cells of width 2^-30 at the finest; closer roots go to the exact stages.
inline constexpr numeric::IsolationLimits kIsolationLimits{30};

/// Root cells of one polynomial: at most its degree (4), so no allocation on this path.
using RootCells = boost::container::small_vector<RootCell, 4>;

/// The roots in [0, 1] of a polynomial not identically zero, in increasing order, exact zeros
/// at 0 and 1 included when include_ends (numeric::isolate_roots). `exact_sign_at_end(e)`
/// (e = 0, 1), called only when the interval value at that end is uncertain, returns the exact
/// sign there or contact::kUnknownSign.
template <int D, class EndSign>
Isolation isolate_roots(const contact::Poly<Interval, D>& p, RootCells& out, bool include_ends,
                        EndSign&& exact_sign_at_end) {
  return numeric::isolate_roots<D>(p.c, out, include_ends, kIsolationLimits, [&](int end) {
    const int exact = exact_sign_at_end(end);
    return exact == contact::kUnknownSign ? SignClass::unknown : sign_class(exact);
  });
}

template <int D>
Isolation isolate_roots(const contact::Poly<Interval, D>& p, RootCells& out, bool include_ends = true) {
  return isolate_roots(p, out, include_ends, [](int) { return contact::kUnknownSign; });
}

}  // namespace exactccd::filter::interval
