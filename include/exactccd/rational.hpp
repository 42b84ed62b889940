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

}  // namespace exactccd
