// exactccd: queries with exact rational coordinates (GMP's mpq_class), answered exactly by
// the CGAL path. A separate header so that code using only doubles does not need GMP's
// headers; link as for the rest of the library.
#pragma once

#include <gmpxx.h>

#include <optional>

#include "exactccd/ccd.hpp"
#include "exactccd/types.hpp"

namespace exactccd {

using RationalVec3 = Vec3T<mpq_class>;                       ///< exact rational coordinates
using RationalVertexFaceQuery = VertexFaceQueryT<mpq_class>;  ///< a vertex-face query in rationals
using RationalEdgeEdgeQuery = EdgeEdgeQueryT<mpq_class>;      ///< an edge-edge query in rationals

/// Exact vertex-face CCD for rational coordinates.
bool vertex_face_ccd(const RationalVertexFaceQuery& q);

/// Exact edge-edge CCD for rational coordinates.
bool edge_edge_ccd(const RationalEdgeEdgeQuery& q);

/// Earliest time of impact of a vertex-face query with rational coordinates.
std::optional<TimeInterval> vertex_face_toi(const RationalVertexFaceQuery& q);

/// Earliest time of impact of an edge-edge query with rational coordinates.
std::optional<TimeInterval> edge_edge_toi(const RationalEdgeEdgeQuery& q);

/// The exact answer for a rational query of either kind; see vertex_face_ccd(const RationalVertexFaceQuery&).
inline bool ccd(const RationalVertexFaceQuery& q) { return vertex_face_ccd(q); }
/// See ccd(const RationalVertexFaceQuery&).
inline bool ccd(const RationalEdgeEdgeQuery& q) { return edge_edge_ccd(q); }
/// The exact TOI for a rational query of either kind.
inline std::optional<TimeInterval> toi(const RationalVertexFaceQuery& q) { return vertex_face_toi(q); }
/// See toi(const RationalVertexFaceQuery&).
inline std::optional<TimeInterval> toi(const RationalEdgeEdgeQuery& q) { return edge_edge_toi(q); }

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
};

/// Exact minimum-separation CCD for rational coordinates, every kind (see ccd.hpp's
/// CcdParams functions). Throws std::invalid_argument on a negative d or a tmax outside (0, 1].
bool ccd(const RationalVertexFaceQuery& q, const RationalCcdParams& params);
/// See ccd(const RationalVertexFaceQuery&, const RationalCcdParams&).
bool ccd(const RationalEdgeEdgeQuery& q, const RationalCcdParams& params);
/// See ccd(const RationalVertexFaceQuery&, const RationalCcdParams&).
bool ccd(const RationalPointEdgeQuery& q, const RationalCcdParams& params);
/// See ccd(const RationalVertexFaceQuery&, const RationalCcdParams&).
bool ccd(const RationalPointPointQuery& q, const RationalCcdParams& params);
/// See ccd(const RationalVertexFaceQuery&, const RationalCcdParams&).
bool ccd(const RationalEdgeEdge2dQuery& q, const RationalCcdParams& params);
/// See ccd(const RationalVertexFaceQuery&, const RationalCcdParams&).
bool ccd(const RationalPointEdge2dQuery& q, const RationalCcdParams& params);
/// See ccd(const RationalVertexFaceQuery&, const RationalCcdParams&).
bool ccd(const RationalPointPoint2dQuery& q, const RationalCcdParams& params);

/// The exact TOI for rational coordinates with a minimum separation and a time limit, every kind.
std::optional<TimeInterval> toi(const RationalVertexFaceQuery& q, const RationalCcdParams& params);
/// See toi(const RationalVertexFaceQuery&, const RationalCcdParams&).
std::optional<TimeInterval> toi(const RationalEdgeEdgeQuery& q, const RationalCcdParams& params);
/// See toi(const RationalVertexFaceQuery&, const RationalCcdParams&).
std::optional<TimeInterval> toi(const RationalPointEdgeQuery& q, const RationalCcdParams& params);
/// See toi(const RationalVertexFaceQuery&, const RationalCcdParams&).
std::optional<TimeInterval> toi(const RationalPointPointQuery& q, const RationalCcdParams& params);
/// See toi(const RationalVertexFaceQuery&, const RationalCcdParams&).
std::optional<TimeInterval> toi(const RationalEdgeEdge2dQuery& q, const RationalCcdParams& params);
/// See toi(const RationalVertexFaceQuery&, const RationalCcdParams&).
std::optional<TimeInterval> toi(const RationalPointEdge2dQuery& q, const RationalCcdParams& params);
/// See toi(const RationalVertexFaceQuery&, const RationalCcdParams&).
std::optional<TimeInterval> toi(const RationalPointPoint2dQuery& q, const RationalCcdParams& params);

}  // namespace exactccd
