// Stage 1 of the filtered method: a static floating-point filter proving that the volume
// V(t) keeps one strict sign on [0, 1], so that the four points are never coplanar and the
// query cannot collide. No rounding-mode switch, no allocation.
//
// The math (docs/design.md, "Volume exclusion"). V(t) = det[u(t), v(t), w(t)] where the rows
// are linear in t: u(t) = (1 - t) u0 + t u1 and likewise v, w. The determinant is trilinear,
// so in the cubic Bernstein basis B_m(t) = C(3, m) (1 - t)^(3-m) t^m its coefficients are
// beta_m / C(3, m) with
//     beta_0 = D000, beta_1 = D100 + D010 + D001, beta_2 = D110 + D101 + D011, beta_3 = D111,
// D_ijk = det[u_i, v_j, w_k]. If every beta_m > 0 then V(t) > 0 on [0, 1] (a sum of
// non-negative terms, at least one positive for each t); likewise for < 0.
//
// Error bound (Shewchuk 1997, "Adaptive precision floating-point arithmetic and fast robust
// geometric predicates", orient3d), valid under the range condition below. Each D_ijk is a
// 3x3 determinant whose entries are single rounded differences of input doubles, evaluated as
// in Shewchuk's orient3dfast; with eps = 2^-53 and P~ its permanent computed in floating point,
//     |D~ - D| <= (7 + 56 eps) eps P~                                     (Shewchuk, o3derrboundA)
// and |D~| <= (1 + 4 eps) P~ (each |term| is rounded at most 3 times more than in P~).
// A group sum S~ = fl(fl(D~1 + D~2) + D~3) adds two roundings, each at most eps times the
// magnitude of its exact result, so with Q = P~1 + P~2 + P~3,
//     |S~ - S| <= (7 eps + 56 eps^2) Q + eps (1 + 4 eps) Q + eps (1 + eps)(1 + 4 eps) Q
//              <= (9 eps + 70 eps^2) Q.
// The computed Q~ = fl(fl(P~1 + P~2) + P~3) >= Q (1 - eps)^2 (non-negative terms), so
//     |S~ - S| <= (9 eps + 70 eps^2) / (1 - eps)^2 Q~ <= (9 eps + 90 eps^2) Q~,
// and the threshold tau = fl(10 eps * Q~) >= (10 eps - 10 eps^2) Q~ exceeds that bound. Hence
// S~ > tau implies S > 0 and S~ < -tau implies S < 0.
//
// Range condition (underflow and overflow). The bounds above use the model
// fl(a op b) = (a op b)(1 + delta), |delta| <= eps, for every operation. With gradual underflow
// (round to nearest, no flush-to-zero) a sum or difference obeys it always (a subnormal sum is
// exact), but a product whose exact value is below 2^-1022 in magnitude may err by 2^-1075
// absolutely, and a later product multiplies that error by an entry: an absolute term added
// per operation is NOT a valid bound (2^-1075 times an entry 2^200 is 2^-875). So the stage
// decides only when no product can underflow or overflow: every entry e (a rounded difference,
// computed exactly or with relative error only) is 0 or 2^-300 <= |e| <= 2^300. Then
// - a product of two entries is 0 or in [2^-600, 2^600] (normal, relative error only);
// - such a product is a double of exponent >= -600, a multiple of 2^-652, so a difference of
//   two of them is 0 or in [2^-652, 2^601];
// - its product with a third entry is 0 or in [2^-952, 2^902] (normal);
// - sums of at most nine such terms stay below 2^906: no overflow anywhere, and sums never
//   underflow (see above);
// - the permanents have the same products; Q~ is 0 or at least 2^-952, so tau = fl(10 eps Q~)
//   is 0 or at least 2^-1006 (normal: relative rounding only; 10 eps is exact). Q~ = 0 gives
//   S~ = 0 and no decision.
// Outside the range (a wide exponent spread, tiny or huge scenes) the stage passes; the
// filtered method retries it on the query scaled by a power of two towards 1 and otherwise
// leaves the query to the later stages, which are sound for every finite input. NaN entries
// (inf - inf) fail the range test too. All of this assumes round-to-nearest without
// flush-to-zero or denormals-are-zero: the public entry points establish that environment
// (fp_environment.hpp).
#pragma once

#include <cmath>

#include "exactccd/types.hpp"

