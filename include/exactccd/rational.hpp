// exactccd: queries with exact rational coordinates (GMP's mpq_class), answered exactly by
// the CGAL path. A separate header so that code using only doubles does not need GMP's
// headers; link as for the rest of the library.
#pragma once

#include <gmpxx.h>

#include <optional>
#include <type_traits>

#include "exactccd/ccd.hpp"
#include "exactccd/types.hpp"

namespace exactccd {

using RationalVec3 = Vec3T<mpq_class>;                       ///< exact rational coordinates
using RationalVertexFaceQuery = VertexFaceQueryT<mpq_class>;  ///< a vertex-face query in rationals
using RationalEdgeEdgeQuery = EdgeEdgeQueryT<mpq_class>;      ///< an edge-edge query in rationals

using RationalPointEdgeQuery = PointEdgeQueryT<mpq_class>;      ///< point-edge in rationals
using RationalPointPointQuery = PointPointQueryT<mpq_class>;    ///< point-point in rationals
using RationalEdgeEdge2dQuery = EdgeEdge2dQueryT<mpq_class>;    ///< 2D edge-edge in rationals
using RationalPointEdge2dQuery = PointEdge2dQueryT<mpq_class>;  ///< 2D point-edge in rationals
using RationalPointPoint2dQuery = PointPoint2dQueryT<mpq_class>;  ///< 2D point-point in rationals

/// CcdParams with exact rational values: collision iff dist <= min_distance at some t in
/// [0, tmax]; min_distance >= 0, tmax in (0, 1].
struct RationalCcdParams {
  mpq_class min_distance = 0;  ///< d >= 0
  mpq_class tmax = 1;          ///< in (0, 1]

  /// True for the contact question (d = 0), as CcdParams::contact_only.
  bool contact_only() const { return !(min_distance > 0); }
  /// True when the whole step is asked (tmax = 1), as CcdParams::whole_step.
  bool whole_step() const { return tmax == 1; }
  /// Contact over the whole step, as CcdParams::contact_over_whole_step.
  bool contact_over_whole_step() const { return contact_only() && whole_step(); }
};

/// The one entry point for rational queries: the exact answer to `params` for a query of any
/// kind with mpq_class coordinates (the library defines it for each kind), the TOI when
/// `want_toi` (else, for a collision, [0, 0]), or nullopt for no collision. Throws
/// std::invalid_argument on a negative d or a tmax outside (0, 1].
template <class RationalQuery>
std::optional<TimeInterval> answer_rational_query(const RationalQuery& q, const RationalCcdParams& params, bool want_toi);

/// True for the query types with rational coordinates.
template <class Query>
inline constexpr bool is_rational_query = std::is_same_v<coordinate_t<Query>, mpq_class>;

/// Exact minimum-separation CCD for rational coordinates, every kind (see ccd.hpp's CcdParams
/// functions). Throws std::invalid_argument on a negative d or a tmax outside (0, 1].
template <class Query, std::enable_if_t<is_rational_query<Query>, int> = 0>
bool ccd(const Query& q, const RationalCcdParams& params = {}) {
  return answer_rational_query(q, params, false).has_value();
}

/// The exact TOI for rational coordinates with a minimum separation and a time limit, every kind.
template <class Query, std::enable_if_t<is_rational_query<Query>, int> = 0>
std::optional<TimeInterval> toi(const Query& q, const RationalCcdParams& params = {}) {
  return answer_rational_query(q, params, true);
}

/// Exact vertex-face CCD for rational coordinates.
inline bool vertex_face_ccd(const RationalVertexFaceQuery& q) { return ccd(q); }
/// Exact edge-edge CCD for rational coordinates.
inline bool edge_edge_ccd(const RationalEdgeEdgeQuery& q) { return ccd(q); }
/// Earliest time of impact of a vertex-face query with rational coordinates.
inline std::optional<TimeInterval> vertex_face_toi(const RationalVertexFaceQuery& q) { return toi(q); }
/// Earliest time of impact of an edge-edge query with rational coordinates.
inline std::optional<TimeInterval> edge_edge_toi(const RationalEdgeEdgeQuery& q) { return toi(q); }

}  // namespace exactccd
