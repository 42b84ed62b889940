// exactccd: counters of which stage of the filtered method decided each query.
#pragma once

#include <cstdint>

namespace exactccd {

/// How many queries each stage of the filtered method decided. Owned by the caller (pass one
/// per thread and add them up: the library keeps no global counters).
struct StageCounters {
  std::uint64_t volume_exclusion = 0;  ///< static filter: V(t) != 0 on [0, 1], no collision
  std::uint64_t interval = 0;          ///< interval arithmetic on the contact polynomials
  std::uint64_t exact = 0;             ///< exact fallback (GMP, CGAL algebraic kernel)
  std::uint64_t exact_toi = 0;         ///< answer from a filter, TOI enclosed by the exact path

  /// Total number of queries counted.
  std::uint64_t total() const { return volume_exclusion + interval + exact; }

  StageCounters& operator+=(const StageCounters& o) {
    volume_exclusion += o.volume_exclusion;
    interval += o.interval;
    exact += o.exact;
    exact_toi += o.exact_toi;
    return *this;
  }
};

}  // namespace exactccd
