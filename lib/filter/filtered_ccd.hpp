// The filtered method: stages from cheapest to exact, each deciding what it can certify.
//   1. volume exclusion (static error bound, doubles): V(t) != 0 on [0, 1] => no collision;
//   1b. nothing moves: CGAL's exact static predicates (orientation, collinearity) at t = 0;
//   2. interval stage (CGAL::Interval_nt): root isolation and in-plane signs;
//   3. integer stage (GMP integers, small exact kernel for degree <= 4);
//   4. CGAL path (GMP rationals, CGAL's Algebraic_kernel_d_1): always decides.
// The answer is always the exact one; only the time taken depends on the stage.
#pragma once

#include <optional>

#include "exactccd/stats.hpp"
#include "exactccd/types.hpp"

namespace exactccd::filter {

/// Exact vertex-face CCD through the filter stages; counts the deciding stage in counters.
bool vertex_face_ccd(const VertexFaceQuery& q, StageCounters* counters);

/// Exact edge-edge CCD through the filter stages; counts the deciding stage in counters.
bool edge_edge_ccd(const EdgeEdgeQuery& q, StageCounters* counters);

/// Exact vertex-face TOI (tightest double interval) through the filter stages.
std::optional<TimeInterval> vertex_face_toi(const VertexFaceQuery& q, StageCounters* counters);

/// Exact edge-edge TOI (tightest double interval) through the filter stages.
std::optional<TimeInterval> edge_edge_toi(const EdgeEdgeQuery& q, StageCounters* counters);

}  // namespace exactccd::filter
