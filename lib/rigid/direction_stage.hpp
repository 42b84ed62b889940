// The first filtered stage of rigid queries (docs/design.md, 9.4): a certified separating
// direction over the whole step, in plain doubles with a static error bound (no interval
// arithmetic, no rounding-mode switch).
//
// Why a direction separates. For body K with pose (c(t), q(t)), a point p of it is at
// X(t) = c(t) + R(q(t)) p. c(t) lies on the segment [c(0), c(1)]. R(q(t)) p runs along an arc
// about the path's fixed axis (9.1); when q0 . q1 > 0 the arc's angle Phi < pi with
// cos(Phi / 2) = q0 . q1 / (|q0| |q1|), and every arc point is within the sagitta
// |p| (1 - cos(Phi / 2)) of the chord [R(q0) p, R(q1) p] (swept_box.hpp); otherwise R(q(t)) p is in
// the ball of radius |p| about 0, so within 2 |p| of R(q0) p. So with s_K the largest such bound
// over the primitive's points of K, for a direction n and every t:
//   n . X(t) <= max_t' n . c(t') + max over the points and t' in {0, 1} of n . R(q(t')) p + s_K |n|
// (t' in {0, 1}: both are linear or convex on the segments), and every point of the primitive
// (a convex combination of its points at t) obeys the same bound. If body B's lower bound of
// this kind exceeds body A's upper bound by more than d |n|, the primitives are farther than d
// apart at every t in [0, 1] (Cauchy-Schwarz), likewise with A and B exchanged.
//
// How it is certified (u = 2^-53; round to nearest, the entry points' environment).
//  1. Scaling (rigid_unit_scaling.hpp): every length below 2 in magnitude, the largest in [1, 2); every
//     quaternion component below 2, the largest of each body in [1, 2), so |q|^2 in [1, 16).
//  2. Rotations: the entries of M(q) are computed with an error below gamma_4 |q|^2 (diagonal:
//     four squares and three sums; off-diagonal: two products, a difference, a doubling) and
//     are at most |q|^2 exactly; r_j = fl(fl(sum_k m_jk p_k) / fl(|q|^2)) then errs by at most
//     (gamma_4 + gamma_3 (1 + gamma_4)) |q|^2 |p|_1 + 2^-1070 in the sum (squares and
//     products may underflow, 2^-1075 each, and |p_k| < 2) and, |q|^2 >= 1 and |r_j| <= |p|_2 <= |p|_1, by at most 12.1 u |p|_1 + 2^-1069
//     <= 2^-47 |p|_inf + 2^-1069 in the quotient (fl(|q|^2) has relative error gamma_4).
//  3. Translations relative to A's c(0): each difference errs by u of its magnitude.
//  4. Sagittas: c~ = fl(fl(q0 . q1) / fl(sqrt(fl(|q0|^2) fl(|q1|^2)))) is within 11 u of cos(Phi / 2)
//     (|q0|, |q1| >= 1; underflowed products cost 2^-1073). If c~ > 2^-20 the arc is short and
//     1 - cos(Phi / 2) <= fl(1 - c~) + 2^-49 (1 - c~ errs by at most u of itself); s is bounded by
//     fl(fl(2 |p|_inf (fl(1 - c~) + 2^-49)) (1 + 2^-50)) + 2^-1070 (2 |p|_inf >= |p|_2); otherwise
//     by 4 |p|_inf (the ball). Both exceed the exact bound.
//  5. Projections, for a direction n scaled so that its largest component is +-1 (|n|_1 <= 3,
//     1 <= n.n <= 3): with Y the largest |component| of every translation and rotated point
//     used, each computed projection errs by at most 3 e + 9.1 u Y (e the vector's error): at
//     most 12.2 u Y for a translation and, |p|_inf <= |p|_2 = |r|_2 <= sqrt(3) |r|_inf,
//     3 (2^-47 1.74 Y) + 9.1 u Y + 2^-1066 <= 2^-44.5 Y + 2^-1066 for a rotated point (the
//     projection's products may underflow too). The gap adds four such quantities and three sums
//     (below 24 u Y): below 2^-42 Y + 2^-1063.
//  6. The gap g~ certifies when g~ > T = fl(fl(fl(fl(d + sA) + sB) r (1 + 2^-47)) + fl(Y 2^-41))
//     + 2^-1060, r = fl(sqrt(fl(n.n))) (|n| <= r (1 + 2^-50)): T is at least (d + sA + sB) |n| +
//     2^-42 Y + 2^-1063 (each of its roundings loses at most u, covered by the factor 1 + 2^-47,
//     the doubled 2^-41 and the larger constant). Nothing overflows (every value below 2^6 after step 1) except a scaled d,
//     which makes T infinite: never certified, rightly. A direction that is not finite or zero
//     is skipped.
// Directions: each feature pair's natural direction (point-point y - x, point-edge e x (r x e),
// point-triangle the normal, edge-edge da x db) from the rounded world positions at t = 0, the
// primitives' own pair first, then at t = 1, then the coordinate axes.
#pragma once

