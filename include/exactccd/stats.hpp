// exactccd: counters of which stage of the filtered method decided each query.
#pragma once

#include <cstdint>

namespace exactccd {

/// How many queries each stage of the filtered method decided. Owned by the caller (pass one
/// per thread and add them up: the library keeps no global counters).
struct StageCounters {
  std::uint64_t volume_exclusion = 0;  ///< static filter: V(t) != 0 on [0, 1], no collision
  std::uint64_t static_predicates = 0;  ///< nothing moves: CGAL's exact static predicates
  std::uint64_t interval = 0;          ///< interval arithmetic on the contact polynomials
  std::uint64_t fixed_integer = 0;     ///< exact integer arithmetic in fixed-width (1024-bit) integers
  std::uint64_t integer = 0;           ///< exact integer arithmetic in GMP, small degree-4 kernel
  std::uint64_t exact = 0;             ///< exact fallback (GMP rationals, CGAL algebraic kernel)
  std::uint64_t separating_direction = 0;  ///< a certified direction separates the primitives:
                                          ///< minimum separation, the swept primitives by more
                                          ///< than d; contact, a plane of fixed normal at t0
                                          ///< and at t1 (so at every t)
  std::uint64_t toi_refined = 0;  ///< answer from the interval stage, TOI from a later stage

  /// Total number of queries counted.
  std::uint64_t total() const {
    return volume_exclusion + static_predicates + interval + fixed_integer + integer + exact + separating_direction;
  }

  /// Adds another thread's counts.
  StageCounters& operator+=(const StageCounters& o) {
    volume_exclusion += o.volume_exclusion;
    static_predicates += o.static_predicates;
    interval += o.interval;
    fixed_integer += o.fixed_integer;
    integer += o.integer;
    exact += o.exact;
    separating_direction += o.separating_direction;
    toi_refined += o.toi_refined;
    return *this;
  }
};

}  // namespace exactccd
