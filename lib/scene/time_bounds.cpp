#include "scene/time_bounds.hpp"

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace exactccd::scene {
namespace {

using Interval = CGAL::Interval_nt<false>;  // only under Protect_FPU_rounding

struct IVec {
  Interval x, y, z;
};

IVec difference(const Vec3& a, const Vec3& b) {
  return {Interval(a.x) - Interval(b.x), Interval(a.y) - Interval(b.y), Interval(a.z) - Interval(b.z)};
}

Interval det(const IVec& u, const IVec& v, const IVec& w) {
  return u.x * (v.y * w.z - v.z * w.y) + u.y * (v.z * w.x - v.x * w.z) + u.z * (v.x * w.y - v.y * w.x);
}

}  // namespace

Box empty_box() {
  constexpr double inf = std::numeric_limits<double>::infinity();
  return Box{{{inf, inf, inf}}, {{-inf, -inf, -inf}}};
}

// Per coordinate, with a = x(0), b = x(1): x(h) = a + h (b - a) lies between a and b. The
// computed m = fl(a + fl(h fl(b - a))) is within 4u M + O(u^2) M + 2^-1074 of it (u = 2^-53,
// M = |a| + |b|: three roundings of terms bounded by 2M, one possible underflow). The pad
// fl(2^-50 fl(M)) + 2^-1070 is at least 7.9 u M + 2^-1071, which also covers the rounding of
// m -+ pad (at most u (M + pad)): [fl(m - pad), fl(m + pad)] holds x(h). Clamped to
// [min(a, b), max(a, b)], which holds x(h) too; on overflow (inf or NaN) the clamp alone
// remains. The box over [0, h] is the hull of x(0) = a and x(h), x being linear.
void add_vertex_until(Box& box, const Vec3& p0, const Vec3& p1, double h) {
  const double a[3] = {p0.x, p0.y, p0.z}, b[3] = {p1.x, p1.y, p1.z};
  for (int k = 0; k < 3; ++k) {
    const double m = a[k] + h * (b[k] - a[k]);
    const double pad = 0x1p-50 * (std::fabs(a[k]) + std::fabs(b[k])) + 0x1p-1070;
    double lo = m - pad, hi = m + pad;
    if (!(lo >= std::min(a[k], b[k]))) lo = std::min(a[k], b[k]);  // also when NaN
    if (!(hi <= std::max(a[k], b[k]))) hi = std::max(a[k], b[k]);
    box.lo[k] = std::min({box.lo[k], a[k], lo});
    box.hi[k] = std::max({box.hi[k], a[k], hi});
  }
}

// V(t) = det[u(t), v(t), w(t)] with rows linear in t is trilinear: its cubic Bernstein
// coefficients on [0, 1] are D000, (D100 + D010 + D001) / 3, (D110 + D101 + D011) / 3, D111
// with D_ijk = det[u_i, v_j, w_k] (design.md, 5.1). De Casteljau's algorithm at h gives the
// coefficients on [0, h] (b0, b01, b012, b0123); if all four are > 0, V > 0 on [0, h] (a
// positive combination of non-negative Bernstein polynomials summing to 1), likewise < 0.
// Every operation is an interval enclosing the exact value (rounding towards +infinity), so
// a certain sign of every enclosure is the sign of the exact coefficient; an infinite or NaN
// bound never certifies anything.
bool never_coplanar_until(const std::array<Vec3, 4>& at_t0, const std::array<Vec3, 4>& at_t1, double h) {
  CGAL::Protect_FPU_rounding<true> rounding_towards_infinity;
  IVec rows[2][3];
  for (int i = 0; i < 3; ++i) {
    rows[0][i] = difference(at_t0[i + 1], at_t0[0]);
    rows[1][i] = difference(at_t1[i + 1], at_t1[0]);
  }
  const auto d = [&](int i, int j, int k) { return det(rows[i][0], rows[j][1], rows[k][2]); };
  const Interval b0 = d(0, 0, 0), b1 = (d(1, 0, 0) + d(0, 1, 0) + d(0, 0, 1)) / 3,
                 b2 = (d(1, 1, 0) + d(1, 0, 1) + d(0, 1, 1)) / 3, b3 = d(1, 1, 1);
  const Interval s(h), r = Interval(1) - s;
  const Interval b01 = r * b0 + s * b1, b12 = r * b1 + s * b2, b23 = r * b2 + s * b3;
  const Interval b012 = r * b01 + s * b12, b123 = r * b12 + s * b23;
  const Interval b0123 = r * b012 + s * b123;
  const Interval left[4] = {b0, b01, b012, b0123};
  bool positive = true, negative = true;
  for (const Interval& c : left) {
    positive = positive && c.inf() > 0;
    negative = negative && c.sup() < 0;
  }
  return positive || negative;
}

}  // namespace exactccd::scene
