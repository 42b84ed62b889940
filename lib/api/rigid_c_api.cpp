// The C API of rigid queries (exactccd/exactccd.h, exactccd_rigid_*) over the C++ one. No
// exception crosses the boundary.
#include <cmath>
#include <exception>
#include <optional>

#include "exactccd/exactccd.h"
#include "exactccd/rigid.hpp"
#include "numeric/fp_environment.hpp"
#include "rigid/rigid_layout.hpp"
#include "rigid/validation.hpp"

namespace {

using namespace exactccd;

template <class Query>
exactccd_status answer(const double* numbers, double d, double tmax, bool want_toi, int* collides, double* lo,
                       double* hi) {
  for (std::size_t i = 0; i < rigid::kQueryNumbers; ++i)
    if (!std::isfinite(numbers[i])) return EXACTCCD_ERROR_NON_FINITE;
  const Query q = rigid::from_numbers<Query>(numbers);
  if (rigid::quaternion_path_vanishes(q.a_t0.q, q.a_t1.q) || rigid::quaternion_path_vanishes(q.b_t0.q, q.b_t1.q))
    return EXACTCCD_ERROR_ROTATION;
  try {
    const CcdParams params{d, tmax};
    const std::optional<TimeInterval> t =
        want_toi ? toi(q, params) : (ccd(q, params) ? std::optional(TimeInterval{}) : std::nullopt);
    *collides = t ? 1 : 0;
    if (t && lo) *lo = t->lo;
    if (t && hi) *hi = t->hi;
    return EXACTCCD_OK;
  } catch (const std::exception&) {
    return EXACTCCD_ERROR_INTERNAL;
  }
}

exactccd_status rigid_answer(int kind, const double* query, double d, double tmax, bool want_toi, int* collides, double* lo,
                      double* hi) {
  if (!query || !collides) return EXACTCCD_ERROR_NULL;
  const numeric::DefaultFpEnvironment fp_environment;  // first: DAZ would read -2^-1074 as -0
  if (!(std::isfinite(d) && d >= 0 && tmax > 0 && tmax <= 1)) return EXACTCCD_ERROR_PARAMETER;
  if (kind == EXACTCCD_VERTEX_FACE) return answer<RigidVertexFaceQuery>(query, d, tmax, want_toi, collides, lo, hi);
  if (kind == EXACTCCD_EDGE_EDGE) return answer<RigidEdgeEdgeQuery>(query, d, tmax, want_toi, collides, lo, hi);
  return EXACTCCD_ERROR_PARAMETER;
}

}  // namespace

extern "C" {

exactccd_status exactccd_rigid_ccd(int kind, const double* query, double min_distance, double tmax, int* collides) {
  return rigid_answer(kind, query, min_distance, tmax, false, collides, nullptr, nullptr);
}

exactccd_status exactccd_rigid_toi(int kind, const double* query, double min_distance, double tmax, int* collides,
                                   double* lo, double* hi) {
  return rigid_answer(kind, query, min_distance, tmax, true, collides, lo, hi);
}

}  // extern "C"
