// The filtered method's stage for minimum separation: a certified separating direction.
//
// Why a direction separates. Every point of A(t), t in [0, 1], is a convex combination of A's
// vertices at t, and each of those of the vertex's positions at t0 and t1 (linear motion). So
// for any vector n != 0, n.a <= max over A's rows of n.x and n.b >= min over B's rows of n.x,
// and if gap = min_B n.x - max_A n.x > d |n| then n.(b - a) > d |n| and, by Cauchy-Schwarz,
// |b - a| > d for every a in A(t), b in B(t), t in [0, 1]: no collision (likewise with A and
// B exchanged). n is any double vector (only its finiteness matters, not its accuracy).
//
// How it is certified, in plain doubles with a static error bound (no interval arithmetic, no
// rounding-mode switch). The bound holds in every rounding mode (each operation's relative
// error is below e = 2^-52, a product's absolute error in the subnormal range below 2^-1074);
// subnormals must be honoured (the callers' DefaultFpEnvironment clears flush-to-zero).
//  1. Frame (ProjectionFrame). When the largest coordinate magnitude X lies outside
//     [2^-400, 2^400], every coordinate and d are multiplied by the power of two 2^s that
//     brings X into [1, 2): exact, except that a result in the subnormal range may be off by
//     less than 2^-1073 (the scaling is two products when s = -1023) (and d 2^s may overflow,
//     to infinity or, rounding downward or toward zero, to the largest double: either way
//     nothing certifies, rightly, since every gap is then below 2^5). The gap and d scale alike, so the question is
//     unchanged. Either way X <= 2^400 now. Then the first row o is subtracted from every row
//     (|x - o| <= 2^401, no overflow): y = x - o with a relative error below e. A common
//     translation changes no gap. Y is the largest |y| (bounds relative to the primitives'
//     local extent, not to their distance from the origin).
//  2. Direction. n is divided by its largest component magnitude (any rounding: the result is
//     just another direction): that component is exactly +-1 and the others are in [-1, 1], so
//     |n|_1 <= 3 and 1 <= n.n <= 3.
//  3. Projections p = (n_x y_x + n_y y_y) + n_z y_z. Against n.(exact translated, scaled row):
//     the rounding of the projection, gamma_3 sum |n_k y_k| + 3 2^-1074 (1 + e)^2
//     <= 3.01 e 3 Y + 2^-1072, plus sum |n_k| |error of y_k| <= 3 (1.01 e Y + 2^-1072) (the
//     translation's rounding, and less than 2^-1073 for each of the two scaled coordinates it
//     subtracts): in all below 12.1 e Y + 2^-1069 < 2^-48 Y (1 - e) + 2^-1061 <= E =
//     fl(Y 2^-48) + 2^-1060 (fl(Y 2^-48) >= Y 2^-48 - 2^-1074, and the sum of two positive
//     doubles is at least their exact sum times 1 - e).
//  4. Gap. With a_hi the largest computed projection of one side and b_lo the least of the
//     other, the exact gap is at least (b_lo - a_hi) - 2E, and g = fl(b_lo - a_hi) is at most
//     (b_lo - a_hi)(1 + e) when positive. With r = fl(sqrt(fl(n.n))), |n| <= r (1 + 2^-50)
//     (n.n >= 1, so underflowed squares are negligible: the sum's relative error is below
//     3.02 e, the square root's below e), and the exact d 2^s is below d' + 2^-1073 (d' its
//     computed value), so d |n| <= fl(d' r) (1 + 2^-49) + 2^-1070. Hence gap > d |n| when
//     g > (1 + e) (2E + fl(d' r) (1 + 2^-49) + 2^-1070), which the computed
//     T = fl(fl(fl(2E + fl(d' r)) + 2^-1060) (1 + 2^-47)) is at least (three roundings cost
//     at most 3e, and 2^-47 - 3e > 2^-52 + 2^-49 + 2^-100). The test is g > T (decided first
//     against T at r = 1 and at r = 2, which bound it: ProjectionFrame's threshold_at_least and
//     threshold_at_most; the square root only when g falls between them); a T made infinite or
//     huge by d' (overflowed) never certifies, and nothing else is near overflow (every |y| and
//     every difference of rows below 2^402, a natural direction's components below 2^806
//     before it is normalised (point-edge: r x e is normalised before the second cross
//     product), every |p| < 2^404, E < 2^355). A natural direction that is not finite, or zero,
//     is skipped. T may be subnormal: additions are then exact and fl(x (1 + 2^-47)) >= x in
//     every rounding mode, so T still bounds what it must.
// Directions tried: each of the kind's feature pairs' natural direction at t0, in order (the
// primitives' own pair first), then each at t1 (point-point: y - x; point-edge: e x (r x e),
// the perpendicular from the line to the point; point-triangle: the normal; edge-edge:
// da x db), then the coordinate axes (on the simulation sets, candidates of a broad phase,
// the first pair's direction at t0 decides most queries and the axes none).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>

