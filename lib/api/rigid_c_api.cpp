// The C API of rigid queries (exactccd/exactccd.h, exactccd_rigid_*) over the C++ one, by the
// one pattern of every C query function (c_query.hpp, as c_api.cpp). No exception crosses the
// boundary.
#include <cmath>
#include <optional>

#include "api/c_query.hpp"
#include "exactccd/exactccd.h"
#include "exactccd/rigid.hpp"
#include "rigid/rigid_layout.hpp"
#include "rigid/validation.hpp"

namespace {

using namespace exactccd;

/// A rigid query of the type Query from its kQueryNumbers doubles, checked (EXACTCCD_ERROR_NON_FINITE,
/// EXACTCCD_ERROR_ROTATION), and its answer.
template <class Query>
exactccd_status read_and_answer(const double* numbers, const CcdParams& params, bool want_toi, int* collides,
                                double* lo, double* hi) {
  for (std::size_t i = 0; i < rigid::kQueryNumbers; ++i)
    if (!std::isfinite(numbers[i])) return EXACTCCD_ERROR_NON_FINITE;
  const Query q = rigid::from_numbers<Query>(numbers);
  if (rigid::quaternion_path_vanishes(q.a_t0.q, q.a_t1.q) || rigid::quaternion_path_vanishes(q.b_t0.q, q.b_t1.q))
    return EXACTCCD_ERROR_ROTATION;
  return api::write_answer(q, params, want_toi, collides, lo, hi);
}

/// The C API's rigid query of kind `kind` (EXACTCCD_VERTEX_FACE or EXACTCCD_EDGE_EDGE).
exactccd_status answer_c_rigid_query(int kind, const double* query, double d, double tmax, bool want_toi,
                                     int* collides, double* lo, double* hi) {
  return api::c_query_call(query, collides, d, tmax, [&](const CcdParams& params) {
    if (kind == EXACTCCD_VERTEX_FACE)
      return read_and_answer<RigidVertexFaceQuery>(query, params, want_toi, collides, lo, hi);
    if (kind == EXACTCCD_EDGE_EDGE) return read_and_answer<RigidEdgeEdgeQuery>(query, params, want_toi, collides, lo, hi);
    return EXACTCCD_ERROR_PARAMETER;
  });
}

}  // namespace

extern "C" {

exactccd_status exactccd_rigid_ccd(int kind, const double* query, double min_distance, double tmax, int* collides) {
  return answer_c_rigid_query(kind, query, min_distance, tmax, false, collides, nullptr, nullptr);
}

exactccd_status exactccd_rigid_toi(int kind, const double* query, double min_distance, double tmax, int* collides,
                                   double* lo, double* hi) {
  return answer_c_rigid_query(kind, query, min_distance, tmax, true, collides, lo, hi);
}

}  // extern "C"
