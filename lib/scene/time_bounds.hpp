// Cheap certified bounds on when a pair of moving primitives can first touch, used by
// exactccd::earliest_toi to skip pairs that cannot beat the earliest contact found so far.
// Each function answers "no contact in [0, h]" only when that is certain; otherwise it passes.
#pragma once

#include <array>
#include <limits>

#include "scene/broad_phase.hpp"

namespace exactccd::scene {

/// An empty box (lo = +inf, hi = -inf), the start of a union.
inline Box empty_box() {
  constexpr double inf = std::numeric_limits<double>::infinity();
  return Box{{{inf, inf, inf}}, {{-inf, -inf, -inf}}};
}

/// Grows `box` to hold both positions of a vertex moving from p0 (t = 0) to p1 (t = 1): its
/// exact swept box over [0, 1] (min and max of input coordinates: no rounding).
inline void add_vertex(Box& box, const Vec3& p0, const Vec3& p1) {
  const double a[3] = {p0.x, p0.y, p0.z}, b[3] = {p1.x, p1.y, p1.z};
  for (int k = 0; k < 3; ++k) {
    const double lo = a[k] < b[k] ? a[k] : b[k], hi = a[k] < b[k] ? b[k] : a[k];
    box.lo[k] = lo < box.lo[k] ? lo : box.lo[k];
    box.hi[k] = hi > box.hi[k] ? hi : box.hi[k];
  }
}

/// Grows `box` to hold the positions over the times [0, h] (h in [0, 1]) of a vertex moving
/// linearly from p0 (t = 0) to p1 (t = 1). Certified despite rounding (see the .cpp).
void add_vertex_until(Box& box, const Vec3& p0, const Vec3& p1, double h);

/// True only if the four moving points, at_t0[i] + t (at_t1[i] - at_t0[i]), are certainly not
/// coplanar for any t in [0, h] (h in [0, 1]): the volume det[q1 - q0, q2 - q0, q3 - q0] keeps
/// one strict sign there, proved with interval arithmetic on its Bernstein coefficients over
/// [0, h]. A vertex-face or edge-edge contact needs its four points coplanar, so then the pair
/// has no contact in [0, h].
bool never_coplanar_until(const std::array<Vec3, 4>& at_t0, const std::array<Vec3, 4>& at_t1, double h);

}  // namespace exactccd::scene
