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
// Underflow. The bounds above use the model fl(a op b) = (a op b)(1 + delta), |delta| <= eps.
// With gradual underflow (round to nearest, no flush-to-zero) a sum or difference obeys it
// always (a subnormal sum is exact), but a product obeys fl(a b) = a b (1 + delta) + eta with
// |eta| <= 2^-1075 (eta != 0 only when |a b| < 2^-1022). A later product multiplies such an eta
// by an entry, so a constant absolute term per operation is NOT a valid bound (2^-1075 times an
// entry 2^200 is 2^-875: that mistake once gave a false negative). Every computed quantity is a
// polynomial in the inputs, the deltas and the etas; call X~0 the value of X~ with every eta set
// to 0 and the same deltas: Shewchuk's bound only uses |delta| <= eps, so it holds between the
// eta-free values, |S~0 - S| <= (9 eps + 90 eps^2) Q~0. With M >= every |entry| of the group
// (the 18 entries of the query), each product u_x * fl(v_y w_z - v_z w_y) of a determinant
// carries |u_x| (|eta_1| + |eta_2|)(1 + eps)^2 + |eta_4| <= (2 M (1 + eps)^2 + 1) 2^-1075; the
// two sums of a determinant and the two of a group add at most a factor (1 + eps)^4 over the
// nine such products, so
//     |S~ - S~0| <= 9 (2 M (1 + eps)^2 + 1)(1 + eps)^4 2^-1075 <= (2 M + 1) 2^-1071 =: A,
// and likewise |Q~ - Q~0| <= A (the permanents use the same products). Hence
//     |S~ - S| <= (9 eps + 90 eps^2)(Q~ + A) + A.
// tau = fl(10 eps Q~) >= (10 eps - 10 eps^2) Q~ - 2^-1075 (it may be subnormal), and
// tau exceeds the bound when (eps - 100 eps^2) Q~ >= (1 + 9 eps + 90 eps^2) A + 2^-1075, which
// holds when Q~ >= (M + 1) 2^-1014: then 2^-54 Q~ >= (M + 1) 2^-1068 >= 2 A + 2^-1069. The stage
// therefore decides only when Q~ >= T = fl(fl(M 2^-1000) + 2^-1000) >= (M + 1) 2^-1001 (the
// product may underflow by 2^-1075, the sum rounds relatively). Tiny scenes (Q~ below T) and
// wide exponent spreads (huge M, tiny Q~) pass: the filtered method retries the stage on the
// query scaled by a power of two towards 1 and otherwise leaves the query to the later stages,
// which are sound for every finite input.
// Overflow: an overflowing difference or product makes M, Q~ or S~ infinite or NaN; then T is
// infinite or one of the comparisons fails, and neither S~ > tau nor S~ < -tau is accepted
// (tau is infinite whenever Q~ is): the filter does not decide, and a later stage does.
// All of this assumes round-to-nearest without flush-to-zero or denormals-are-zero: the public
// entry points establish that environment (fp_environment.hpp).
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "exactccd/types.hpp"
#include "kinds/primitive_kinds.hpp"
#include "filter/volume_block.hpp"
#include "numeric/simd_level.hpp"
#include "pipeline/block.hpp"
#include "pipeline/outcome.hpp"

