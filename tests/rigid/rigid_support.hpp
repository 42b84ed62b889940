// Shared helpers of the rigid tests: poses, closed-form checks of a time of impact.
#pragma once

#include <gmpxx.h>

#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "exactccd/rigid.hpp"

namespace exactccd::rigid_test {

constexpr Quaternion kIdentity{1, 0, 0, 0};

/// A body that does not move: pose (c, q) at both ends.
inline std::array<RigidPose, 2> still(const Vec3& c = {0, 0, 0}, const Quaternion& q = kIdentity) {
  return {RigidPose{c, q}, RigidPose{c, q}};
}

/// A rigid vertex-face query from the two bodies' motions and the body points.
inline RigidVertexFaceQuery vertex_face(const std::array<RigidPose, 2>& a, const std::array<RigidPose, 2>& b,
                                        const Vec3& p, const Vec3& ta, const Vec3& tb, const Vec3& tc) {
  return {a[0], a[1], b[0], b[1], p, ta, tb, tc};
}

/// A rigid edge-edge query.
inline RigidEdgeEdgeQuery edge_edge(const std::array<RigidPose, 2>& a, const std::array<RigidPose, 2>& b,
                                    const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1) {
  return {a[0], a[1], b[0], b[1], a0, a1, b0, b1};
}

/// True iff [lo, hi] is the tightest double interval around the rational t: [t, t] when t is a
/// double, else consecutive doubles with lo < t < hi.
inline bool tightly_encloses(const TimeInterval& r, const mpq_class& t) {
  if (r.lo == r.hi) return mpq_class(r.lo) == t;
  return r.hi == std::nextafter(r.lo, std::numeric_limits<double>::infinity()) && mpq_class(r.lo) < t &&
         t < mpq_class(r.hi);
}

/// The value at the rational t of the polynomial with integer coefficients c (c[0] + c[1] t + ...).
inline mpq_class evaluate(const std::vector<long>& c, const mpq_class& t) {
  mpq_class r = 0;
  for (std::size_t k = c.size(); k-- > 0;) r = r * t + c[k];
  return r;
}

/// True iff [lo, hi] is the tightest double interval around the only root in [lo, hi] of the
/// polynomial c, which changes sign there (lo == hi: the root itself).
inline bool tightly_encloses_root(const TimeInterval& r, const std::vector<long>& c) {
  if (r.lo == r.hi) return evaluate(c, mpq_class(r.lo)) == 0;
  return r.hi == std::nextafter(r.lo, std::numeric_limits<double>::infinity()) &&
         sgn(evaluate(c, mpq_class(r.lo))) * sgn(evaluate(c, mpq_class(r.hi))) < 0;
}

/// The quaternion of a rotation about the z axis whose path from the identity, q(t) = (1, 0, 0,
/// t s), turns by 2 atan(t s): at t the point (r, 0, 0) is at r ((1 - (ts)^2), 2 ts, 0) / (1 + (ts)^2).
inline Quaternion z_turn(double s) { return {1, 0, 0, s}; }

}  // namespace exactccd::rigid_test
