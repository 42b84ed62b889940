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
#include "pipeline/outcome.hpp"

namespace exactccd::filter {

/// True when every point of the query is at the same position at t0 and t1.
bool is_static(const VertexFaceQuery& q);
/// True when every point of the query is at the same position at t0 and t1.
bool is_static(const EdgeEdgeQuery& q);

/// Exact vertex-face contact at t = `end` (0 or 1): p in the closed convex hull of a, b, c then
/// (a degenerate triangle is the segment or point it spans). For a static query, the answer.
bool contact_at_end(const VertexFaceQuery& q, int end);

/// Exact edge-edge contact at t = `end` (0 or 1): the closed segments share a point then (a
/// zero-length edge is a point). For a static query, the answer.
bool contact_at_end(const EdgeEdgeQuery& q, int end);

/// The exact sign (-1, 0, 1) of the volume V at t = `end` (0 or 1), V as in
/// contact_polynomials.hpp: the orientation of a, b, c, p then.
int volume_sign_at_end(const VertexFaceQuery& q, int end);

/// The exact sign (-1, 0, 1) of the volume V at t = `end` (0 or 1): the orientation of a0, a1,
/// b0, b1 then.
int volume_sign_at_end(const EdgeEdgeQuery& q, int end);

// All four call CGAL's static filters, which assume round-to-nearest.

/// The contact question's stage for queries in which nothing moves: decided at t = 0 (the TOI
/// is 0 when they touch).
struct StaticQueryStage {
  static constexpr pipeline::Counter counter = &StageCounters::static_predicates;  ///< counted as
  /// Decides static queries, passes the others on.
  template <class Query, class Findings>
  pipeline::Outcome operator()(const pipeline::Work<Query, Findings>& work) const {
    if (!is_static(work.query())) return pipeline::Outcome::undecided();
    if (!contact_at_end(work.query(), 0)) return pipeline::Outcome::separate();
    return pipeline::Outcome::collides(TimeInterval{0.0, 0.0});
  }
};

}  // namespace exactccd::filter