namespace exactccd::filter {

/// A determinant det[u, v, w] = u . (v x w) evaluated in doubles, with its permanent.
struct RoundedDeterminant {
  double value;
  double permanent;
};

/// Shewchuk's orient3dfast evaluation order, whose error bound the comment above quotes.
inline RoundedDeterminant rounded_determinant(const Vec3& u, const Vec3& v, const Vec3& w) {
  const double vy_wz = v.y * w.z, vz_wy = v.z * w.y;
  const double vz_wx = v.z * w.x, vx_wz = v.x * w.z;
  const double vx_wy = v.x * w.y, vy_wx = v.y * w.x;
  return {u.x * (vy_wz - vz_wy) + u.y * (vz_wx - vx_wz) + u.z * (vx_wy - vy_wx),
          (std::fabs(vy_wz) + std::fabs(vz_wy)) * std::fabs(u.x) +
              (std::fabs(vz_wx) + std::fabs(vx_wz)) * std::fabs(u.y) +
              (std::fabs(vx_wy) + std::fabs(vy_wx)) * std::fabs(u.z)};
}

/// Certified sign of a sum of up to three rounded determinants: +1 or -1 when certain, 0 when
/// the filter cannot tell (see the bound above; entries must satisfy the range condition).
inline int certified_group_sign(double sum, double permanent_sum) {
  constexpr double kEps = 0x1p-53;
  const double tau = (10 * kEps) * permanent_sum;
  if (sum > tau) return 1;
  if (sum < -tau) return -1;
  return 0;  // also for Q~ = 0
}

/// The range condition above: e is 0 or 2^-300 <= |e| <= 2^300 (false for NaN). Written with
/// non-short-circuit operators so that the 18 tests of a query vectorise.
inline bool in_filter_range(double e) {
  const double a = std::fabs(e);
  return (a <= 0x1p300) & ((a >= 0x1p-300) | (a == 0));
}

inline bool in_filter_range(const Vec3& v) {
  return in_filter_range(v.x) & in_filter_range(v.y) & in_filter_range(v.z);
}

/// Certified "V(t) != 0 for every t in [0, 1]" for the volume det[u(t), v(t), w(t)], rows given
/// at t = 0 and t = 1 as rounded differences of the input points. False means "not proven"
/// (also whenever an entry is outside the range where the error bound is valid).
inline bool volume_certainly_nonzero(const Vec3& u0, const Vec3& u1, const Vec3& v0,
                                     const Vec3& v1, const Vec3& w0, const Vec3& w1) {
  if (!(in_filter_range(u0) & in_filter_range(u1) & in_filter_range(v0) & in_filter_range(v1) &
        in_filter_range(w0) & in_filter_range(w1)))
    return false;
  const RoundedDeterminant d000 = rounded_determinant(u0, v0, w0);
  const int s0 = certified_group_sign(d000.value, d000.permanent);
  if (s0 == 0) return false;
  const RoundedDeterminant d111 = rounded_determinant(u1, v1, w1);
  if (certified_group_sign(d111.value, d111.permanent) != s0) return false;
  const RoundedDeterminant d100 = rounded_determinant(u1, v0, w0);
  const RoundedDeterminant d010 = rounded_determinant(u0, v1, w0);
  const RoundedDeterminant d001 = rounded_determinant(u0, v0, w1);
  if (certified_group_sign(d100.value + d010.value + d001.value,
                           d100.permanent + d010.permanent + d001.permanent) != s0)
    return false;
  const RoundedDeterminant d110 = rounded_determinant(u1, v1, w0);
  const RoundedDeterminant d101 = rounded_determinant(u1, v0, w1);
  const RoundedDeterminant d011 = rounded_determinant(u0, v1, w1);
  return certified_group_sign(d110.value + d101.value + d011.value,
                              d110.permanent + d101.permanent + d011.permanent) == s0;
}

inline Vec3 rounded_difference(const Vec3& a, const Vec3& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}

/// Stage 1 for vertex-face: V = (b - a) . ((c - a) x (p - a)) never vanishes on [0, 1].
inline bool vertex_face_volume_excluded(const VertexFaceQuery& q) {
  return volume_certainly_nonzero(
      rounded_difference(q.b_t0, q.a_t0), rounded_difference(q.b_t1, q.a_t1),
      rounded_difference(q.c_t0, q.a_t0), rounded_difference(q.c_t1, q.a_t1),
      rounded_difference(q.p_t0, q.a_t0), rounded_difference(q.p_t1, q.a_t1));
}

/// Stage 1 for edge-edge: V = (a1 - a0) . ((b0 - a0) x (b1 - a0)) never vanishes on [0, 1].
inline bool edge_edge_volume_excluded(const EdgeEdgeQuery& q) {
  return volume_certainly_nonzero(
      rounded_difference(q.a1_t0, q.a0_t0), rounded_difference(q.a1_t1, q.a0_t1),
      rounded_difference(q.b0_t0, q.a0_t0), rounded_difference(q.b0_t1, q.a0_t1),
      rounded_difference(q.b1_t0, q.a0_t0), rounded_difference(q.b1_t1, q.a0_t1));
}

}  // namespace exactccd::filter
