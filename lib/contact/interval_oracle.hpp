// The contact rule's sign oracle (contact_rule.hpp) over a time interval, for polynomials with
// interval coefficients: the linear contact filter's strategies (filter/interval/) and the
// rigid coplanar walk (rigid/coplanar_walk.cpp) evaluate the rule with it at a candidate root.
//
// Soundness rests on the inclusion property of interval arithmetic: p evaluated over the time
// interval T (Horner's scheme in CGAL::Interval_nt) contains p(t) for every t in T, so a sign it
// certifies (numeric::interval_sign) is p's sign at every t in T. Needs the upward rounding of
// CGAL::Protect_FPU_rounding<true>, held by the caller.
#pragma once

#include "contact/polynomial.hpp"
#include "numeric/interval.hpp"

namespace exactccd::contact {

/// True when every coefficient of p is exactly [0, 0]: each encloses its exact coefficient, so
/// the exact polynomial vanishes identically.
template <int D>
bool exactly_zero(const Poly<numeric::Interval, D>& p) {
  for (const numeric::Interval& c : p.c)
    if (numeric::classify(c) != numeric::SignClass::zero) return false;
  return true;
}

/// Sign oracle over a time interval: the signs the polynomials' values over `t` certify
/// (numeric::interval_sign: kUnknownSign where they certify none). The polynomial whose root
/// defines the candidate (if any) is zero there by construction.
struct IntervalSignOracle {
  numeric::Interval t;                   ///< the time interval (a root's cell)
  const void* zero_at_candidate = nullptr;  ///< the polynomial whose root the candidate is, or null
  /// The sign of p over t.
  template <int D>
  int operator()(const Poly<numeric::Interval, D>& p) const {
    if (static_cast<const void*>(&p) == zero_at_candidate) return 0;
    return numeric::interval_sign(p(t));
  }
};

}  // namespace exactccd::contact
