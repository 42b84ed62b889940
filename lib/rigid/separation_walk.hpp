// The interval stage of the rigid minimum-separation question (d > 0; docs/design.md, 9.4).
#pragma once

#include "exactccd/rigid.hpp"
#include "rigid/stage_result.hpp"

namespace exactccd::rigid {

/// The stage on a normalized query with the scaled d > 0, over [0, tmax]. Needs round-to-nearest
/// on entry.
StageResult separation_walk(const RigidVertexFaceQuery& normalized_query, double d, double tmax, bool want_toi);
/// See separation_walk(const RigidVertexFaceQuery&, double, double, bool).
StageResult separation_walk(const RigidEdgeEdgeQuery& normalized_query, double d, double tmax, bool want_toi);

}  // namespace exactccd::rigid
