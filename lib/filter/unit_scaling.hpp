// Exact power-of-two normalisation of a query before the floating-point filters.
//
// Multiplying every coordinate by 2^s multiplies every contact polynomial by a positive power
// of two: signs, roots, answers and the TOI are unchanged. Bringing the largest magnitude near
// 1 keeps huge scenes (~1e300) from overflowing and tiny ones (subnormal) from underflowing in
// the filters, which would otherwise pass them on to the exact integer stage.
#pragma once

#include <cmath>
#include <cstddef>

#include "exactccd/types.hpp"
#include "filter/volume_exclusion.hpp"
#include "numeric/power_of_two.hpp"
#include "pipeline/outcome.hpp"

namespace exactccd::filter {

/// Writes to `out` the query q scaled by 2^s so that its largest |coordinate| lies in [1, 2),
/// and returns true, when s != 0 and every scaled coordinate is exact (scaling up never rounds
/// below the largest magnitude 2; scaling down may underflow small coordinates, and then `out`
/// is left as it was and the answer is false).
template <class Query>
bool scale_to_unit(const Query& q, Query& out) {
  auto r = rows(q);
  // Finite input: plain comparisons (std::fmax's NaN handling costs a library call each), in
  // four independent running maxima (one chain of 24 dependent comparisons was most of this
  // function's time on the cloth-ball step); the maximum is the same in any order.
  double m[4] = {0, 0, 0, 0};
  for (std::size_t i = 0; i < r.size(); ++i) {
    const double c[3] = {std::fabs(r[i].x), std::fabs(r[i].y), std::fabs(r[i].z)};
    double& a = m[i % 2 * 2];
    double& b = m[i % 2 * 2 + 1];
    a = c[0] > a ? c[0] : a;
    b = c[1] > b ? c[1] : b;
    a = c[2] > a ? c[2] : a;
  }
  const double m01 = m[0] > m[1] ? m[0] : m[1], m23 = m[2] > m[3] ? m[2] : m[3];
  const double largest = m01 > m23 ? m01 : m23;
  if (largest == 0) return false;
  const numeric::UnitScale unit = numeric::unit_scale(largest);
  const int s = unit.s;
  if (s == 0) return false;
  if (s > 0 && s <= 1000) {
    // Scaling up by a normal power of two: every product is exact (no underflow, and no
    // overflow since the largest result is below 2). One multiplication per coordinate.
    const double factor = unit.first;  // 2^s (unit.second is 1)
    for (Vec3& p : r) p = {p.x * factor, p.y * factor, p.z * factor};
    out = from_rows<Query>(r);
    return true;
  }
  if (s < 0 && s >= -1022) {
    // Scaling down by a normal power of two 2^s: y = fl(x 2^s) is x 2^s exactly unless that
    // lies in the subnormal range and has bits below 2^-1074. Multiplying back by 2^-s (a
    // normal double, s >= -1022) is exact (|y| < 2, so y 2^-s < 2^1023: a power-of-two
    // product that neither overflows nor underflows), so y 2^-s == x iff y is exact, in any
    // rounding direction. Two multiplications per coordinate instead of two library calls.
    const double factor = numeric::power_of_two(s), back = numeric::power_of_two(-s);
    bool exact = true;
    for (Vec3& p : r) {
      const Vec3 y{p.x * factor, p.y * factor, p.z * factor};
      exact &= (y.x * back == p.x) & (y.y * back == p.y) & (y.z * back == p.z);
      p = y;
    }
    if (!exact) return false;  // a coordinate would round (underflow): `out` untouched
    out = from_rows<Query>(r);
    return true;
  }
  for (Vec3& p : r)
    for (double* x : {&p.x, &p.y, &p.z}) {
      const double y = std::ldexp(*x, s);
      if (std::ldexp(y, -s) != *x) return false;  // a coordinate would round (underflow)
      *x = y;
    }
  out = from_rows<Query>(r);
  return true;
}

/// The query scaled as by scale_to_unit, or q itself; `scaled` tells which.
template <class Query>
Query scaled_to_unit(const Query& q, bool& scaled) {
  Query out = q;
  scaled = scale_to_unit(q, out);
  return out;
}

/// The contact question's step right after stage 1, where its range limits stopped it
/// (volume_exclusion.hpp: otherwise the scaled query's rounded values are the same up to a power
/// of two, and the retry could not decide): the query brought to a magnitude near 1 (exactly:
/// answers are unchanged) and stage 1 retried on it. Counted as volume exclusion when the retry
/// decides.
struct VolumeRetryStage {
  static constexpr pipeline::Counter counter = &StageCounters::volume_exclusion;  ///< counted as
  /// Rescales work.query() and retries stage 1, only after an out-of-range stage 1.
  template <class Query, class Findings>
  pipeline::Outcome operator()(pipeline::Work<Query, Findings>& work) const {
    if (!work.findings.volume_out_of_range) return pipeline::Outcome::undecided();
    if (!scale_to_unit(work.query(), work.replacement())) return pipeline::Outcome::undecided();
    work.use_replacement();
    return volume_excluded(work.query()) ? pipeline::Outcome::separate() : pipeline::Outcome::undecided();
  }
};

/// The contact question's step before the interval stage (never decides): the query brought to
/// a magnitude near 1 (exactly: answers are unchanged) so that huge or tiny coordinates do not
/// overflow or underflow the interval and integer stages. After the static and separating-plane
/// stages, which need no scaling (exact predicates; a frame scaled by the plane stage itself),
/// so that the queries they decide (most of those stage 1 passes on) are not copied and scaled.
/// A query VolumeRetryStage scaled already is at unit scale: scaling it again changes nothing.
struct UnitScalingStage {
  static constexpr pipeline::Counter counter = &StageCounters::volume_exclusion;  ///< never decides
  /// Rescales work.query(); always undecided.
  template <class Query, class Findings>
  pipeline::Outcome operator()(pipeline::Work<Query, Findings>& work) const {
    if (scale_to_unit(work.query(), work.replacement())) work.use_replacement();
    return pipeline::Outcome::undecided();
  }
};

}  // namespace exactccd::filter
