// The interval stage of the rigid minimum-separation question (d > 0; docs/design.md, 9.4).
#pragma once

#include "exactccd/rigid.hpp"
#include "rigid/direction_stage.hpp"
#include "rigid/interval_frame.hpp"
#include "rigid/stage_result.hpp"

namespace exactccd::rigid {

/// The stage on a normalized query with the scaled d > 0, over [0, tmax], with the query's
/// direction and interval frames. Needs upward rounding held by the caller.
StageResult separation_walk(const RigidVertexFaceQuery& normalized_query, const DirectionFrame<RigidVertexFaceQuery>& directions,
                            const IntervalFrame<RigidVertexFaceQuery>& frame, double d, double tmax, bool want_toi);
/// See separation_walk(const RigidVertexFaceQuery&, ...).
StageResult separation_walk(const RigidEdgeEdgeQuery& normalized_query, const DirectionFrame<RigidEdgeEdgeQuery>& directions,
                            const IntervalFrame<RigidEdgeEdgeQuery>& frame, double d, double tmax, bool want_toi);

}  // namespace exactccd::rigid
