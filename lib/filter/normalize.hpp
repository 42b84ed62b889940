// Exact power-of-two normalisation of a query before the floating-point filters.
//
// Multiplying every coordinate by 2^s multiplies every contact polynomial by a positive power
// of two: signs, roots, answers and the TOI are unchanged. Bringing the largest magnitude near
// 1 keeps huge scenes (~1e300) from overflowing and tiny ones (subnormal) from underflowing in
// the filters, which would otherwise pass them on to the exact integer stage.
#pragma once

#include <cmath>

#include "exactccd/types.hpp"
#include "filter/power_of_two.hpp"

namespace exactccd::filter {

/// The query scaled by 2^s so that its largest |coordinate| lies in [1, 2), when every scaled
/// coordinate is exact (scaling up never rounds below the largest magnitude 2; scaling down may
/// underflow small coordinates, and then the query is returned unchanged). sets `scaled`.
template <class Query>
Query scaled_to_unit(const Query& q, bool& scaled) {
  scaled = false;
  auto r = rows(q);
  double largest = 0;
  // Finite input: plain comparisons (std::fmax's NaN handling costs a library call each).
  for (const Vec3& p : r)
    for (const double x : {p.x, p.y, p.z}) largest = std::fabs(x) > largest ? std::fabs(x) : largest;
  if (largest == 0) return q;
  const UnitScale unit = unit_scale(largest);
  const int s = unit.s;
  if (s == 0) return q;
  if (s > 0 && s <= 1000) {
    // Scaling up by a normal power of two: every product is exact (no underflow, and no
    // overflow since the largest result is below 2). One multiplication per coordinate.
    const double factor = unit.first;  // 2^s (unit.second is 1)
    for (Vec3& p : r) p = {p.x * factor, p.y * factor, p.z * factor};
    scaled = true;
    return from_rows<Query>(r);
  }
  for (Vec3& p : r)
    for (double* x : {&p.x, &p.y, &p.z}) {
      const double y = std::ldexp(*x, s);
      if (std::ldexp(y, -s) != *x) return q;  // a coordinate would round (underflow)
      *x = y;
    }
  scaled = true;
  return from_rows<Query>(r);
}

}  // namespace exactccd::filter