#include "contact/vec3_ops.hpp"
#include "exactccd/types.hpp"
#include "numeric/power_of_two.hpp"
#include "kinds/primitive_kinds.hpp"
#include "pipeline/outcome.hpp"
#include "contact/separation_terms.hpp"

namespace exactccd::separation {

/// Which set a point belongs to in points_separated: neither, the first or the second.
enum class Side { none, first, second };

/// A query's rows and d in the frame of the header's step 1 (scaled by a power of two,
/// translated to the first row), with the projection error bound E of step 3. `usable` is
/// false when every coordinate is zero (no direction can separate anything then).
template <std::size_t N>
struct ProjectionFrame {
  std::array<Vec3, N> y;
  double d = 0;      ///< d 2^s (possibly infinite)
  double error = 0;  ///< E: bounds |computed n.y - exact n.(row)| for a normalised n
  double extent = 0;  ///< Y: the largest |y| at t0 and t1
  /// The threshold T of step 4 for |n| taken as 1 and as 2: T of any normalised direction
  /// lies between them (set_threshold_bounds), so most gaps are decided without a square root.
  double threshold_at_least = 0, threshold_at_most = 0;
  bool usable = false;

  /// T of step 4 for the computed length r of the normalised direction.
  double threshold_for_length(double r) const { return ((2 * error + d * r) + 0x1p-1060) * (1 + 0x1p-47); }

  /// The frame of rows `x` (finite doubles) and the minimum distance d >= 0 (finite).
  ProjectionFrame(const std::array<Vec3, N>& x, double min_distance) {
    double largest = 0;
    for (const Vec3& p : x) largest = std::max(largest, std::max(std::fabs(p.x), std::max(std::fabs(p.y), std::fabs(p.z))));
    if (!(largest > 0)) return;
    // Scaled only outside [2^-400, 2^400] (step 1 of the header), by 2^s: largest 2^s in [1, 2).
    if (largest >= 0x1p-400 && largest <= 0x1p400) {
      for (std::size_t i = 0; i < N; ++i) y[i] = {x[i].x - x[0].x, x[i].y - x[0].y, x[i].z - x[0].z};
      d = min_distance;
    } else {
      const numeric::UnitScale unit = numeric::unit_scale(largest);
      const auto scale = [&](double v) { return unit.apply(v); };
      const Vec3 o{scale(x[0].x), scale(x[0].y), scale(x[0].z)};
      for (std::size_t i = 0; i < N; ++i) y[i] = {scale(x[i].x) - o.x, scale(x[i].y) - o.y, scale(x[i].z) - o.z};
      d = scale(min_distance);
    }
    double extent = 0;
    for (const Vec3& p : y) extent = std::max(extent, std::max(std::fabs(p.x), std::max(std::fabs(p.y), std::fabs(p.z))));
    this->extent = extent;
    error = extent * 0x1p-48 + 0x1p-1060;
    set_threshold_bounds();
    usable = true;
  }

  /// The rows at the times a and b (doubles, 0 <= a <= b <= 1) in place of t0 and t1: the
  /// points move linearly over [a, b] as well, so a direction certified on these rows
  /// separates over [a, b]. Each row y0 + a (y1 - y0) is computed with an error below
  /// 7.01 e Y + 2^-1074 per coordinate (the difference, the product, the sum; every |y| <= Y),
  /// on top of y's own 1.01 e Y + 2^-1072; the rows stay below Y (1 + 9 e) in magnitude, so a
  /// projection errs by at most 9.03 e Y (1 + 9 e) + 3 (8.02 e Y + 2^-1071) < 2^-46 Y + 2^-1068:
  /// the error bound becomes fl(Y 2^-46) + 2^-1060 (as in step 3 of the header).
  ProjectionFrame over(double a, double b) const {
    ProjectionFrame r = *this;
    constexpr std::size_t P = N / 2;
    for (std::size_t i = 0; i < P; ++i) {
      const Vec3 &y0 = y[i], &y1 = y[i + P];
      const Vec3 delta{y1.x - y0.x, y1.y - y0.y, y1.z - y0.z};
      r.y[i] = {y0.x + a * delta.x, y0.y + a * delta.y, y0.z + a * delta.z};
      r.y[i + P] = {y0.x + b * delta.x, y0.y + b * delta.y, y0.z + b * delta.z};
    }
    r.error = extent * 0x1p-46 + 0x1p-1060;
    r.set_threshold_bounds();
    return r;
  }

