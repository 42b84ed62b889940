// Input validation of rigid queries (include/exactccd/rigid.hpp): bad input is never answered.
#pragma once

#include <cmath>
#include <stdexcept>
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

/// Throws std::invalid_argument, the message starting with function() (called only then: no
/// allocation on the common path), when a number of the query is not finite, a quaternion path
/// vanishes in [0, 1], d is negative or not finite, or tmax is not in (0, 1].
template <class Query, class Name>
void validate(const Query& q, const CcdParams& params, Name&& function) {
  const auto fail = [&](const std::string& why) { throw std::invalid_argument(function() + ": " + why); };
  if (const char* why = invalid_motion(q.a_t0, q.a_t1)) fail(std::string("body A: ") + why);
  if (const char* why = invalid_motion(q.b_t0, q.b_t1)) fail(std::string("body B: ") + why);
  for (const Vec3& p : body_points(q))
    if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)))
      fail("non-finite body point coordinate (NaN or infinity)");
  if (!(std::isfinite(params.min_distance) && params.min_distance >= 0))
    fail("min_distance must be finite and >= 0, not " + std::to_string(params.min_distance));
  if (!(params.tmax > 0 && params.tmax <= 1)) fail("tmax must be in (0, 1], not " + std::to_string(params.tmax));
}

}  // namespace exactccd::rigid
