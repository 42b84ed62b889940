// Input validation of rigid queries (include/exactccd/rigid.hpp): bad input is never answered.
#pragma once

#include <cmath>
#include <optional>
#include <string>

#include "exactccd/rigid.hpp"

namespace exactccd::rigid {

/// True iff (1 - t) q0 + t q1 = 0 for some t in [0, 1], decided exactly: iff q0 = 0, q1 = 0, or
/// q1 = -s q0 for some s > 0 (then t = 1 / (1 + s); conversely (1 - t) q0 + t q1 = 0 with t in
/// (0, 1) gives q1 = -((1 - t) / t) q0). The components must be finite. Needs round-to-nearest
/// (the entry points' DefaultFpEnvironment).
bool quaternion_path_vanishes(const Quaternion& q0, const Quaternion& q1);

/// Why a body's motion is bad input, or nullptr when it is not: a non-finite component of a
/// pose, or a quaternion path that vanishes in [0, 1].
const char* invalid_motion(const RigidPose& t0, const RigidPose& t1);

/// Why a rigid query is bad input, or nothing: a non-finite number, a quaternion path that
/// vanishes in [0, 1] (the entry point's check of the query, api/entry_point.cpp; its
/// parameters are checked there as for linear queries). Allocates only for bad input.
template <class Query>
std::optional<std::string> invalid_query(const Query& q) {
  if (const char* why = invalid_motion(q.a_t0, q.a_t1)) return std::string("body A: ") + why;
  if (const char* why = invalid_motion(q.b_t0, q.b_t1)) return std::string("body B: ") + why;
  for (const Vec3& p : body_points(q))
    if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)))
      return std::string("non-finite body point coordinate (NaN or infinity)");
  return std::nullopt;
}

}  // namespace exactccd::rigid