namespace exactccd::filter {

/// A determinant det[u, v, w] = u . (v x w) evaluated in doubles, with its permanent.
struct RoundedDeterminant {
  double value;
  double permanent;
};

/// What a determinant u . (v x w) needs of v and w in Shewchuk's orient3dfast evaluation order:
/// the rounded cross product v x w and, per component, the sum of its two products' magnitudes
/// (for the permanent). The eight determinants of a volume share four of these (one per pair
/// of rows v_j, w_k), so each is formed once; the determinants' values are the same.
struct CrossTerms {
  Vec3 cross;      ///< fl(v_y w_z - v_z w_y), ... (the products rounded, then their difference)
  Vec3 magnitude;  ///< fl(|v_y w_z| + |v_z w_y|), ...
};

/// The cross terms of v and w (CrossTerms).
inline CrossTerms cross_terms(const Vec3& v, const Vec3& w) {
  const double vy_wz = v.y * w.z, vz_wy = v.z * w.y;
  const double vz_wx = v.z * w.x, vx_wz = v.x * w.z;
  const double vx_wy = v.x * w.y, vy_wx = v.y * w.x;
  return {{vy_wz - vz_wy, vz_wx - vx_wz, vx_wy - vy_wx},
          {std::fabs(vy_wz) + std::fabs(vz_wy), std::fabs(vz_wx) + std::fabs(vx_wz),
           std::fabs(vx_wy) + std::fabs(vy_wx)}};
}

/// det[u, v, w] from u and the cross terms of v and w, in orient3dfast's order (the error bound
/// of the comment above).
inline RoundedDeterminant rounded_determinant(const Vec3& u, const CrossTerms& vw) {
  return {u.x * vw.cross.x + u.y * vw.cross.y + u.z * vw.cross.z,
          vw.magnitude.x * std::fabs(u.x) + vw.magnitude.y * std::fabs(u.y) + vw.magnitude.z * std::fabs(u.z)};
}

/// Shewchuk's orient3dfast evaluation order, whose error bound the comment above quotes.
inline RoundedDeterminant rounded_determinant(const Vec3& u, const Vec3& v, const Vec3& w) {
  return rounded_determinant(u, cross_terms(v, w));
}

/// tau = fl(10 eps Q~), the bound of the comment above on a group's error (valid when
/// Q~ >= T).
inline double group_error_bound(double permanent_sum) { return (10 * 0x1p-53) * permanent_sum; }

/// A computed group sum S~ and a certified bound on its error: |S~ - S| < error.
struct CertifiedSum {
  double value;
  double error;
};

/// The bound of the comment above for a sum of up to three rounded determinants: tau when
/// Q~ >= T (`threshold`, from the largest entry), nothing otherwise (underflow could exceed
/// it) or when a value overflowed.
inline std::optional<CertifiedSum> certified_group(double sum, double permanent_sum, double threshold) {
  if (!(permanent_sum >= threshold)) return std::nullopt;  // underflow guard; also catches NaN
  const double tau = group_error_bound(permanent_sum);
  if (!(tau < std::numeric_limits<double>::infinity()) || !(std::fabs(sum) < std::numeric_limits<double>::infinity()))
    return std::nullopt;
  return CertifiedSum{sum, tau};
}

/// certified_group_sign's answer when the bound does not apply (Q~ below T, or an overflow).
inline constexpr int kOutOfRange = 2;

/// Certified sign of a sum of up to three rounded determinants: +1 or -1 when certain, 0 when
/// the bound leaves it open, kOutOfRange when the bound does not apply. `threshold` is T of the
/// bound above (from the largest entry). The same test as certified_group followed by a
/// comparison with the bound, written out for the hot path (an overflow makes the permanent
/// sum, and so tau, infinite: neither comparison holds, and the sign is out of range).
inline int certified_group_sign(double sum, double permanent_sum, double threshold) {
  if (!(permanent_sum >= threshold)) return kOutOfRange;  // underflow guard, see above; also catches NaN
  const double tau = group_error_bound(permanent_sum);
  if (sum > tau) return 1;
  if (sum < -tau) return -1;
  return tau < std::numeric_limits<double>::infinity() ? 0 : kOutOfRange;
}

/// The largest |coordinate| of v (NaN cannot occur: entries are differences of finite doubles).
inline double largest_magnitude(const Vec3& v) {
  const double x = std::fabs(v.x), y = std::fabs(v.y), z = std::fabs(v.z);
  const double xy = x > y ? x : y;
  return xy > z ? xy : z;
}

/// T of the bound above for the 18 entries of a volume's rows at t = 0 and t = 1.
inline double underflow_threshold(const Vec3& u0, const Vec3& u1, const Vec3& v0, const Vec3& v1,
                                  const Vec3& w0, const Vec3& w1) {
  double m = 0;
  for (const Vec3* e : {&u0, &u1, &v0, &v1, &w0, &w1}) {
    const double l = largest_magnitude(*e);
    m = m > l ? m : l;
  }
  return m * 0x1p-1000 + 0x1p-1000;  // T >= (M + 1) 2^-1014, see above
}

/// What stage 1 decides on: V's four Bernstein group sums S~_m (beta_m of the comment above,
/// m = 0..3) with their permanent sums Q~_m, and the underflow threshold T of the 18 entries.
/// The one evaluation of the stage's arithmetic: the per-query stage, the block form
/// (volume_block.hpp: the same function per lane) and the scene's time bounds all use it.
struct VolumeGroups {
  double threshold;                ///< T
  std::array<double, 4> sum;       ///< S~_m
  std::array<double, 4> permanent;  ///< Q~_m
};

/// The groups of det[u(t), v(t), w(t)], rows given at t = 0 and t = 1: the eight determinants
/// D_ijk = u_i . c_jk (c_jk the cross terms of v_j and w_k, each formed once: CrossTerms) in
/// orient3dfast's order, summed by group in the order of the proof.
[[gnu::always_inline]] inline VolumeGroups volume_groups(const Vec3& u0, const Vec3& u1, const Vec3& v0,
                                                         const Vec3& v1, const Vec3& w0, const Vec3& w1) {
  const double threshold = underflow_threshold(u0, u1, v0, v1, w0, w1);
  const CrossTerms c00 = cross_terms(v0, w0), c11 = cross_terms(v1, w1), c10 = cross_terms(v1, w0),
                   c01 = cross_terms(v0, w1);
  const RoundedDeterminant d000 = rounded_determinant(u0, c00), d111 = rounded_determinant(u1, c11);
  const RoundedDeterminant d100 = rounded_determinant(u1, c00), d010 = rounded_determinant(u0, c10),
                           d001 = rounded_determinant(u0, c01);
  const RoundedDeterminant d110 = rounded_determinant(u1, c10), d101 = rounded_determinant(u1, c01),
                           d011 = rounded_determinant(u0, c11);
  return {threshold,
          {d000.value, d100.value + d010.value + d001.value, d110.value + d101.value + d011.value, d111.value},
          {d000.permanent, d100.permanent + d010.permanent + d001.permanent,
           d110.permanent + d101.permanent + d011.permanent, d111.permanent}};
}

/// V's cubic Bernstein coefficients on [0, 1] times C(3, m) (beta_0 .. beta_3 of the comment
/// above), each with its certified error bound; nothing when a bound does not apply. The same
/// groups and proof as volume_exclusion, for callers that need the coefficients themselves
/// (the scene's time bounds subdivide them, lib/scene/time_bounds.cpp).
inline std::optional<std::array<CertifiedSum, 4>> certified_volume_bernstein(const Vec3& u0, const Vec3& u1,
                                                                             const Vec3& v0, const Vec3& v1,
                                                                             const Vec3& w0, const Vec3& w1) {
  const VolumeGroups g = volume_groups(u0, u1, v0, v1, w0, w1);
  std::array<CertifiedSum, 4> b{};
  for (std::size_t m = 0; m < 4; ++m) {
    const std::optional<CertifiedSum> c = certified_group(g.sum[m], g.permanent[m], g.threshold);
    if (!c) return std::nullopt;
    b[m] = *c;
  }
  return b;
}

/// What stage 1 proved about a volume.
enum class Exclusion {
  excluded,      ///< V(t) != 0 for every t in [0, 1]
  not_proven,    ///< the bound applies but does not prove it (a coefficient's sign is open, or
                 ///< two have opposite signs)
  out_of_range,  ///< a bound needed did not apply (underflow guard or overflow)
};

/// certified_group_sign(sum, permanent_sum, threshold) as three flags, in operations a vector
/// lane can do: +1 is `positive`, -1 `negative`, kOutOfRange `out_of_range`, 0 none of them.
/// (Flags through references, not a struct: a struct of flags stayed in memory after inlining
/// and kept the block form's loop from being vectorized.)
[[gnu::always_inline]] inline void group_sign(double sum, double permanent_sum, double threshold, bool& positive,
                                              bool& negative, bool& out_of_range) {
  const bool in_range = permanent_sum >= threshold;  // the underflow guard; false for NaN
  const double tau = group_error_bound(permanent_sum);
  positive = in_range & (sum > tau);
  negative = in_range & (sum < -tau);
  const bool open = (!positive) & (!negative);
  out_of_range = (!in_range) | (open & !(tau < std::numeric_limits<double>::infinity()));
}

/// Stage 1's verdict from the groups `g`, as flags: `excluded` when all four signs are certain
/// and equal; otherwise `out_of_range` when the first group that differs from group 0's certain
/// sign (or group 0 itself, when its sign is not certain), comparing in the order 0, 3, 1, 2, is
/// out of range (its bound did not apply: worth retrying on the query scaled towards 1), else
/// neither (not proven). Branch-free, so that the block form evaluates it in vector lanes (flags
/// through references, as group_sign's).
[[gnu::always_inline]] inline void stage_one_verdict(const VolumeGroups& g, bool& excluded, bool& out_of_range) {
  bool p0, n0, o0, p1, n1, o1, p2, n2, o2, p3, n3, o3;
  group_sign(g.sum[0], g.permanent[0], g.threshold, p0, n0, o0);
  group_sign(g.sum[1], g.permanent[1], g.threshold, p1, n1, o1);
  group_sign(g.sum[2], g.permanent[2], g.threshold, p2, n2, o2);
  group_sign(g.sum[3], g.permanent[3], g.threshold, p3, n3, o3);
  const bool differs0 = (!p0) & (!n0);  // group 0's sign not certain
  const bool differs3 = !((p0 & p3) | (n0 & n3));
  const bool differs1 = !((p0 & p1) | (n0 & n1));
  const bool differs2 = !((p0 & p2) | (n0 & n2));
  const bool same0 = !differs0, same3 = !differs3, same1 = !differs1, same2 = !differs2;
  out_of_range = (differs0 & o0) | (same0 & differs3 & o3) | (same0 & same3 & differs1 & o1) |
                 (same0 & same3 & same1 & differs2 & o2);
  excluded = same0 & same3 & same1 & same2;
}

/// Stage 1's verdict on `g` as an Exclusion.
inline Exclusion exclusion_of(const VolumeGroups& g) {
  bool excluded = false, out_of_range = false;
  stage_one_verdict(g, excluded, out_of_range);
  return excluded ? Exclusion::excluded : out_of_range ? Exclusion::out_of_range : Exclusion::not_proven;
}

/// a - b rounded, coordinate by coordinate: the rows of a volume from the query's points.
inline Vec3 rounded_difference(const Vec3& a, const Vec3& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}

/// The groups of the volume of a query of a kind with contact stages (Kind::volume_rows:
/// det[u - base, v - base, w - base]), from its rows: row(i) is row i of the query (rows(q)
/// order: the points at t0, then at t1), so that the per-query stage and the block form
/// (volume_block.cpp: row(i) reads a lane) take the same rows in the same order.
template <class Kind, class Row>
[[gnu::always_inline]] inline VolumeGroups volume_groups_of(const Row& row) {
  constexpr auto v = Kind::volume_rows;
  constexpr int n = Kind::points;  // the row of a point at t1 is n rows after its row at t0
  return volume_groups(rounded_difference(row(v[1]), row(v[0])), rounded_difference(row(v[1] + n), row(v[0] + n)),
                       rounded_difference(row(v[2]), row(v[0])), rounded_difference(row(v[2] + n), row(v[0] + n)),
                       rounded_difference(row(v[3]), row(v[0])), rounded_difference(row(v[3] + n), row(v[0] + n)));
}

/// The groups of query q's volume (volume_groups_of).
template <class Query>
inline VolumeGroups volume_groups(const Query& q) {
  const auto r = rows(q);
  return volume_groups_of<kinds::kind_of<Query>>([&](int i) { return r[static_cast<std::size_t>(i)]; });
}

/// Stage 1 for any kind: its volume V never vanishes on [0, 1], so the four points are never
/// coplanar. On a query scaled by 2^s every rounded value above is the
/// unscaled one times 2^s, 2^2s or 2^3s (by degree) unless a value is subnormal or overflows in
/// either run, and each sign test S~ > tau compares values of the same degree. The underflow
/// guard Q~ >= T does not scale alike (T is not a pure power of the scale), but where it passes
/// in both runs the signs agree, and where it fails in the scaled run the answer there is
/// out_of_range, never excluded. So a not_proven answer stays not_proven after scaling but for
/// the subnormal cases. The filtered method therefore retries on the query scaled towards 1
/// (filter/unit_scaling.hpp, VolumeRetryStage) only after out_of_range; skipping a retry can only leave a query to the
/// later stages, which are sound for every input.
template <class Query>
inline Exclusion volume_exclusion(const Query& q) {
  return exclusion_of(volume_groups(q));
}

/// volume_exclusion(q) is excluded.
template <class Query>
inline bool volume_excluded(const Query& q) {
  return volume_exclusion(q) == Exclusion::excluded;
}

/// Stage 1's handover to VolumeRetryStage (unit_scaling.hpp): its bound could not apply
/// (underflow guard or overflow), so a retry on the query scaled towards 1 may decide.
struct VolumeRange {
  bool volume_out_of_range = false;  ///< stage 1 ended out_of_range
};

/// Stage 1 of the contact question (pipeline/outcome.hpp): V(t) != 0 on [0, 1], so the four
/// points are never coplanar and the primitives never touch. Hands over whether its bound
/// could not apply (VolumeRange: worth a retry on the query scaled towards 1). Its block form
/// (pipeline/block.hpp) decides a block of queries in vector lanes (volume_block.hpp), the same
/// verdict and handover per lane.
struct VolumeExclusionStage {
  static constexpr pipeline::Counter counter = &StageCounters::volume_exclusion;  ///< counted as
  /// The stage on work.query().
  template <class Query, class Findings>
  pipeline::Outcome operator()(pipeline::Work<Query, Findings>& work) const {
    const Exclusion e = volume_exclusion(work.query());
    work.findings.volume_out_of_range = e == Exclusion::out_of_range;
    return e == Exclusion::excluded ? pipeline::Outcome::separate() : pipeline::Outcome::undecided();
  }

  /// The stage on every lane of `lanes` at numeric::simd_level().
  template <class Query, class Findings>
  pipeline::LaneDecisions block(const pipeline::QueryLanes<Query>& lanes, const pipeline::Question&,
                                std::array<Findings, pipeline::kLanes>& findings) const {
    const VolumeLaneVerdicts v = volume_exclusion_block(lanes, numeric::simd_level());
    for (std::size_t i = 0; i < lanes.size; ++i) findings[i].volume_out_of_range = (v.out_of_range >> i & 1u) != 0;
    return {v.excluded, 0};
  }
};

}  // namespace exactccd::filter