 private:
  /// For a direction n normalised as in step 2 (one component exactly +-1, the others in
  /// [-1, 1]), r = fl(sqrt(fl(fl(n_x n_x + n_y n_y) + n_z n_z))) lies in [1, 2]: the exact sum
  /// is in [1, 3], and rounding (in any mode) is monotone and keeps 1 and 3, so the computed
  /// sum is in [1, 3] and its rounded square root in [1, 2]. T is d r and E combined by
  /// roundings of sums and products of nonnegative numbers, each monotone nondecreasing in r,
  /// so T(1) <= T(r) <= T(2) (also when d is infinite: all three are infinite).
  void set_threshold_bounds() {
    threshold_at_least = threshold_for_length(1.0);
    threshold_at_most = threshold_for_length(2.0);
  }
};

/// The rows (at t0 and at t1) of the points of each set of a separation test.
template <std::size_t N>
struct SideRows {
  std::array<std::size_t, N> first{}, second{};
  std::size_t firsts = 0, seconds = 0;

  /// The rows of `side`'s points (P of them, the query's rows all at t0 then all at t1).
  template <std::size_t P>
  explicit SideRows(const std::array<Side, P>& side) {
    for (std::size_t i = 0; i < 2 * P; ++i) {
      if (side[i % P] == Side::first) first[firsts++] = i;
      if (side[i % P] == Side::second) second[seconds++] = i;
    }
  }
};

/// The threshold T of the header's step 4 for the normalised direction n: a computed gap
/// between projections above it certifies an exact gap above d |n|.
template <std::size_t N>
double gap_threshold(const ProjectionFrame<N>& frame, const Vec3& n) {
  return frame.threshold_for_length(std::sqrt((n.x * n.x + n.y * n.y) + n.z * n.z));
}

/// g > T(n) for the normalised direction n: the same test as g > gap_threshold(frame, n),
/// decided by the frame's bounds on T (ProjectionFrame::set_threshold_bounds) unless g falls
/// between them (at d = 0 the bounds are equal: never).
template <std::size_t N>
bool gap_exceeds_threshold(const ProjectionFrame<N>& frame, const Vec3& n, double g) {
  if (!(g > frame.threshold_at_least)) return false;
  if (g > frame.threshold_at_most) return true;
  return g > gap_threshold(frame, n);
}

/// The gap along the normalised direction n certifies the separation (header, step 4): the
/// projections of one set's rows stay farther than the threshold from the other's.
template <std::size_t N>
bool gap_certified(const ProjectionFrame<N>& frame, const SideRows<N>& rows, const Vec3& n) {
  const auto project = [&](std::size_t i) { return (n.x * frame.y[i].x + n.y * frame.y[i].y) + n.z * frame.y[i].z; };
  const auto extent = [&](const std::array<std::size_t, N>& of, std::size_t count, double& lo, double& hi) {
    lo = hi = project(of[0]);
    for (std::size_t k = 1; k < count; ++k) {
      const double p = project(of[k]);
      lo = std::min(lo, p);
      hi = std::max(hi, p);
    }
  };
  double a_lo, a_hi, b_lo, b_hi;
  extent(rows.first, rows.firsts, a_lo, a_hi);
  extent(rows.second, rows.seconds, b_lo, b_hi);
  // Either set below the other (no projection is NaN: every |p| < 2^404, header step 4).
  return gap_exceeds_threshold(frame, n, std::max(b_lo - a_hi, a_lo - b_hi));
}

/// As gap_certified, but the rows at t0 and those at t1 compared separately, the same set
/// below the other at both ends: for a point x_i of the first set and x_j of the second,
/// n.(x_j(t) - x_i(t)) is affine in t (linear motion), so above d |n| at t = 0 and at t = 1 it
/// is above d |n| on all of [0, 1]; then, as in the header, every point of the second hull is
/// farther than d from every point of the first at each t. Step 4's certification applies to
/// the rows of each end as to all rows. Stronger than gap_certified (the hulls of both times
/// at once): the primitives may move along n farther than their gap, as long as they move
/// alike (a cloth's neighbouring elements, or sliding contact).
///
/// Each set needs a row at each end (a point has one at t0 and one at t1, so a nonempty set
/// does): an empty one would leave its bounds infinite, and the infinite gap would certify.
template <std::size_t N>
bool gap_certified_at_each_end(const ProjectionFrame<N>& frame, const SideRows<N>& rows, const Vec3& n) {
  constexpr std::size_t P = N / 2;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (rows.firsts == 0 || rows.seconds == 0) return false;  // nothing to separate (see above)
  const auto project = [&](std::size_t i) { return (n.x * frame.y[i].x + n.y * frame.y[i].y) + n.z * frame.y[i].z; };
  // [end] = the rows at t0 (0) or at t1 (1): every point has one of each.
  double a_lo[2] = {kInf, kInf}, a_hi[2] = {-kInf, -kInf}, b_lo[2] = {kInf, kInf}, b_hi[2] = {-kInf, -kInf};
  for (std::size_t k = 0; k < rows.firsts; ++k) {
    const std::size_t i = rows.first[k], end = i < P ? 0 : 1;
    const double p = project(i);
    a_lo[end] = std::min(a_lo[end], p);
    a_hi[end] = std::max(a_hi[end], p);
  }
  for (std::size_t k = 0; k < rows.seconds; ++k) {
    const std::size_t j = rows.second[k], end = j < P ? 0 : 1;
    const double p = project(j);
    b_lo[end] = std::min(b_lo[end], p);
    b_hi[end] = std::max(b_hi[end], p);
  }
  // The same set below the other at both ends (no projection is NaN, as in gap_certified).
  const double first_below = std::min(b_lo[0] - a_hi[0], b_lo[1] - a_hi[1]);
  const double second_below = std::min(a_lo[0] - b_hi[0], a_lo[1] - b_hi[1]);
  return gap_exceeds_threshold(frame, n, std::max(first_below, second_below));
}

/// n divided by its largest component magnitude (header, step 2), or nothing for a direction
/// that is zero or not finite.
inline std::optional<Vec3> normalised_direction(const Vec3& n) {
  if (!(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z))) return std::nullopt;
  const double m = std::max(std::fabs(n.x), std::max(std::fabs(n.y), std::fabs(n.z)));
  if (!(m > 0)) return std::nullopt;  // zero
  return Vec3{n.x / m, n.y / m, n.z / m};
}

