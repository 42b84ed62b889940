// The power of two that brings a magnitude into [1, 2), as factors that are normal doubles:
// shared by the filters that scale a query before evaluating it (filter/unit_scaling.hpp,
// rigid/rigid_unit_scaling.hpp, separation/distance_sign.hpp,
// separation/separating_direction.hpp). Multiplying by a power of two is exact unless the result
// leaves the normal range, which each caller handles.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace exactccd::numeric {

/// floor(log2 v) for a finite v > 0 (std::ilogb without the library call for normal v).
inline int binary_exponent(double v) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &v, sizeof bits);
  const int biased = static_cast<int>(bits >> 52 & 0x7ff);
  return biased != 0 ? biased - 1023 : std::ilogb(v);  // subnormal: rare, the library
}

/// 2^k as a double, for k in [-1022, 1023] (normal: exact from its bits).
inline double power_of_two(int k) {
  const std::uint64_t bits = static_cast<std::uint64_t>(k + 1023) << 52;
  double v = 0;
  std::memcpy(&v, &bits, sizeof v);
  return v;
}

/// 2^s with largest 2^s in [1, 2), for a finite largest > 0: s in [-1023, 1074], as the product
/// of two normal doubles first * second (2^1074 and 2^-1023 are not normal doubles), applied in
/// that order by apply().
struct UnitScale {
  int s = 0;
  double first = 1, second = 1;
  double apply(double v) const { return (v * first) * second; }
};

inline UnitScale unit_scale(double largest) {
  UnitScale r;
  r.s = -binary_exponent(largest);
  const int k = std::clamp(r.s, -1022, 1000);
  r.first = power_of_two(k);
  r.second = power_of_two(r.s - k);
  return r;
}

}  // namespace exactccd::numeric
