// Certified swept bounds of a rigid body's points over a step (docs/design.md, 9.5): a box
// holding c(t) + R(q(t)) p for every t in [0, 1], for the broad phase of the rigid scene
// function and for generating candidate pairs.
//
// Why it holds. c(t) is on the segment [c0, c1]. The quaternion path turns about one fixed axis
// (9.1), so R(q(t)) p runs along an arc of a circle about that axis, of radius r <= |p|, from
// R(q0) p to R(q1) p. When q0 . q1 > 0 the unit quaternions move the short way along their great
// circle and the arc's angle Phi satisfies cos(Phi / 2) = q0 . q1 / (|q0| |q1|) > 0, so Phi < pi
// and every point of the arc lies within the sagitta r (1 - cos(Phi / 2)) of the chord
// [R(q0) p, R(q1) p] (the arc's farthest point is its middle, and every arc point projects into
// the chord). And always |R(q(t)) p| = |p|. So X(t) lies in the box hull(c0, c1) + (hull(R(q0) p,
// R(q1) p) grown by s) intersected, for the rotation part, with [-|p|, |p|]^3. Everything is
// computed in interval arithmetic (CGAL::Interval_nt, outward rounding), so the box holds the
// exact curves; overflow gives infinite bounds, which still hold them.
#pragma once

#include <array>
#include <vector>

#include "exactccd/rigid.hpp"
#include "numeric/interval.hpp"

namespace exactccd::rigid {

/// An axis-aligned box [lo, hi] (closed).
struct Box {
  Vec3 lo;  ///< the least corner
  Vec3 hi;  ///< the greatest corner
};

/// One body's motion over a step, ready to bound its points' curves. Needs upward rounding
/// (CGAL::Protect_FPU_rounding<true>) around every call, constructor included.
class SweptBody {
 public:
  using I = numeric::Interval;

  /// The body moving from pose t0 to pose t1 (finite, quaternion path not through 0).
  SweptBody(const RigidPose& t0, const RigidPose& t1);

  /// A box holding c(t) + R(q(t)) p for every t in [0, 1], grown by `margin` >= 0.
  Box box(const Vec3& p, double margin = 0) const;

 private:
  std::array<std::array<I, 9>, 2> rotation_;  // R(q0), R(q1), row-major
  std::array<I, 3> c_lo_, c_hi_;             // hull of c0, c1
  I one_minus_cos_;                           // 1 - cos(Phi / 2), or unusable (long arc)
  bool short_arc_ = false;
};

/// The box of one point with the motion, under its own rounding guard.
Box swept_box(const RigidPose& t0, const RigidPose& t1, const Vec3& p, double margin = 0);

/// The boxes of every point of a body with the motion, under its own rounding guard.
std::vector<Box> swept_boxes(const RigidPose& t0, const RigidPose& t1, const std::vector<Vec3>& points,
                             double margin = 0);

}  // namespace exactccd::rigid