/// The gap along n normalised by its largest component magnitude (header, step 2) certifies
/// the separation; false for a direction that is zero or not finite.
template <std::size_t N>
bool direction_certified(const ProjectionFrame<N>& frame, const SideRows<N>& rows, const Vec3& n) {
  const std::optional<Vec3> u = normalised_direction(n);
  return u && gap_certified(frame, rows, *u);
}

/// Feature pair f's natural direction at the rows `at` + its points (header: point-point
/// y - x; point-edge e x (r x e); point-triangle the normal; edge-edge da x db), or a zero
/// vector when it has none.
template <std::size_t N>
Vec3 natural_direction(const std::array<Vec3, N>& y, const kinds::Feature& f, int at) {
  using contact::cross;
  using contact::operator-;
  const auto p = [&](int j) { return y[static_cast<std::size_t>(f.points[j] + at)]; };
  switch (f.pair) {
    case kinds::FeaturePair::point_point:
      return p(1) - p(0);
    case kinds::FeaturePair::point_edge: {
      // r x e normalised before the second product keeps n of the size of e (not e^2 r).
      const Vec3 e = p(2) - p(1), r = p(0) - p(1), c = cross(r, e);
      const double m = std::max(std::fabs(c.x), std::max(std::fabs(c.y), std::fabs(c.z)));
      if (!(m > 0 && std::isfinite(m))) return Vec3{0, 0, 0};
      return cross(e, Vec3{c.x / m, c.y / m, c.z / m});
    }
    case kinds::FeaturePair::point_triangle:
      return cross(p(2) - p(1), p(3) - p(1));
    case kinds::FeaturePair::edge_edge:
      return cross(p(1) - p(0), p(3) - p(2));
  }
  return Vec3{0, 0, 0};
}

