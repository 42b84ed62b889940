#include "scene/time_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "filter/unit_scaling.hpp"
#include "filter/volume_exclusion.hpp"
#include "numeric/interval.hpp"

namespace exactccd::scene {
namespace {

using numeric::Interval;  // only under Protect_FPU_rounding

}  // namespace

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
// coefficients on [0, 1] are beta_0, beta_1 / 3, beta_2 / 3, beta_3 (design.md, 5.1). They come
// from the filtered method's stage 1 with its certified error bounds (one static volume filter,
// one proof: filter/volume_exclusion.hpp), as intervals [beta~ - tau, beta~ + tau] holding the
// exact values. De Casteljau's algorithm at h in interval arithmetic (rounding towards
// +infinity, every operation enclosing the exact value) gives enclosures of the coefficients on
// [0, h] (b0, b01, b012, b0123); if all four are certainly > 0, V > 0 on [0, h] (a positive
// combination of non-negative Bernstein polynomials summing to 1), likewise < 0. Where stage 1's
// bound does not apply (tiny or overflowing entries) nothing is proved.
bool never_coplanar_until(const std::array<Vec3, 4>& at_t0, const std::array<Vec3, 4>& at_t1, double h) {
  const auto difference = [](const Vec3& a, const Vec3& b) { return Vec3{a.x - b.x, a.y - b.y, a.z - b.z}; };
  const auto certified = [&](const std::array<Vec3, 8>& r) {
    return filter::certified_volume_bernstein(difference(r[1], r[0]), difference(r[5], r[4]),
                                              difference(r[2], r[0]), difference(r[6], r[4]),
                                              difference(r[3], r[0]), difference(r[7], r[4]));
  };
  const std::array<Vec3, 8> points{at_t0[0], at_t0[1], at_t0[2], at_t0[3], at_t1[0], at_t1[1], at_t1[2], at_t1[3]};
  auto beta = certified(points);
  if (!beta) {
    // Tiny (or huge) points: the same test on the points scaled exactly by a power of two
    // towards 1 (V scales by a positive factor, its signs do not change), as the filtered method
    // retries stage 1.
    bool scaled = false;
    const auto q = filter::scaled_to_unit(from_rows<VertexFaceQuery>(points), scaled);
    if (scaled) beta = certified(rows(q));
  }
  if (!beta) return false;
  CGAL::Protect_FPU_rounding<true> rounding_towards_infinity;
  const auto enclosure = [](const filter::CertifiedSum& x) {
    return Interval(x.value) + Interval(-x.error, x.error);
  };
  const Interval b0 = enclosure((*beta)[0]), b1 = enclosure((*beta)[1]) / 3, b2 = enclosure((*beta)[2]) / 3,
                 b3 = enclosure((*beta)[3]);
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
