// A stage of the filtered method for queries in which nothing moves (every point's position at
// t1 equals its position at t0). Then contact does not depend on t: the query is the static
// question "does the point lie in the closed triangle" / "do the closed segments meet", decided
// at t = 0 with CGAL's exact static predicates (orientation, coplanar orientation, collinearity
// and order along a line, from Exact_predicates_inexact_constructions_kernel: a static and an
// interval filter, then exact arithmetic). Static pairs are common in scenes (obstacles,
// resting or pinned parts) and often exactly degenerate (coplanar, parallel grid edges), where
// the contact polynomials' signs are exactly zero and the interval stage cannot certify them.
#pragma once

#include <optional>

#include "exactccd/types.hpp"

namespace exactccd::filter {

/// True when every point of the query is at the same position at t0 and t1.
bool is_static(const VertexFaceQuery& q);
/// True when every point of the query is at the same position at t0 and t1.
bool is_static(const EdgeEdgeQuery& q);

/// Exact contact of a static vertex-face query (is_static(q) must hold): p in the closed convex
/// hull of a, b, c (a degenerate triangle is the segment or point it spans).
bool static_vertex_face_contact(const VertexFaceQuery& q);

/// Exact contact of a static edge-edge query (is_static(q) must hold): the closed segments
/// share a point (a zero-length edge is a point).
bool static_edge_edge_contact(const EdgeEdgeQuery& q);

}  // namespace exactccd::filter