/// True when a direction certifies that the points of `side` first, moving linearly over
/// [0, 1], stay farther than d from the hull of the second ones (so from every convex
/// combination of them) at every t; directions: those of `features` at t0 and t1, then the axes
/// (the header's argument). False: only "not certified".
template <class Kind, std::size_t N, std::size_t F>
bool points_separated(const ProjectionFrame<N>& frame, const std::array<Side, Kind::points>& side,
                      const std::array<kinds::Feature, F>& features, std::size_t feature_count,
                      bool both_ends = true) {
  constexpr int P = Kind::points;
  if (!frame.usable) return false;
  const SideRows<N> rows(side);  // each set needs at least one point
  if (rows.firsts == 0 || rows.seconds == 0) return false;
  for (int at = 0; at < (both_ends ? 2 * P : P); at += P)
    for (std::size_t k = 0; k < feature_count; ++k) {
      if (Kind::dimension == 2 && features[k].pair == kinds::FeaturePair::edge_edge) continue;  // n = z axis
      if (direction_certified(frame, rows, natural_direction(frame.y, features[k], at))) return true;
    }
  for (int axis = 0; axis < Kind::dimension; ++axis)
    if (gap_certified(frame, rows, Vec3{axis == 0 ? 1.0 : 0.0, axis == 1 ? 1.0 : 0.0, axis == 2 ? 1.0 : 0.0}))
      return true;
  return false;
}

/// True when a direction certifies that the kind's two primitives, with the rows of `frame`,
/// stay farther than the frame's d apart (over [0, 1], or over [a, b] for frame.over(a, b)).
/// `feature_count`: the directions of the kind's first pairs only; `both_ends`: false for the
/// pairs' directions at the start alone (the axes are tried either way).
template <class Kind, std::size_t N>
bool primitives_separated(const ProjectionFrame<N>& frame, bool both_ends = true,
                          std::size_t feature_count = Kind::features.size()) {
  std::array<Side, Kind::points> side;
  for (int i = 0; i < Kind::points; ++i) side[i] = i < Kind::first_points ? Side::first : Side::second;
  return points_separated<Kind>(frame, side, Kind::features, feature_count, both_ends);
}

/// True when a direction certifies dist(A(t), B(t)) > d for every t in [0, 1] (then no t in
/// [0, tmax] collides). False means only "not certified".
template <class Query>
bool separated_beyond(const Query& q, double d) {
  using Kind = kinds::kind_of<Query>;
  return primitives_separated<Kind>(ProjectionFrame(contact::points3<double>(q), d));
}

/// True when a direction certifies that feature pair f's two parts (its first point, or first
/// edge for edge-edge, against the rest) stay farther than d apart over [0, 1]: then its term
/// holds nowhere (the term's distance is that of the two parts' hulls, or more). `frame`: the
/// query's rows and d (ProjectionFrame).
template <class Kind, std::size_t N>
bool feature_separated(const ProjectionFrame<N>& frame, const kinds::Feature& f) {
  std::array<Side, Kind::points> side;
  side.fill(Side::none);
  const int first = f.pair == kinds::FeaturePair::edge_edge ? 2 : 1;
  const int count = f.pair == kinds::FeaturePair::point_point ? 2
                    : f.pair == kinds::FeaturePair::point_edge ? 3
                                                               : 4;
  for (int k = 0; k < count; ++k) side[f.points[k]] = k < first ? Side::first : Side::second;
  return points_separated<Kind>(frame, side, std::array<kinds::Feature, 1>{f}, 1);
}

/// The first stage of the minimum-separation question (and, at d = 0, of the point and 2D
/// kinds): a direction certifies that the swept primitives stay farther than d apart.
struct SeparatingDirectionStage {
  static constexpr pipeline::Counter counter = &StageCounters::separating_direction;  ///< counted as
  /// Separate when a direction certifies it; else undecided.
  template <class Query, class Findings>
  pipeline::Outcome operator()(const pipeline::Work<Query, Findings>& work) const {
    if (separated_beyond(work.query(), work.question.params.min_distance)) return pipeline::Outcome::separate();
    return pipeline::Outcome::undecided();
  }
};

}  // namespace exactccd::separation