#include <array>
#include <cstddef>

#include "exactccd/rigid.hpp"
#include "exactccd/stats.hpp"
#include "kinds/primitive_kinds.hpp"
#include "pipeline/outcome.hpp"

namespace exactccd::rigid {

/// The direction stage's view of a normalized query (rigid_unit_scaling.hpp): the body points
/// rotated at t = 0 and 1, the translations relative to A's c(0), the sagitta terms (header,
/// steps 1-4).
template <class Query>
class DirectionFrame {
 public:
  /// Computes the rotated points, translations and arcs of the normalized query.
  explicit DirectionFrame(const Query& normalized_query);

  /// True when a direction certifies that the primitives stay farther than d apart over all of
  /// [0, 1]; false means only "not certified".
  bool separated_beyond(double d) const;

  /// True when a direction certifies that the two parts of the kind's feature pair number
  /// `feature` (kinds::VertexFace::features or EdgeEdge's: each part on one body) stay farther
  /// than d apart over [0, 1] (the same argument restricted to those points): then the pair's
  /// term holds nowhere (it implies a point of each part within d, docs/design.md 4b.1).
  bool feature_separated(double d, std::size_t feature) const;

 private:
  bool separated(double d, unsigned used, const kinds::Feature* features, std::size_t feature_count) const;
  /// The gap along n (largest component +-1) between the `used` points of A and of B certified
  /// beyond `distance` |n| (d plus the sagittas), header steps 5 and 6.
  bool certifies(const Vec3& n, unsigned used, double distance) const;

  std::array<std::array<Vec3, 4>, 2> rotated_;   // R(q(t)) p for t = 0, 1
  std::array<Vec3, 2> translation_a_, translation_b_;
  std::array<double, 4> extent_;                 // |p|_inf of each body point
  double extent_y_ = 0;                          // Y of step 5
  double cosine_a_ = 0, cosine_b_ = 0;           // fl(cos(Phi / 2)) of each body
};

extern template class DirectionFrame<RigidVertexFaceQuery>;
extern template class DirectionFrame<RigidEdgeEdgeQuery>;

/// The first filtered stage of both rigid questions: separate when a direction certifies that
/// the primitives stay farther than d apart over the whole step, else undecided.
struct DirectionStage {
  static constexpr pipeline::Counter counter = &StageCounters::separating_direction;  ///< counted as
  /// The certificate on the Work's normalized query and scaled d.
  template <class Query, class Findings>
  pipeline::Outcome operator()(pipeline::Work<Query, Findings>& work) const {
    return DirectionFrame<Query>(work.query()).separated_beyond(work.question.params.min_distance)
               ? pipeline::Outcome::separate()
               : pipeline::Outcome::undecided();
  }
};

}  // namespace exactccd::rigid
